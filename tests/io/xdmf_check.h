// Consistency check of an XDMF index against the HDF5 files it points to, reusable by any test
// that has a run directory (io unit tests, coupler integration tests):
//   #include "tests/io/xdmf_check.h"   and link porosph_io.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "io/snapshot_reader.h"
#include "tests/io/xml_scan.h"

namespace porosph::test {

namespace xdmf_detail {

struct CheckContext {
  std::filesystem::path folder;  ///< the XDMF file's folder: HDF paths are relative to it
  std::map<std::string, std::unique_ptr<io::SnapshotReader>> readers;  ///< by resolved path
  std::map<std::string, std::string> unreadable;                       ///< path -> error
  std::vector<std::string> problems;
  std::size_t data_items_checked = 0;

  void problem(const std::string& where, const std::string& what) {
    problems.push_back(where + ": " + what);
  }
  /// The reader of an HDF5 file, or nullptr (and one problem) if it cannot be opened.
  io::SnapshotReader* reader(const std::string& h5_file, const std::string& where) {
    std::filesystem::path file(h5_file);
    if (file.is_relative()) file = folder / file;
    const std::string key = file.lexically_normal().string();
    if (auto it = readers.find(key); it != readers.end()) return it->second.get();
    if (unreadable.count(key) == 0) {
      try {
        return (readers[key] = std::make_unique<io::SnapshotReader>(key)).get();
      } catch (const std::exception& error) {
        readers.erase(key);
        unreadable[key] = error.what();
        problem(where, std::string("cannot open HDF5 file: ") + error.what());
      }
    }
    return nullptr;
  }
};

inline std::vector<std::uint64_t> parse_dimensions(const std::string& text, bool& ok) {
  std::istringstream in(text);
  std::vector<std::uint64_t> dims;
  std::string word;
  ok = true;
  while (in >> word) {
    if (word.find_first_not_of("0123456789") != std::string::npos)
      ok = false;
    else
      dims.push_back(std::stoull(word));
  }
  ok = ok && !dims.empty();
  return dims;
}

inline std::string join_dimensions(const std::vector<std::uint64_t>& dims) {
  std::string text;
  for (std::size_t i = 0; i < dims.size(); ++i) text += (i ? " " : "") + std::to_string(dims[i]);
  return text;
}

/// Element type named by NumberType/Precision (XDMF defaults: Float, precision 4; UChar 1).
inline io::StoredType declared_type(const XmlElement& item) {
  const std::string number_type = item.attribute("NumberType", "Float");
  const std::string precision = item.attribute("Precision", number_type == "UChar" ? "1" : "4");
  if (number_type == "Float" && precision == "8") return io::StoredType::F64;
  if (number_type == "Int" && precision == "8") return io::StoredType::I64;
  if (number_type == "UChar" && precision == "1") return io::StoredType::U8;
  return io::StoredType::Other;
}

/// Checks one DataItem; returns its declared dimensions (empty if unusable).
inline std::vector<std::uint64_t> check_data_item(const XmlElement& item, const std::string& where,
                                                  CheckContext& context) {
  bool ok = false;
  const std::vector<std::uint64_t> dims = parse_dimensions(item.attribute("Dimensions"), ok);
  if (!ok) {
    context.problem(where, "bad Dimensions \"" + item.attribute("Dimensions") + "\"");
    return {};
  }
  if (item.attribute("Format", "XML") != "HDF") return dims;  // inline data: nothing to resolve
  std::string reference = item.text;
  const std::size_t first = reference.find_first_not_of(" \t\r\n");
  const std::size_t last = reference.find_last_not_of(" \t\r\n");
  reference = first == std::string::npos ? "" : reference.substr(first, last - first + 1);
  const std::size_t colon = reference.rfind(':');
  if (colon == std::string::npos || colon + 1 >= reference.size() || reference[colon + 1] != '/') {
    context.problem(where, "HDF reference \"" + reference + "\" is not FILE:/DATASET");
    return {};
  }
  const std::string h5_file = reference.substr(0, colon);
  const std::string dataset = reference.substr(colon + 1);
  const std::string at = where + " -> " + reference;
  ++context.data_items_checked;
  io::SnapshotReader* reader = context.reader(h5_file, at);
  if (reader == nullptr) return {};
  if (!reader->exists(dataset)) {
    context.problem(at, "no such dataset in " + reader->path());
    return {};
  }
  try {
    const io::DatasetInfo info = reader->dataset_info(dataset);
    if (info.dims != dims) {
      context.problem(at, "declared Dimensions \"" + join_dimensions(dims) +
                              "\" but the dataset has \"" + join_dimensions(info.dims) + "\"");
    }
    const io::StoredType declared = declared_type(item);
    if (declared == io::StoredType::Other || declared != info.type) {
      context.problem(at, "declared " + item.attribute("NumberType", "Float") + " " +
                              item.attribute("Precision", "(default)") + " but the dataset holds " +
                              io::describe(info.type));
    }
  } catch (const std::exception& error) {
    context.problem(at, error.what());
  }
  return dims;
}

/// Checks a Uniform grid: Topology size vs every DataItem's rows, Geometry and Attribute shapes.
inline void check_uniform_grid(const XmlElement& grid, const std::string& where,
                               CheckContext& context) {
  const auto topologies = grid.children_named("Topology");
  const auto geometries = grid.children_named("Geometry");
  if (topologies.size() != 1 || geometries.size() != 1) {
    context.problem(where, "needs exactly one Topology and one Geometry");
    return;
  }
  const std::string count_text = topologies[0]->attribute("NumberOfElements", "?");
  bool ok = false;
  const auto count = parse_dimensions(count_text, ok);
  if (!ok || count.size() != 1) context.problem(where, "bad NumberOfElements " + count_text);
  const auto expect_rows = [&](const std::vector<std::uint64_t>& dims, const std::string& at) {
    if (ok && count.size() == 1 && !dims.empty() && dims[0] != count[0]) {
      context.problem(at, std::to_string(dims[0]) + " rows but NumberOfElements " + count_text);
    }
  };
  const std::string geometry_type = geometries[0]->attribute("GeometryType");
  const std::uint64_t d = geometry_type == "XY" ? 2 : geometry_type == "XYZ" ? 3 : 0;
  if (d == 0) context.problem(where, "unsupported GeometryType \"" + geometry_type + "\"");
  for (const XmlElement* item : geometries[0]->children_named("DataItem")) {
    const auto dims = check_data_item(*item, where + "/Geometry", context);
    if (d != 0 && !dims.empty() && (dims.size() != 2 || dims[1] != d)) {
      context.problem(where + "/Geometry",
                      geometry_type + " needs Dimensions \"N " + std::to_string(d) + "\"");
    }
    expect_rows(dims, where + "/Geometry");
  }
  for (const XmlElement* attribute : grid.children_named("Attribute")) {
    const std::string at = where + "/Attribute[" + attribute->attribute("Name") + "]";
    const std::string kind = attribute->attribute("AttributeType", "Scalar");
    for (const XmlElement* item : attribute->children_named("DataItem")) {
      const auto dims = check_data_item(*item, at, context);
      expect_rows(dims, at);
      if (dims.empty()) continue;
      const std::uint64_t cols = dims.size() == 1 ? 1 : dims[1];
      const bool shape_fits = (kind == "Scalar" && dims.size() == 1) ||
                              (kind == "Vector" && dims.size() == 2 && (cols == 2 || cols == 3)) ||
                              (kind == "Tensor" && dims.size() == 2 && cols == 9) ||
                              (kind == "Matrix" && dims.size() == 2);
      if (!shape_fits)
        context.problem(at, kind + " does not fit \"" + join_dimensions(dims) + "\"");
    }
  }
}

/// Walks the grid tree; every spatial step of a temporal collection needs a Time, increasing.
inline void check_grid(const XmlElement& grid, const std::string& where, CheckContext& context) {
  const std::string type = grid.attribute("GridType", "Uniform");
  const std::string at = where + "/Grid[" + grid.attribute("Name") + "]";
  if (type == "Uniform") {
    check_uniform_grid(grid, at, context);
    return;
  }
  if (type != "Collection") {
    context.problem(at, "unsupported GridType " + type);
    return;
  }
  const bool temporal = grid.attribute("CollectionType") == "Temporal";
  double previous_time = -HUGE_VAL;
  for (const XmlElement* child : grid.children_named("Grid")) {
    if (temporal) {
      const auto times = child->children_named("Time");
      char* end = nullptr;
      const std::string value = times.size() == 1 ? times[0]->attribute("Value") : "";
      const double time = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0') {
        context.problem(at, "step " + child->attribute("Name") + " has no numeric <Time Value>");
      } else if (!(time > previous_time)) {
        context.problem(at, "step " + child->attribute("Name") + " time does not increase");
      } else {
        previous_time = time;
      }
    }
    check_grid(*child, at, context);
  }
}

}  // namespace xdmf_detail

