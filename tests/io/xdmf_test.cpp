// write_xdmf: structure of the index, and consistency with the HDF5 snapshots it points to (via the
// reusable checker in xdmf_check.h, which is itself shown to catch each kind of mismatch).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/snapshot_writer.h"
#include "io/xdmf_writer.h"
#include "tests/io/sample_snapshots.h"
#include "tests/io/scratch_dir.h"
#include "tests/io/xdmf_check.h"
#include "tests/io/xml_scan.h"

namespace porosph::io {
namespace {

using test::check_xdmf_references;
using test::make_sample;
using test::ScratchDir;
using test::XmlElement;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Writes `h5_path` with one snapshot per (index, time, count) and returns the matching series.
XdmfPhaseSeries write_phase(const std::string& h5_path, const std::string& h5_name,
                            const std::string& phase, int dimension,
                            const std::vector<XdmfSnapshot>& snapshots) {
  SnapshotWriter writer(h5_path);
  XdmfPhaseSeries series{phase, h5_name, dimension, {}, snapshots};
  for (const XdmfSnapshot& snapshot : snapshots) {
    const auto sample = make_sample(snapshot.particle_count, dimension, int(snapshot.index));
    writer.write(snapshot.index, snapshot.time, sample.views());
    series.fields = sample.xdmf_fields();
  }
  return series;
}

/// Fluid at outputs 0, 1, 2 (output 1 empty); soil at outputs 0 and 2 only.
std::vector<XdmfPhaseSeries> write_two_phases(const ScratchDir& dir) {
  return {write_phase(dir.file("water.h5"), "water.h5", "water", 2,
                      {{0, 0.0, 4}, {1, 0.1, 0}, {2, 0.2, 3}}),
          write_phase(dir.file("soil.h5"), "soil.h5", "soil", 2, {{0, 0.0, 6}, {2, 0.2, 5}})};
}

TEST(WriteXdmf, TwoPhasesResolveToTheirHdf5Datasets) {
  ScratchDir dir;
  const auto phases = write_two_phases(dir);
  write_xdmf(dir.file("run.xdmf"), phases);
  EXPECT_FALSE(std::filesystem::exists(dir.file("run.xdmf.tmp")));

  std::size_t checked = 0;
  const auto problems = check_xdmf_references(dir.file("run.xdmf"), &checked);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems);
  // 5 phase-snapshots, each with position + 6 fields: every one of them was resolved.
  EXPECT_EQ(checked, 5u * 7u);
}

TEST(WriteXdmf, StructureIsATemporalCollectionOfSpatialCollections) {
  ScratchDir dir;
  write_xdmf(dir.file("run.xdmf"), write_two_phases(dir));
  const XmlElement root = test::parse_xml(read_text(dir.file("run.xdmf")));
  EXPECT_EQ(root.name, "Xdmf");
  EXPECT_EQ(root.attribute("Version"), "3.0");
  const auto domain = root.children_named("Domain");
  ASSERT_EQ(domain.size(), 1u);
  const auto temporal = domain[0]->children_named("Grid");
  ASSERT_EQ(temporal.size(), 1u);
  EXPECT_EQ(temporal[0]->attribute("GridType"), "Collection");
  EXPECT_EQ(temporal[0]->attribute("CollectionType"), "Temporal");

  const auto steps = temporal[0]->children_named("Grid");
  ASSERT_EQ(steps.size(), 3u);
  const std::vector<std::string> times = {"0", "0.1", "0.2"};
  const std::vector<std::vector<std::string>> phases = {
      {"water", "soil"}, {"water"}, {"water", "soil"}};
  for (std::size_t s = 0; s < steps.size(); ++s) {
    EXPECT_EQ(steps[s]->attribute("CollectionType"), "Spatial");
    ASSERT_EQ(steps[s]->children_named("Time").size(), 1u);
    EXPECT_EQ(steps[s]->children_named("Time")[0]->attribute("Value"), times[s]);
    std::vector<std::string> names;
    for (const XmlElement* grid : steps[s]->children_named("Grid")) {
      names.push_back(grid->attribute("Name"));
      EXPECT_EQ(grid->attribute("GridType"), "Uniform");
    }
    EXPECT_EQ(names, phases[s]) << "output " << s;
  }

  // Output 2, soil: 5 particles.
  const XmlElement& soil = *steps[2]->children_named("Grid")[1];
  const XmlElement& topology = *soil.children_named("Topology")[0];
  EXPECT_EQ(topology.attribute("TopologyType"), "Polyvertex");
  EXPECT_EQ(topology.attribute("NumberOfElements"), "5");
  EXPECT_EQ(topology.attribute("NodesPerElement"), "1");
  const XmlElement& geometry = *soil.children_named("Geometry")[0];
  EXPECT_EQ(geometry.attribute("GeometryType"), "XY");
  const XmlElement& position = geometry.children[0];
  EXPECT_EQ(position.attribute("Dimensions"), "5 2");
  EXPECT_EQ(position.attribute("Format"), "HDF");
  EXPECT_EQ(position.text, "soil.h5:/snapshots/000002/position");

  std::map<std::string, std::string> kinds, number_types, dimensions;
  for (const XmlElement* attribute : soil.children_named("Attribute")) {
    const std::string name = attribute->attribute("Name");
    EXPECT_EQ(attribute->attribute("Center"), "Node");
    kinds[name] = attribute->attribute("AttributeType");
    const XmlElement& item = attribute->children.at(0);
    number_types[name] = item.attribute("NumberType") + " " + item.attribute("Precision");
    dimensions[name] = item.attribute("Dimensions");
  }
  const std::map<std::string, std::string> expected_kinds = {
      {"velocity", "Vector"}, {"density", "Scalar"}, {"stress", "Tensor"},
      {"extra", "Matrix"},    {"id", "Scalar"},      {"fixed", "Scalar"}};
  EXPECT_EQ(kinds, expected_kinds);
  EXPECT_EQ(number_types["velocity"], "Float 8");
  EXPECT_EQ(number_types["id"], "Int 8");
  EXPECT_EQ(number_types["fixed"], "UChar 1");
  EXPECT_EQ(dimensions["density"], "5");
  EXPECT_EQ(dimensions["stress"], "5 9");
  EXPECT_EQ(dimensions["extra"], "5 4");
}

TEST(WriteXdmf, ThreeDimensionsAndReferencesRelativeToTheXdmfFolder) {
  ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "data");
  std::filesystem::create_directories(dir.path() / "index");
  // A time that needs 17 digits must be written exactly.
  const double time = 0.1 + 0.2;
  auto series =
      write_phase(dir.file("data/soil.h5"), "../data/soil.h5", "soil & rock", 3, {{5, time, 4}});
  series.fields.push_back({"position", 3, "Float"});  // skipped: it is the Geometry
  write_xdmf(dir.file("index/run.xdmf"), {series});
  std::size_t checked = 0;
  const auto problems = check_xdmf_references(dir.file("index/run.xdmf"), &checked);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems);
  EXPECT_EQ(checked, 7u);  // position once, as Geometry, + 6 fields

  const XmlElement root = test::parse_xml(read_text(dir.file("index/run.xdmf")));
  const XmlElement& step = root.children[0].children[0].children[0];
  EXPECT_EQ(std::stod(step.children_named("Time")[0]->attribute("Value")), time);
  const XmlElement& grid = *step.children_named("Grid")[0];
  EXPECT_EQ(grid.attribute("Name"), "soil & rock");
  EXPECT_EQ(grid.children_named("Geometry")[0]->attribute("GeometryType"), "XYZ");
  EXPECT_EQ(grid.children_named("Geometry")[0]->children[0].attribute("Dimensions"), "4 3");
  EXPECT_EQ(grid.children_named("Attribute")[0]->attribute("AttributeType"), "Vector");
}

