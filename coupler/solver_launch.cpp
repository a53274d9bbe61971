#include "coupler/solver_launch.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace porosph::coupler {

SolverCommand resolve_solver_command(const std::string& phase, const std::string& command_line,
                                     const scene::Scene& scene) {
  SolverCommand c;
  c.requested = command_line;
  if (c.requested.empty())
    c.requested = phase == "water" ? scene.water->solver : scene.soil->solver;
  c.user_named = !c.requested.empty();
  if (!c.user_named) c.requested = phase == "water" ? "fluid_solver" : "soil_solver";
  std::istringstream words(c.requested);
  for (std::string word; words >> word;) c.args.push_back(word);
  if (c.args.empty()) throw std::invalid_argument("the " + phase + " solver command is empty");
  return c;
}

std::vector<std::pair<std::string, std::string>> solver_environment(const std::string& endpoint,
                                                                    unsigned solvers) {
  std::vector<std::pair<std::string, std::string>> env = {{"POROSPH_ENDPOINT", endpoint}};
  if (solvers > 1) {
    if (!std::getenv("OMP_WAIT_POLICY")) env.emplace_back("OMP_WAIT_POLICY", "PASSIVE");
    if (!std::getenv("OMP_NUM_THREADS")) {
      const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
      env.emplace_back("OMP_NUM_THREADS", std::to_string(std::max(1u, cores / solvers)));
    }
  }
  return env;
}

}  // namespace porosph::coupler