/// Checks the XDMF file at `xdmf_path`: well-formed XML, <Xdmf Version="3.0"> with one Domain, and
/// every HDF DataItem `FILE:/DATASET` (FILE relative to the XDMF file's folder) resolves to an
/// existing dataset whose shape equals the declared Dimensions and whose element type matches
/// NumberType/Precision (Float 8, Int 8, UChar 1). Also checks NumberOfElements against the rows,
/// Geometry columns, AttributeType against the shape, and increasing Time values.
/// Returns the problems found (empty if none). `data_items_checked`, if given, receives the number
/// of HDF DataItems examined, so callers can assert that the check covered what they expect.
inline std::vector<std::string> check_xdmf_references(const std::string& xdmf_path,
                                                      std::size_t* data_items_checked = nullptr) {
  xdmf_detail::CheckContext context;
  context.folder = std::filesystem::path(xdmf_path).parent_path();
  if (data_items_checked != nullptr) *data_items_checked = 0;
  std::ifstream file(xdmf_path, std::ios::binary);
  if (!file) return {xdmf_path + ": cannot open"};
  std::stringstream text;
  text << file.rdbuf();
  XmlElement root;
  try {
    root = parse_xml(text.str());
  } catch (const std::exception& error) {
    return {xdmf_path + ": " + error.what()};
  }
  if (root.name != "Xdmf" || root.attribute("Version") != "3.0") {
    context.problem(xdmf_path, "root is not <Xdmf Version=\"3.0\">");
  }
  const auto domains = root.children_named("Domain");
  if (domains.size() != 1) context.problem(xdmf_path, "needs exactly one Domain");
  for (const XmlElement* domain : domains) {
    for (const XmlElement* grid : domain->children_named("Grid")) {
      xdmf_detail::check_grid(*grid, xdmf_path, context);
    }
  }
  if (data_items_checked != nullptr) *data_items_checked = context.data_items_checked;
  return context.problems;
}

}  // namespace porosph::test
