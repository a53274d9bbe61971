// SnapshotWriter / SnapshotReader: layout, exact round trip of every field type, empty snapshots,
// error messages, flush-per-snapshot and no leaked HDF5 ids.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>

#include "io/snapshot_reader.h"
#include "io/snapshot_writer.h"
#include "tests/io/sample_snapshots.h"
#include "tests/io/scratch_dir.h"

namespace porosph::io {
namespace {

using test::make_sample;
using test::SampleSnapshot;
using test::ScratchDir;

/// Message of the std::runtime_error thrown by `action` ("" if none was thrown).
template <class F>
std::string error_of(F&& action) {
  try {
    action();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

/// Bit-exact comparison: HDF5 stores native doubles unchanged, so no tolerance is needed and
/// even the sign of zero / denormals must survive.
void expect_bitwise_equal(const std::vector<double>& expected, const std::vector<double>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  EXPECT_EQ(0, std::memcmp(expected.data(), actual.data(), expected.size() * sizeof(double)));
}

void expect_round_trip(const SnapshotReader& reader, std::uint32_t index, const SampleSnapshot& s) {
  SCOPED_TRACE("snapshot " + std::to_string(index));
  const std::size_t n = s.count();
  const auto d = static_cast<std::size_t>(s.dimension);
  const std::vector<std::string> names = {"density",  "extra",  "fixed",   "id",
                                          "position", "stress", "velocity"};
  EXPECT_EQ(reader.fields(index), names);

  const auto position = reader.read_f64(index, "position");
  EXPECT_EQ(position.rows, n);
  EXPECT_EQ(position.cols, d);
  expect_bitwise_equal(s.position, position.values);
  const auto velocity = reader.read_f64(index, "velocity");
  EXPECT_EQ(velocity.cols, d);
  expect_bitwise_equal(s.velocity, velocity.values);
  const auto density = reader.read_f64(index, "density");
  EXPECT_EQ(density.rows, n);
  EXPECT_EQ(density.cols, 1u);
  expect_bitwise_equal(s.density, density.values);
  const auto stress = reader.read_f64(index, "stress");
  EXPECT_EQ(stress.cols, 9u);
  expect_bitwise_equal(s.stress, stress.values);
  expect_bitwise_equal(s.extra, reader.read_f64(index, "extra").values);
  const auto id = reader.read_i64(index, "id");
  EXPECT_EQ(id.rows, n);
  EXPECT_EQ(id.values, s.id);
  const auto fixed = reader.read_u8(index, "fixed");
  EXPECT_EQ(fixed.rows, n);
  EXPECT_EQ(fixed.values, s.fixed);

  // Shape: (N) for one column, (N, cols) otherwise, also when N == 0.
  const std::string group = snapshot_group(index);
  const DatasetInfo density_info = reader.dataset_info(group + "/density");
  EXPECT_EQ(density_info.dims, std::vector<std::uint64_t>({n}));
  EXPECT_EQ(density_info.type, StoredType::F64);
  const DatasetInfo position_info = reader.dataset_info(group + "/position");
  EXPECT_EQ(position_info.dims, std::vector<std::uint64_t>({n, d}));
  EXPECT_EQ(reader.dataset_info(group + "/stress").dims, std::vector<std::uint64_t>({n, 9}));
  EXPECT_EQ(reader.dataset_info(group + "/id").type, StoredType::I64);
  EXPECT_EQ(reader.dataset_info(group + "/fixed").type, StoredType::U8);
}

TEST(SnapshotGroup, IsSixDigitZeroPadded) {
  EXPECT_EQ(snapshot_group(12), "/snapshots/000012");
  EXPECT_EQ(snapshot_group(0), "/snapshots/000000");
  EXPECT_EQ(snapshot_group(999999), "/snapshots/999999");
}

TEST(SnapshotWriter, RoundTripsEveryFieldTypeIncludingAnEmptySnapshot) {
  ScratchDir dir;
  const SampleSnapshot first = make_sample(5, 2, 0);
  const SampleSnapshot empty = make_sample(0, 2, 1);
  const SampleSnapshot third = make_sample(3, 2, 2);
  const double times[] = {0.0, 0.1, 0.30000000000000004};  // 0.1 and 0.1+0.2 are inexact
  {
    SnapshotWriter writer(dir.file("water.h5"));
    EXPECT_EQ(writer.path(), dir.file("water.h5"));
    writer.write(0, times[0], first.views());
    writer.write(1, times[1], empty.views());
    writer.write(12, times[2], third.views());
  }
  SnapshotReader reader(dir.file("water.h5"));
  const std::vector<SnapshotInfo> snapshots = reader.snapshots();
  ASSERT_EQ(snapshots.size(), 3u);
  const std::uint32_t indices[] = {0, 1, 12};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(snapshots[i].index, indices[i]);
    EXPECT_EQ(snapshots[i].time, times[i]);  // exact: stored as a native double
  }
  EXPECT_TRUE(reader.exists("/snapshots/000012/density"));
  EXPECT_FALSE(reader.exists("/snapshots/000002/density"));
  expect_round_trip(reader, 0, first);
  expect_round_trip(reader, 1, empty);
  expect_round_trip(reader, 12, third);
}

TEST(SnapshotWriter, ThreeDimensionalPositionsHaveThreeColumns) {
  ScratchDir dir;
  const SampleSnapshot sample = make_sample(4, 3, 5);
  SnapshotWriter(dir.file("soil.h5")).write(7, 1.5, sample.views());
  SnapshotReader reader(dir.file("soil.h5"));
  expect_round_trip(reader, 7, sample);
}

TEST(SnapshotWriter, WaterAndSoilWritersWorkSideBySide) {
  ScratchDir dir;
  const SampleSnapshot water = make_sample(4, 2, 1);
  const SampleSnapshot soil = make_sample(6, 2, 2);
  {
    SnapshotWriter fluid(dir.file("water.h5"));
    SnapshotWriter soil_writer(dir.file("soil.h5"));
    for (std::uint32_t index = 0; index < 2; ++index) {
      fluid.write(index, 0.5 * index, water.views());
      soil_writer.write(index, 0.5 * index, soil.views());
    }
  }
  SnapshotReader fluid(dir.file("water.h5"));
  SnapshotReader soil_reader(dir.file("soil.h5"));
  EXPECT_EQ(fluid.snapshots().size(), 2u);
  expect_round_trip(fluid, 1, water);
  expect_round_trip(soil_reader, 1, soil);
}

TEST(SnapshotWriter, UnwritablePathThrowsNamingThePath) {
  ScratchDir dir;
  const std::string missing_folder = dir.file("no_such_folder/water.h5");
  EXPECT_NE(error_of([&] { SnapshotWriter writer(missing_folder); }).find(missing_folder),
            std::string::npos);
  // A folder cannot be truncated into a file (this also holds when the tests run as root).
  const std::string folder = dir.path().string();
  EXPECT_NE(error_of([&] { SnapshotWriter writer(folder); }).find(folder), std::string::npos);
}

TEST(SnapshotWriter, MalformedFieldsThrowAndWriteNothing) {
  ScratchDir dir;
  const std::string path = dir.file("water.h5");
  SnapshotWriter writer(path);
  const std::vector<double> values = {1, 2, 3};
  const std::vector<std::int64_t> ids = {1, 2, 3};

  FieldView no_data{"density", 3, 1};
  FieldView two_pointers{"density", 3, 1, values.data(), ids.data()};
  FieldView empty_untyped{"density", 0, 1};
  FieldView contradicting = field_view("density", values);
  contradicting.type = FieldType::I64;
  for (const FieldView& bad : {no_data, two_pointers, empty_untyped, contradicting}) {
    const std::string message = error_of([&] { writer.write(3, 0.0, {bad}); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("/snapshots/000003/density"), std::string::npos) << message;
  }
  const std::string duplicate = error_of([&] {
    writer.write(3, 0.0, {field_view("a", values), field_view("a", values)});
  });
  EXPECT_NE(duplicate.find("given twice"), std::string::npos) << duplicate;
  EXPECT_NE(error_of([] { field_view("position", std::vector<double>(5), 2); }), "");

  // An empty field with an explicit type needs no pointer.
  FieldView empty_typed{"density", 0, 1};
  empty_typed.type = FieldType::U8;
  writer.write(4, 0.0, {empty_typed});
  // Writing the same index twice is refused.
  EXPECT_NE(error_of([&] { writer.write(4, 1.0, {empty_typed}); }).find("already written"),
            std::string::npos);

  SnapshotReader reader(path);
  ASSERT_EQ(reader.snapshots().size(), 1u);  // the rejected writes left no group behind
  EXPECT_EQ(reader.snapshots()[0].index, 4u);
  EXPECT_EQ(reader.dataset_info("/snapshots/000004/density").type, StoredType::U8);
}

TEST(SnapshotReader, FailuresNameTheFileAndTheDataset) {
  ScratchDir dir;
  const std::string path = dir.file("water.h5");
  SnapshotWriter(path).write(2, 0.25, make_sample(3, 2, 0).views());
  SnapshotReader reader(path);
  const std::string wrong_type = error_of([&] { reader.read_i64(2, "density"); });
  EXPECT_NE(wrong_type.find(path), std::string::npos) << wrong_type;
  EXPECT_NE(wrong_type.find("/snapshots/000002/density"), std::string::npos) << wrong_type;
  const std::string missing = error_of([&] { reader.read_f64(2, "pressure"); });
  EXPECT_NE(missing.find("/snapshots/000002/pressure"), std::string::npos) << missing;
  EXPECT_NE(missing.find(path), std::string::npos) << missing;
  const std::string no_file = dir.file("absent.h5");
  EXPECT_NE(error_of([&] { SnapshotReader absent(no_file); }).find(no_file), std::string::npos);
}

/// A fresh (immediately closed) id of the dataspace or datatype kind, used as a position marker:
/// HDF5 hands out the ids of one kind in increasing order, so every dataspace (datatype) created
/// between two markers has an id strictly between them. File, group, dataset and attribute ids are
/// counted directly with H5Fget_obj_count instead.
hid_t marker(H5I_type_t kind) {
  const hid_t id = kind == H5I_DATASPACE ? H5Screate(H5S_SCALAR) : H5Tcopy(H5T_NATIVE_INT);
  kind == H5I_DATASPACE ? H5Sclose(id) : H5Tclose(id);
  return id;
}

/// Expects that no id created between the markers `before` and `after` is still open.
void expect_all_closed_between(hid_t before, hid_t after, const char* kind) {
  ASSERT_GT(after - before, 1) << kind << ": no ids were created, the check would be vacuous";
  int still_open = 0;
  for (hid_t id = before + 1; id < after; ++id) still_open += H5Iis_valid(id) > 0;
  EXPECT_EQ(still_open, 0) << kind << " ids left open";
}

TEST(SnapshotWriter, ClosesEveryHdf5Id) {
  ScratchDir dir;
  const SampleSnapshot sample = make_sample(4, 2, 0);
  const hid_t space_before = marker(H5I_DATASPACE);
  const hid_t type_before = marker(H5I_DATATYPE);
  ASSERT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
  {
    SnapshotWriter writer(dir.file("water.h5"));
    writer.write(0, 0.0, sample.views());
    EXPECT_THROW(writer.write(0, 0.0, sample.views()), std::runtime_error);
    writer.write(1, 0.1, make_sample(0, 2, 0).views());
    // Only the file itself stays open between snapshots: no group, dataset or attribute.
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 1);
    SnapshotReader reader(dir.file("water.h5"));
    reader.snapshots();
    reader.fields(1);
    reader.read_f64(0, "stress");
    reader.dataset_info("/snapshots/000000/id");
    EXPECT_THROW(reader.read_f64(0, "missing"), std::runtime_error);
    EXPECT_THROW(reader.read_i64(0, "stress"), std::runtime_error);
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 2);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
  expect_all_closed_between(space_before, marker(H5I_DATASPACE), "dataspace");
  expect_all_closed_between(type_before, marker(H5I_DATATYPE), "datatype");
}

TEST(SnapshotWriter, SnapshotsSurviveAProcessThatDiesWithoutClosingTheFile) {
  ScratchDir dir;
  const std::string path = dir.file("water.h5");
  const SampleSnapshot sample = make_sample(4, 2, 3);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Leaked on purpose: _exit skips every destructor, like a crashed solver.
    auto* writer = new SnapshotWriter(path);
    writer->write(0, 0.0, sample.views());
    writer->write(1, 0.5, sample.views());
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  SnapshotReader reader(path);
  ASSERT_EQ(reader.snapshots().size(), 2u);
  EXPECT_EQ(reader.snapshots()[1].time, 0.5);
  expect_round_trip(reader, 1, sample);
}

// A write that fails half-way (here: HDF5 refuses the second dataset's name) leaves no half
// snapshot in /snapshots nor anywhere else, and the index can be written again (issue 29).
TEST(SnapshotWriter, AWriteThatFailsHalfWayLeavesNoHalfSnapshot) {
  ScratchDir dir;
  const std::string path = dir.file("water.h5");
  const std::vector<double> values = {1, 2, 3};
  {
    SnapshotWriter writer(path);
    writer.write(0, 0.0, {field_view("density", values)});
    const std::string message = error_of([&] {
      writer.write(1, 0.5, {field_view("density", values), field_view(".", values)});
    });
    EXPECT_NE(message.find("/snapshots/000001/."), std::string::npos) << message;
    SnapshotReader reader(path);
    ASSERT_EQ(reader.snapshots().size(), 1u) << "a half snapshot is visible";
    writer.write(1, 0.5, {field_view("density", values)});
  }
  SnapshotReader reader(path);
  ASSERT_EQ(reader.snapshots().size(), 2u);
  EXPECT_EQ(reader.snapshots()[1].time, 0.5);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_LE(H5Lexists(file, "/partial_snapshot", H5P_DEFAULT), 0);
  H5Fclose(file);
}

}  // namespace
}  // namespace porosph::io
