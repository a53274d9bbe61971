// How the coupler starts a phase solver: which command (command line over scene over built-in),
// its arguments, and the environment the solver processes share the cores by.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "coupler/socket_dir.h"
#include "coupler/solver_hub.h"
#include "scene/scene.h"

namespace porosph::coupler {

/// The command of one phase's solver, resolved but not yet searched for on disk.
struct SolverCommand {
  std::string requested;          ///< as given ("my_solver --model x"), or the built-in name
  std::vector<std::string> args;  ///< the words of `requested`, the program first
  bool user_named = false;        ///< false: the built-in fluid_solver / soil_solver
};

/// `command_line` (--water-solver / --soil-solver) wins over the scene (water.solver /
/// soil.solver); neither names one: the built-in solver. A command may carry its own arguments,
/// split at spaces. Throws std::invalid_argument for a command of only spaces.
SolverCommand resolve_solver_command(const std::string& phase, const std::string& command_line,
                                     const scene::Scene& scene);

/// Environment of the solvers of a run with `solvers` processes: POROSPH_ENDPOINT,
/// POROSPH_RUN_TOKEN (the run's secret: in the environment, not on the command line, so that
/// other users cannot read it), and when several share the cores (unless the user set them)
/// OMP_WAIT_POLICY=PASSIVE and OMP_NUM_THREADS = cores / solvers: OpenMP threads that spin while
/// their process waits for the coupler steal the other solver's core (measured: 30x slower).
std::vector<std::pair<std::string, std::string>> solver_environment(const std::string& endpoint,
                                                                    const std::string& run_token,
                                                                    unsigned solvers);

/// The largest frame a solver of `scene` can need to send (its whole phase as overlap particles,
/// with every optional array, twice over), for SolverHub's frame limit: the particle lattice of
/// the box around the domain and every wall, grown by 8 dp on each side; at least 1 MiB.
std::size_t max_frame_bytes(const scene::Scene& scene);

/// The hub of a run, its frames limited by max_frame_bytes(scene): at `endpoint`, or (empty) at a
/// fresh ipc socket in a private directory that `socket_dir` then holds (keep it until the hub is
/// gone; older directories of dead couplers are swept first). Throws BadEndpoint,
/// std::runtime_error.
std::unique_ptr<SolverHub> open_solver_hub(const std::string& endpoint, const scene::Scene& scene,
                                           std::unique_ptr<PrivateSocketDir>& socket_dir);

/// How long a solver waits for the coupler (Setup.timeout_seconds) when the coupler waits
/// `coupler_timeout` for a solver (run.solver_timeout): 2 x + 5 s, so that when one solver stalls
/// the coupler's timeout fires first and names it, and the healthy solver is still waiting.
inline double solver_side_timeout(double coupler_timeout) { return 2.0 * coupler_timeout + 5.0; }

/// What `coupler run --attach` tells the user: where the solvers connect, the token they need
/// (POROSPH_RUN_TOKEN) and, for `everywhere`, that every interface of the machine listens.
std::string attach_instructions(const std::vector<std::string>& phases, const std::string& endpoint,
                                const std::string& run_token, bool everywhere);

}  // namespace porosph::coupler
