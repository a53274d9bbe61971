// Where a run directory keeps each phase's snapshots, for the tools that read finished runs
// (README.md "The run directory").
#pragma once

#include <filesystem>
#include <string>

namespace porosph::io {

/// The water's snapshot file in `run_dir`: water.h5; in a run written before the phase had one
/// name (issue 24, coupler/phase_slots.h) fluid.h5, when only that one is there.
inline std::string water_snapshot_path(const std::string& run_dir) {
  const std::filesystem::path dir(run_dir);
  const std::filesystem::path current = dir / "water.h5", former = dir / "fluid.h5";
  std::error_code error;
  if (!std::filesystem::exists(current, error) && std::filesystem::exists(former, error))
    return former.string();
  return current.string();
}

}  // namespace porosph::io
