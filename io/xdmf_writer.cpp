#include "io/xdmf_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/snapshot_writer.h"

namespace porosph::io {

namespace {

/// Escapes the five XML special characters for attribute values and text.
std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// Shortest decimal text that reads back as exactly `value`.
std::string exact_decimal(double value) {
  if (!std::isfinite(value)) throw std::runtime_error("write_xdmf: non-finite time");
  char text[40];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

/// XDMF NumberType and Precision of a field's element type.
std::pair<std::string, int> number_type_and_precision(const XdmfField& field,
                                                      const std::string& where) {
  if (field.number_type == "Float") return {"Float", 8};
  if (field.number_type == "Int") return {"Int", 8};
  if (field.number_type == "UChar") return {"UChar", 1};
  throw std::runtime_error(where + ": number_type '" + field.number_type +
                           "' is not Float, Int or UChar");
}

std::string attribute_type(std::size_t cols, int dimension) {
  if (cols == 1) return "Scalar";
  if (cols == static_cast<std::size_t>(dimension) || cols == 3) return "Vector";
  if (cols == 9) return "Tensor";
  return "Matrix";
}

std::string dimensions(std::size_t rows, std::size_t cols) {
  return cols == 1 ? std::to_string(rows) : std::to_string(rows) + " " + std::to_string(cols);
}

void write_data_item(std::ostream& out, const std::string& indent, std::size_t rows,
                     std::size_t cols, const std::string& number_type, int precision,
                     const std::string& h5_file, std::uint32_t index, const std::string& field) {
  out << indent << "<DataItem Dimensions=\"" << dimensions(rows, cols) << "\" NumberType=\""
      << number_type << "\" Precision=\"" << precision << "\" Format=\"HDF\">"
      << xml_escape(h5_file + ":" + snapshot_group(index) + "/" + field) << "</DataItem>\n";
}

void validate(const XdmfPhaseSeries& phase, const std::string& path) {
  const std::string where = "write_xdmf('" + path + "') phase '" + phase.phase + "'";
  if (phase.phase.empty()) throw std::runtime_error(where + ": empty phase name");
  if (phase.h5_file.empty()) throw std::runtime_error(where + ": empty h5_file");
  if (phase.dimension != 2 && phase.dimension != 3) {
    throw std::runtime_error(where + ": dimension must be 2 or 3");
  }
  for (const XdmfField& field : phase.fields) {
    if (field.cols == 0) throw std::runtime_error(where + " field '" + field.name + "': cols 0");
    number_type_and_precision(field, where + " field '" + field.name + "'");
  }
}

/// One phase's Uniform grid for one snapshot.
void write_phase_grid(std::ostream& out, const XdmfPhaseSeries& phase,
                      const XdmfSnapshot& snapshot) {
  const std::size_t n = snapshot.particle_count;
  const auto d = static_cast<std::size_t>(phase.dimension);
  out << "        <Grid Name=\"" << xml_escape(phase.phase) << "\" GridType=\"Uniform\">\n"
      << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"/>\n"
      << "          <Geometry GeometryType=\"" << (d == 2 ? "XY" : "XYZ") << "\">\n";
  write_data_item(out, "            ", n, d, "Float", 8, phase.h5_file, snapshot.index, "position");
  out << "          </Geometry>\n";
  for (const XdmfField& field : phase.fields) {
    if (field.name == "position") continue;  // it is the Geometry
    const auto [number_type, precision] = number_type_and_precision(field, "write_xdmf");
    out << "          <Attribute Name=\"" << xml_escape(field.name) << "\" AttributeType=\""
        << attribute_type(field.cols, phase.dimension) << "\" Center=\"Node\">\n";
    write_data_item(out, "            ", n, field.cols, number_type, precision, phase.h5_file,
                    snapshot.index, field.name);
    out << "          </Attribute>\n";
  }
  out << "        </Grid>\n";
}

}  // namespace

void write_xdmf(const std::string& path, const std::vector<XdmfPhaseSeries>& phases) {
  // Output index -> (phase, snapshot) pairs present at that index, in phase order.
  std::map<std::uint32_t, std::vector<std::pair<const XdmfPhaseSeries*, const XdmfSnapshot*>>>
      by_index;
  for (const XdmfPhaseSeries& phase : phases) {
    validate(phase, path);
    for (const XdmfSnapshot& snapshot : phase.snapshots) {
      by_index[snapshot.index].emplace_back(&phase, &snapshot);
    }
  }

  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& [index, entries] : by_index) {
    // All phases share the coupler's output times; the first phase's time labels the step.
    out << "      <Grid Name=\"output_" << snapshot_group(index).substr(11)
        << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "        <Time Value=\"" << exact_decimal(entries.front().second->time) << "\"/>\n";
    for (const auto& [phase, snapshot] : entries) write_phase_grid(out, *phase, *snapshot);
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";

  const std::string temporary = path + ".tmp";
  // Every failure names the file and the system's reason (errno), and leaves no temporary file.
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("write_xdmf: cannot " + what + ": " + reason);
  };
  {
    errno = 0;
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) fail("create '" + temporary + "'");
    file << out.str();
    file.close();
    if (!file) fail("write '" + temporary + "'");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    fail("rename '" + temporary + "' to '" + path + "'");
  }
}

}  // namespace porosph::io
