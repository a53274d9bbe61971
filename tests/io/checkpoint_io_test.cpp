// The I/O pieces of checkpoints (docs/checkpoints.md): checkpoint files round-trip exactly and
// appear atomically, a resumed snapshot file drops the snapshots after the checkpoint, a resumed
// timeseries.csv keeps exactly the rows before it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/checkpoint_file.h"
#include "io/snapshot_reader.h"
#include "io/snapshot_writer.h"
#include "io/timeseries_csv.h"
#include "tests/io/scratch_dir.h"

namespace porosph::io {
namespace {

using test::ScratchDir;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CheckpointFile, ArraysAndScalarsRoundTripBitForBit) {
  ScratchDir dir;
  const std::string path = dir.file("water_0001.h5");
  const std::vector<double> xy = {0.1, 1.0 / 3.0, -2.5e-300, std::nan("")};
  const std::vector<std::int64_t> ids = {7, -1, 1LL << 40};
  const std::vector<std::int32_t> zones = {-1, 0, 2};
  const std::vector<std::uint8_t> flags = {0, 1, 1};
  {
    CheckpointWriter out(path);
    out.write("xy", xy.data(), 2, 2);
    out.write("ids", ids.data(), ids.size());
    out.write("zones", zones.data(), zones.size());
    out.write("flags", flags.data(), flags.size());
    out.write("empty", static_cast<const double*>(nullptr), 0);
    out.set("time", 0.1 + 0.2);
    out.set("step", std::int64_t{123456789});
    EXPECT_FALSE(std::filesystem::exists(path)) << "visible before commit";
    out.commit();
  }
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const CheckpointReader in(path);
  ASSERT_EQ(in.rows("xy", 2), 2u);
  std::vector<double> xy_back(4);
  in.read("xy", xy_back.data(), 2);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(xy_back[i], xy[i]);
  EXPECT_TRUE(std::isnan(xy_back[3]));
  std::vector<std::int64_t> ids_back(3);
  in.read("ids", ids_back.data());
  EXPECT_EQ(ids_back, ids);
  std::vector<std::int32_t> zones_back(3);
  in.read("zones", zones_back.data());
  EXPECT_EQ(zones_back, zones);
  std::vector<std::uint8_t> flags_back(3);
  in.read("flags", flags_back.data());
  EXPECT_EQ(flags_back, flags);
  EXPECT_EQ(in.rows("empty"), 0u);
  EXPECT_EQ(in.get_f64("time"), 0.1 + 0.2);
  EXPECT_EQ(in.get_i64("step"), 123456789);
  EXPECT_TRUE(in.has("ids"));
  EXPECT_TRUE(in.has("step"));
  EXPECT_FALSE(in.has("nothing"));
  EXPECT_THROW(in.rows("xy", 3), std::runtime_error);                // wrong width
  EXPECT_THROW(in.read("ids", xy_back.data()), std::runtime_error);  // wrong element type
  EXPECT_THROW(in.get_f64("nothing"), std::runtime_error);
}

TEST(CheckpointFile, AnUncommittedWriterLeavesThePreviousFile) {
  ScratchDir dir;
  const std::string path = dir.file("soil_0002.h5");
  {
    CheckpointWriter out(path);
    out.set("step", std::int64_t{1});
    out.commit();
  }
  {
    CheckpointWriter out(path);
    out.set("step", std::int64_t{2});
    // destroyed without commit: as a writer that failed half-way
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  EXPECT_EQ(CheckpointReader(path).get_i64("step"), 1);
}

TEST(SnapshotWriterResume, DropsTheSnapshotsFromTheFirstDroppedIndex) {
  ScratchDir dir;
  const std::string path = dir.file("water.h5");
  const std::vector<double> density = {1000.0, 1001.0};
  {
    SnapshotWriter writer(path);
    for (std::uint32_t i = 0; i < 5; ++i)
      writer.write(i, 0.1 * i, {field_view("density", density)});
  }
  {
    SnapshotWriter writer(path, 3);  // the checkpoint was taken before output 3
    writer.write(3, 0.3, {field_view("density", density)});
  }
  const SnapshotReader reader(path);
  const auto snapshots = reader.snapshots();
  ASSERT_EQ(snapshots.size(), 4u);
  EXPECT_EQ(snapshots.back().index, 3u);
  EXPECT_EQ(reader.read_f64(3, "density").values, density);
}

TEST(TimeSeriesCsvResume, KeepsTheRowsBeforeTheCheckpointAndAppends) {
  ScratchDir dir;
  const std::string path = dir.file("timeseries.csv");
  {
    TimeSeriesCsv csv(path, {"t", "e"});
    for (int i = 0; i < 4; ++i) csv.append({0.1 * i, 1.0 * i});
  }
  {
    TimeSeriesCsv csv(path, {"t", "e"}, 2);
    csv.append({0.2, 5.0});
  }
  EXPECT_EQ(read_text(path), "t,e\n0,0\n0.1,1\n0.2,5\n");
  EXPECT_THROW(TimeSeriesCsv(path, {"t", "other"}, 1), std::runtime_error);  // another header
  EXPECT_THROW(TimeSeriesCsv(path, {"t", "e"}, 9), std::runtime_error);      // rows missing
  EXPECT_THROW(TimeSeriesCsv(dir.file("none.csv"), {"t"}, 0), std::runtime_error);
}

}  // namespace
}  // namespace porosph::io
