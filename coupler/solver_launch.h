// How the coupler starts a phase solver: which command (command line over scene over built-in),
// its arguments, and the environment the solver processes share the cores by.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

/// The command of one phase's solver, resolved but not yet searched for on disk.
struct SolverCommand {
  std::string requested;          ///< as given ("my_solver --model x"), or the built-in name
  std::vector<std::string> args;  ///< the words of `requested`, the program first
  bool user_named = false;        ///< false: the built-in fluid_solver / soil_solver
};

/// `command_line` (--fluid-solver / --soil-solver) wins over the scene (water.solver /
/// soil.solver); neither names one: the built-in solver. A command may carry its own arguments,
/// split at spaces. Throws std::invalid_argument for a command of only spaces.
SolverCommand resolve_solver_command(const std::string& phase, const std::string& command_line,
                                     const scene::Scene& scene);

/// Environment of the solvers of a run with `solvers` processes: POROSPH_ENDPOINT, and when
/// several share the cores (unless the user set them) OMP_WAIT_POLICY=PASSIVE and
/// OMP_NUM_THREADS = cores / solvers: OpenMP threads that spin while their process waits for the
/// coupler steal the other solver's core (measured: 30x slower).
std::vector<std::pair<std::string, std::string>> solver_environment(const std::string& endpoint,
                                                                    unsigned solvers);

}  // namespace porosph::coupler
