#include "coupler/observable_feedback.h"

#include <algorithm>
#include <cmath>

namespace porosph::coupler {
namespace {

/// The latest value of observable `name`, 0 when it is unknown or not finite.
double value_of(const std::map<std::string, double>& observables, const std::string& name) {
  const auto it = observables.find(name);
  return it != observables.end() && std::isfinite(it->second) ? it->second : 0.0;
}

}  // namespace

void wall_speeds_from(const scene::Scene& scene, const std::map<std::string, double>& observables,
                      std::vector<double>& speeds) {
  speeds.clear();
  const auto& walls = scene.walls;
  if (std::none_of(walls.begin(), walls.end(),
                   [](const scene::Shape& w) { return !w.moves_with.empty(); }))
    return;
  speeds.assign(walls.size(), 0.0);
  for (std::size_t i = 0; i < walls.size(); ++i)
    if (!walls[i].moves_with.empty()) speeds[i] = value_of(observables, walls[i].moves_with);
}

void load_forces_from(const scene::Scene& scene, const std::map<std::string, double>& observables,
                      std::vector<double>& forces) {
  forces.clear();
  if (!scene.soil) return;
  const auto& loads = scene.soil->loads;
  if (std::none_of(loads.begin(), loads.end(),
                   [](const scene::SoilLoad& l) { return !l.plus_force_from.empty(); }))
    return;
  forces.assign(loads.size(), 0.0);
  for (std::size_t i = 0; i < loads.size(); ++i)
    if (!loads[i].plus_force_from.empty())
      forces[i] = value_of(observables, loads[i].plus_force_from);
}

}  // namespace porosph::coupler
