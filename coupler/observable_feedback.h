// What the coupler feeds back from the observables to the solvers each step (docs/scene.md):
// the speed of every wall that moves with an observable (walls[].moves_with;
// StepCommand.wall_speed) and the force added to every load from one (soil.loads[].plus_force_from;
// StepCommand.load_force). Together they make a rigid soil plate and the water's lid one body
// (docs/verification.md, "Mandel's problem"). A value that is NaN (nothing left to measure) counts
// as 0.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

/// One speed per scene wall, the latest value of the observable it moves with (0 for a fixed
/// wall); empty when no wall moves.
void wall_speeds_from(const scene::Scene& scene, const std::map<std::string, double>& observables,
                      std::vector<double>& speeds);

/// One force per soil load, the latest value of its plus_force_from observable (0 without one);
/// empty when no load takes one.
void load_forces_from(const scene::Scene& scene, const std::map<std::string, double>& observables,
                      std::vector<double>& forces);

}  // namespace porosph::coupler
