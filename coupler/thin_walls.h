// Walls too thin to separate two bodies of water (docs/water-in-soil.md, section 2): a wall of L
// particle layers keeps the water on its two sides apart by itself only for L >= 2m,
// m = ceil(2h / dp) - 1 (4 layers at h = 1.2 dp). With water.thin_walls = "separating" (the
// default) such a wall is filled once per side and hides the pairs across it
// (sph/wall_occluders.h); with "shared" its particles carry one side's pressure to the other and,
// under a head difference, let water through (the hydraulic heave's 1 cm sheet pile at dp 10 mm
// let nine tenths of the upstream pool's loss through it, docs/validation-studies.md).
// `coupler check` and `coupler run` print these warnings.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

/// With water.thin_walls = "shared" (with "separating": for moving walls only, which are never
/// filled on both sides): one warning per box wall acting on water that is thinner
/// than scene::separating_wall_layers() along an axis with water within 2h of both its faces
/// (scene::thin_wall_axis), naming the wall (index, label, scene line), its layers, the axis and
/// the remedy.
std::vector<std::string> thin_wall_warnings(const scene::Scene& scene);

}  // namespace porosph::coupler
