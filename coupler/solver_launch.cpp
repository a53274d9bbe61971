#include "coupler/solver_launch.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "coupler/phase_slots.h"
#include "proto/coupling_client.h"

namespace porosph::coupler {

SolverCommand resolve_solver_command(const std::string& phase, const std::string& command_line,
                                     const scene::Scene& scene) {
  SolverCommand c;
  c.requested = command_line;
  if (c.requested.empty()) c.requested = scene_solver_command(scene, phase);
  c.user_named = !c.requested.empty();
  if (!c.user_named) c.requested = phase_slot(phase).builtin_solver;
  std::istringstream words(c.requested);
  for (std::string word; words >> word;) c.args.push_back(word);
  if (c.args.empty()) throw std::invalid_argument("the " + phase + " solver command is empty");
  return c;
}

std::vector<std::pair<std::string, std::string>> solver_environment(const std::string& endpoint,
                                                                    const std::string& run_token,
                                                                    unsigned solvers) {
  std::vector<std::pair<std::string, std::string>> env = {{"POROSPH_ENDPOINT", endpoint},
                                                          {coupling::kRunTokenVariable, run_token}};
  if (solvers > 1) {
    if (!std::getenv("OMP_WAIT_POLICY")) env.emplace_back("OMP_WAIT_POLICY", "PASSIVE");
    if (!std::getenv("OMP_NUM_THREADS")) {
      const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
      env.emplace_back("OMP_NUM_THREADS", std::to_string(std::max(1u, cores / solvers)));
    }
  }
  return env;
}

std::size_t max_frame_bytes(const scene::Scene& scene) {
  const std::size_t dimension = static_cast<std::size_t>(std::max(1, scene.run.dimension));
  std::vector<double> low = scene.domain.min, high = scene.domain.max;
  low.resize(dimension, 0.0);
  high.resize(dimension, 0.0);
  const auto include = [&](const std::vector<double>& point, double grow) {
    for (std::size_t axis = 0; axis < dimension && axis < point.size(); ++axis) {
      low[axis] = std::min(low[axis], point[axis] - grow);
      high[axis] = std::max(high[axis], point[axis] + grow);
    }
  };
  for (const scene::Shape& wall : scene.walls) {
    const double thickness = wall.layers * scene.run.dp;
    include(wall.min, thickness);
    include(wall.max, thickness);
    for (const auto& vertex : wall.vertices) include(vertex, thickness);
  }
  double particles = 2.0;  // twice the lattice: compaction, packings denser than the lattice
  for (std::size_t axis = 0; axis < dimension; ++axis) {
    particles *= std::max(0.0, high[axis] - low[axis]) / scene.run.dp + 17.0;  // + 8 dp a side
  }
  // Per particle: id and material (varints, up to 10 bytes each), position, velocity, update
  // base and rate (D doubles each), density, mass, porosity.
  const double per_particle = 20.0 + 8.0 * (4.0 * static_cast<double>(dimension) + 3.0);
  const double bytes = particles * per_particle + double(1 << 20);  // + diagnostics, messages
  constexpr double kMost = double((1ULL << 31) - 1);                // what Protobuf parses
  return static_cast<std::size_t>(std::min(std::isfinite(bytes) ? bytes : kMost, kMost));
}

std::unique_ptr<SolverHub> open_solver_hub(const std::string& endpoint, const scene::Scene& scene,
                                           std::unique_ptr<PrivateSocketDir>& socket_dir) {
  if (!endpoint.empty()) return std::make_unique<SolverHub>(endpoint, max_frame_bytes(scene));
  socket_dir = std::make_unique<PrivateSocketDir>();
  return std::make_unique<SolverHub>(socket_dir->endpoint(), max_frame_bytes(scene));
}

std::string attach_instructions(const std::vector<std::string>& phases, const std::string& endpoint,
                                const std::string& run_token, bool everywhere) {
  std::string names;
  for (const std::string& phase : phases) names += (names.empty() ? "" : ", ") + phase;
  std::string text = "coupler: waiting for solvers (" + names + ") at " + endpoint + "\n" +
                     "coupler: start each with POROSPH_ENDPOINT=" + endpoint +
                     " and POROSPH_RUN_TOKEN=" + run_token + " in its environment (or --endpoint " +
                     endpoint + "); messages without this token are dropped\n";
  if (everywhere) {
    text +=
        "coupler: listening on every network interface: anyone who can reach this machine can "
        "connect, and only the token keeps them out; name one address (tcp://ADDRESS:PORT) to "
        "listen there only\n";
  }
  return text;
}

}  // namespace porosph::coupler
