// The main() of a built-in solver process (fluid_solver, soil_solver): command line, connection to
// the coupler, the scene it sends, the dimension, and the error paths. Started by `coupler run`; a
// solver connects to POROSPH_ENDPOINT (or --endpoint) and follows proto/porosph.proto.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "proto/coupling_client.h"
#include "proto/solver_runtime.h"
#include "scene/scene_loader.h"

namespace porosph::coupling {

/// What names a built-in solver process.
struct SolverProgram {
  const char* program;      ///< executable name, prefixes its messages on stderr
  const char* description;  ///< --help text
  const char* phase;        ///< "water" | "soil"
  const char* name;         ///< solver name sent in Hello
  const char* version;      ///< solver version sent in Hello
  const char* h5_file;      ///< snapshot file in the run directory
};

/// Runs Solver<2> or Solver<3> (after the scene's run.dimension) against the coupler. Returns the
/// process exit code: 0 when the coupler ended the run, 1 on any failure (reported to the coupler
/// where the connection allows, and on stderr).
template <template <int> class Solver>
int solver_process_main(int argc, char** argv, const SolverProgram& program) {
  CLI::App app{program.description};
  std::string endpoint_arg;
  app.add_option("--endpoint", endpoint_arg, "coupler endpoint (default: $POROSPH_ENDPOINT)");
  app.set_version_flag("--version", program.version);
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<CouplingClient> client;
  try {
    const std::string endpoint = resolve_endpoint(endpoint_arg);
    client = std::make_unique<CouplingClient>(
        endpoint, SolverIdentity{program.phase, program.name, program.version});
    const auto scene = scene::load_scene_text(client->setup().scene_toml, "<scene from coupler>");
    const auto run = [&](auto& solver) {
      const auto writer = open_snapshot_writer(client->setup(), program.h5_file);
      return run_solver_loop(*client, solver, *writer);
    };
    if (scene.run.dimension == 3) {
      Solver<3> solver(scene);
      return run(solver);
    }
    Solver<2> solver(scene);
    return run(solver);
  } catch (const CouplingError& e) {
    std::fprintf(stderr, "%s: %s\n", program.program, e.what());
    return 1;
  } catch (const SolverFailure& e) {
    std::fprintf(stderr, "%s: failed at step %llu, t = %.9g s: %s\n", program.program,
                 static_cast<unsigned long long>(e.step), e.time, e.what());
    if (client) client->report_error(e.what(), e.step, e.time);
    return 1;
  } catch (const std::exception& e) {  // before the step loop: step 0, t = 0
    std::fprintf(stderr, "%s: %s\n", program.program, e.what());
    if (client) client->report_error(e.what(), 0, 0.0);
    return 1;
  }
}

}  // namespace porosph::coupling
