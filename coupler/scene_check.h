// `coupler check`: validate a scene, estimate the run's size (coupler/run_size.h), print both and
// the resolved scene; in process, so that tests can feed it scenes by the hundred.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

struct CheckOptions {
  std::string scene_path;
  std::vector<std::string> overrides;  ///< "--set a.b=value"
  std::string out_dir;                 ///< the run directory whose disk is measured; default
                                       ///< runs/<scene name>
  bool force_size = false;             ///< --force-size: a run too big for this machine passes
};

/// Returns the exit code: 0 valid, 2 a bad scene or one too big for this machine (without
/// force_size), the reason on `err` ("coupler: bad scene: FILE:LINE: key 'k': ...").
int check_scene(const CheckOptions& options, std::ostream& out, std::ostream& err);

/// The size gate before a run starts its solvers: "" when `scene` fits this machine (its run
/// directory `out_dir`) or `force` is set, else why not (run_size_problem's text).
std::string size_gate(const scene::Scene& scene, const std::string& out_dir, bool force);

/// Everything a fresh run checks after loading its scene, as the error a run stops with (exit
/// 2): the size gate ("the run does not fit this machine: ..."), then the blocks on the particle
/// lattice ("bad scene: ...", coupler/block_lattice.h); "" when the scene may run.
std::string run_gate(const scene::Scene& scene, const std::string& out_dir, bool force);

}  // namespace porosph::coupler
