// XDMF 3 index over the phases' HDF5 snapshot files: the one file a user opens in ParaView.
// A temporal collection of spatial collections (one Polyvertex grid per phase per output time).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace porosph::io {

struct XdmfField {
  std::string name;
  std::size_t cols = 1;               ///< 1 scalar; D vector; 9 tensor (row-major 3x3)
  std::string number_type = "Float";  ///< "Float" (8 bytes) | "Int" (8 bytes) | "UChar"
};

struct XdmfSnapshot {
  std::uint32_t index = 0;
  double time = 0;
  std::size_t particle_count = 0;
};

/// One phase's series: its HDF5 file name relative to the XDMF file, its fields, and snapshots.
struct XdmfPhaseSeries {
  std::string phase;
  std::string h5_file;  ///< e.g. "water.h5"
  int dimension = 2;
  std::vector<XdmfField> fields;  ///< besides "position", which becomes the Geometry
  std::vector<XdmfSnapshot> snapshots;
};

/// Writes the XDMF file atomically (temp file + rename). Snapshots of all phases are grouped by
/// output index; a phase missing an index is left out of that time step. A field named "position"
/// is skipped (it is the Geometry). h5_file is written as given, so give it relative to the XDMF
/// file's folder. Throws std::runtime_error naming the path on invalid input (dimension not 2 or 3,
/// unknown number_type, cols 0) - then an existing file is left unchanged - or if writing fails.
void write_xdmf(const std::string& path, const std::vector<XdmfPhaseSeries>& phases);

}  // namespace porosph::io
