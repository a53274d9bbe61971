// `coupler run`: one coupled run from scene to run directory (docs/design.md sections 1, 4, 6).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace porosph::coupler {

struct RunOptions {
  std::string scene_path;
  std::string out_dir;                 ///< default: runs/<scene name>
  std::vector<std::string> overrides;  ///< "--set a.b=value"
  /// phase -> solver executable named on the command line (--<phase>-solver EXE).
  std::map<std::string, std::string> solver_overrides;
  /// The override of `phase`; empty: none.
  std::string solver_override(const std::string& phase) const {
    const auto found = solver_overrides.find(phase);
    return found == solver_overrides.end() ? std::string() : found->second;
  }
  bool attach = false;   ///< solvers are started by hand and connect to `endpoint`
  std::string endpoint;  ///< default: a fresh ipc:// path
  bool progress = true;
  /// `coupler run --resume DIR`: continue the run in DIR from its latest checkpoint (scene_path,
  /// out_dir and overrides unused: the scene is the one the checkpoint keeps).
  std::string resume_dir;
  /// --overwrite: a fresh run may replace the outputs of an earlier run in its directory (without
  /// it such a directory is refused, docs/reliability.md).
  bool overwrite = false;
  /// --force-size: run even when the size estimate does not fit this machine (coupler/run_size.h).
  bool force_size = false;
};

/// Exit codes of the contract (docs/design.md section 6).
enum ExitCode { kCompleted = 0, kRunFailed = 1, kBadInput = 2 };

/// Runs the scene (or resumes a run, RunOptions::resume_dir; docs/checkpoints.md); never throws.
/// Holds OUT's lock (coupler/run_directory.h) for the run's life, and writes OUT/run.json in every
/// case where OUT could be locked (a failure to write it: the reason on stderr, exit code 1).
int run_scene(const RunOptions& options);

}  // namespace porosph::coupler