/// Each kind of mismatch between index and data is reported, naming the offending reference.
TEST(CheckXdmfReferences, ReportsEveryKindOfMismatch) {
  ScratchDir dir;
  const auto good = write_two_phases(dir);
  const std::string xdmf = dir.file("run.xdmf");
  const auto problems_with = [&](const std::vector<XdmfPhaseSeries>& phases) {
    write_xdmf(xdmf, phases);
    return ::testing::PrintToString(check_xdmf_references(xdmf));
  };
  auto wrong_count = good;
  wrong_count[0].snapshots[2].particle_count = 4;  // the dataset has 3 rows
  EXPECT_NE(problems_with(wrong_count).find("water.h5:/snapshots/000002/position"),
            std::string::npos);
  auto wrong_type = good;
  wrong_type[1].fields[1].number_type = "Int";  // density is Float 8
  EXPECT_NE(problems_with(wrong_type).find("soil.h5:/snapshots/000000/density"), std::string::npos);
  auto wrong_cols = good;
  wrong_cols[1].fields[2].cols = 6;  // stress has 9 columns
  EXPECT_NE(problems_with(wrong_cols).find("/snapshots/000000/stress"), std::string::npos);
  auto missing_field = good;
  missing_field[0].fields.push_back({"pressure", 1, "Float"});
  EXPECT_NE(problems_with(missing_field).find("no such dataset"), std::string::npos);
  auto missing_index = good;
  missing_index[0].snapshots.push_back({3, 0.3, 2});
  EXPECT_NE(problems_with(missing_index).find("water.h5:/snapshots/000003/position"),
            std::string::npos);
  auto missing_file = good;
  missing_file[1].h5_file = "clay.h5";
  EXPECT_NE(problems_with(missing_file).find("cannot open HDF5 file"), std::string::npos);

  std::ofstream(xdmf) << "<Xdmf Version=\"3.0\"><Domain></Xdmf>";
  EXPECT_NE(::testing::PrintToString(check_xdmf_references(xdmf)).find("XML error"),
            std::string::npos);
  EXPECT_FALSE(check_xdmf_references(dir.file("absent.xdmf")).empty());
}

TEST(WriteXdmf, InvalidInputThrowsAndKeepsThePreviousFile) {
  ScratchDir dir;
  const auto phases = write_two_phases(dir);
  const std::string xdmf = dir.file("run.xdmf");
  write_xdmf(xdmf, phases);
  const std::string before = read_text(xdmf);

  auto bad_type = phases;
  bad_type[0].fields[0].number_type = "Double";
  EXPECT_THROW(write_xdmf(xdmf, bad_type), std::runtime_error);
  auto bad_dimension = phases;
  bad_dimension[1].dimension = 4;
  EXPECT_THROW(write_xdmf(xdmf, bad_dimension), std::runtime_error);
  EXPECT_EQ(read_text(xdmf), before);

  const std::string unwritable = dir.file("no_such_folder/run.xdmf");
  try {
    write_xdmf(unwritable, phases);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(unwritable), std::string::npos) << error.what();
    // ... and the system's reason (issue 29: "the xdmf error gives no reason").
    EXPECT_NE(std::string(error.what()).find("No such file or directory"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace porosph::io
