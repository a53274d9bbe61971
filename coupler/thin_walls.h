// Walls too thin to separate two bodies of water (docs/water-in-soil.md, section 2): a wall of L
// particle layers keeps the water on its two sides apart only for L >= 2m, m = ceil(2h / dp) - 1
// (4 layers at h = 1.2 dp). A thinner wall shares its particles' pressure between the two sides,
// and under a head difference water passes through it: the hydraulic heave's 1 cm sheet pile at
// dp 10 mm (one layer) let nine tenths of the upstream pool's loss through it
// (docs/validation-studies.md). `coupler check` and `coupler run` print these warnings.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

/// The fewest particle layers a wall between two bodies of water needs at this h and dp: 2m.
int separating_wall_layers(double h, double dp);

/// One warning per box wall acting on water that is thinner than separating_wall_layers() along
/// an axis with water blocks within 2h of both its faces there (over its span across the axis),
/// naming the wall (index, label, scene line), its layers, the axis and the remedy.
std::vector<std::string> thin_wall_warnings(const scene::Scene& scene);

}  // namespace porosph::coupler
