// Unchanging fields (FieldView::unchanging): stored once in /static, hard-linked from every
// snapshot, read back by SnapshotReader like any other field; a file reopened for a resume keeps
// them; a later snapshot whose unchanging field has another shape is refused.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "io/snapshot_reader.h"
#include "io/snapshot_writer.h"
#include "tests/io/scratch_dir.h"

namespace porosph::io {
namespace {

using test::ScratchDir;

struct Skeleton {
  std::vector<double> position;    // unchanging, N x 2
  std::vector<double> stress;      // unchanging, N x 9
  std::vector<std::int64_t> id;    // unchanging
  std::vector<double> saturation;  // changes

  explicit Skeleton(std::size_t n) : position(2 * n), stress(9 * n, 0.0), saturation(n, 0.0) {
    for (std::size_t i = 0; i < n; ++i) {
      position[2 * i] = 0.001 * static_cast<double>(i);
      position[2 * i + 1] = -0.5;
      id.push_back(static_cast<std::int64_t>(i));
    }
  }
  std::vector<FieldView> views() const {
    std::vector<FieldView> fields = {field_view("position", position, 2),
                                     field_view("stress", stress, 9), field_view("id", id)};
    for (FieldView& f : fields) f.unchanging = true;
    fields.push_back(field_view("saturation", saturation));
    return fields;
  }
};

TEST(SnapshotWriterUnchanging, StoresOnceAndEverySnapshotReadsIt) {
  ScratchDir dir;
  const std::string path = dir.file("soil.h5");
  Skeleton s(2000);
  {
    SnapshotWriter writer(path);
    for (std::uint32_t k = 0; k < 5; ++k) {
      for (double& v : s.saturation) v = 0.1 * k;
      writer.write(k, 0.01 * k, s.views());
    }
  }
  SnapshotReader reader(path);
  ASSERT_EQ(reader.snapshots().size(), 5u);
  EXPECT_TRUE(reader.exists("/static/position"));
  EXPECT_FALSE(reader.exists("/static/saturation"));
  for (std::uint32_t k = 0; k < 5; ++k) {
    EXPECT_EQ(reader.fields(k),
              (std::vector<std::string>{"id", "position", "saturation", "stress"}));
    const auto position = reader.read_f64(k, "position");
    EXPECT_EQ(position.values, s.position);
    EXPECT_EQ(position.cols, 2u);
    EXPECT_EQ(reader.read_f64(k, "stress").cols, 9u);
    EXPECT_EQ(reader.read_i64(k, "id").values, s.id);
    EXPECT_EQ(reader.read_f64(k, "saturation").values[7], 0.1 * k);
  }
  // Five snapshots of N x (2 + 9 + 1) unchanging values would take 5 x 2000 x 12 x 8 = 960 kB;
  // stored once they take a fifth of that, plus the changing saturation.
  const auto bytes = std::filesystem::file_size(path);
  EXPECT_LT(bytes, 2000u * 8u * (12u + 5u) + 64u * 1024u) << bytes;
}

TEST(SnapshotWriterUnchanging, AResumedFileKeepsThemAndLinksThemAgain) {
  ScratchDir dir;
  const std::string path = dir.file("soil.h5");
  Skeleton s(10);
  {
    SnapshotWriter writer(path);
    for (std::uint32_t k = 0; k < 3; ++k) writer.write(k, 0.01 * k, s.views());
  }
  {
    SnapshotWriter resumed(path, 1);  // snapshots 1 and 2 were written after the checkpoint
    resumed.write(1, 0.01, s.views());
    resumed.write(2, 0.02, s.views());
    resumed.write(3, 0.03, s.views());
  }
  SnapshotReader reader(path);
  ASSERT_EQ(reader.snapshots().size(), 4u);
  for (std::uint32_t k = 0; k < 4; ++k)
    EXPECT_EQ(reader.read_f64(k, "position").values, s.position);
}

TEST(SnapshotWriterUnchanging, AnotherShapeLaterIsRefused) {
  ScratchDir dir;
  SnapshotWriter writer(dir.file("soil.h5"));
  Skeleton s(10), bigger(11);
  writer.write(0, 0.0, s.views());
  EXPECT_THROW(writer.write(1, 0.1, bigger.views()), std::runtime_error);
  writer.write(1, 0.1, s.views());  // the failed write left nothing behind
  SnapshotReader reader(dir.file("soil.h5"));
  EXPECT_EQ(reader.snapshots().size(), 2u);
}

}  // namespace
}  // namespace porosph::io
