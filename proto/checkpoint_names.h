// Names of the checkpoint files in a run directory (docs/checkpoints.md), shared by the coupler and
// the solvers: OUT/checkpoint/<phase>_NNNN.h5 (solvers), coupler_NNNN.json, latest.json.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace porosph::coupling {

/// OUT/checkpoint for the run directory `out_dir`.
inline std::string checkpoint_dir(const std::string& out_dir) { return out_dir + "/checkpoint"; }

/// "<phase>_NNNN.<extension>" (4-digit zero-padded index, more digits past 9999).
inline std::string checkpoint_file_name(const std::string& phase, std::uint32_t index,
                                        const char* extension = "h5") {
  char number[16];
  std::snprintf(number, sizeof number, "%04u", static_cast<unsigned>(index));
  return phase + "_" + number + "." + extension;
}

/// The solver checkpoint file of `phase` for checkpoint `index` in `out_dir`.
inline std::string solver_checkpoint_path(const std::string& out_dir, const std::string& phase,
                                          std::uint32_t index) {
  return checkpoint_dir(out_dir) + "/" + checkpoint_file_name(phase, index);
}

}  // namespace porosph::coupling
