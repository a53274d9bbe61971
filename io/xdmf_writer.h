// XDMF 3 index over the phases' HDF5 snapshot files: the one file a user opens in ParaView.
// A temporal collection of spatial collections (one Polyvertex grid per phase per output time).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace porosph::io {

struct XdmfField {
  std::string name;
  std::size_t cols = 1;         ///< 1 scalar; D vector; 9 tensor (row-major 3x3)
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
  std::string h5_file;  ///< e.g. "fluid.h5"
  int dimension = 2;
  std::vector<XdmfField> fields;  ///< besides "position", which becomes the Geometry
  std::vector<XdmfSnapshot> snapshots;
};

/// Writes the XDMF file atomically (temp file + rename). Snapshots of all phases are grouped by
/// output index; a phase missing an index is left out of that time step.
void write_xdmf(const std::string& path, const std::vector<XdmfPhaseSeries>& phases);

}  // namespace porosph::io
