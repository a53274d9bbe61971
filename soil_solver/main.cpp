// soil_solver: the soil phase (Drucker-Prager SPH, seed eq. 5-12, 18-20) as a process driven by the
// coupler.
// Started by `coupler run`; connects to POROSPH_ENDPOINT (or --endpoint) and follows the protocol
// of proto/porosph.proto. Writes OUT/soil.h5.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>

#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"
#include "proto/solver_runtime.h"
#include "scene/scene_loader.h"
#include "soil_solver/soil_solver.h"

namespace {

constexpr const char* kSolverName = "porosph-soil";
constexpr const char* kSolverVersion = "0.1.0";

template <int D>
int run_dimension(porosph::coupling::CouplingClient& client, const porosph::scene::Scene& scene) {
  porosph::soil::SoilSolver<D> solver(scene);
  const auto writer = porosph::coupling::open_snapshot_writer(client.setup(), "soil.h5");
  return porosph::coupling::run_solver_loop(client, solver, *writer);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"PoroSPH soil solver (started by `coupler run`)"};
  std::string endpoint_arg;
  app.add_option("--endpoint", endpoint_arg, "coupler endpoint (default: $POROSPH_ENDPOINT)");
  app.set_version_flag("--version", kSolverVersion);
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<porosph::coupling::CouplingClient> client;
  try {
    const std::string endpoint = porosph::coupling::resolve_endpoint(endpoint_arg);
    client = std::make_unique<porosph::coupling::CouplingClient>(
        endpoint, porosph::coupling::SolverIdentity{"soil", kSolverName, kSolverVersion});
    const auto& setup = client->setup();
    const auto scene = porosph::scene::load_scene_text(setup.scene_toml, "<scene from coupler>");
    return scene.run.dimension == 3 ? run_dimension<3>(*client, scene)
                                    : run_dimension<2>(*client, scene);
  } catch (const porosph::coupling::CouplingError& e) {
    std::fprintf(stderr, "soil_solver: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soil_solver: %s\n", e.what());
    if (client) client->report_error(e.what(), 0, 0.0);
    return 1;
  }
}
