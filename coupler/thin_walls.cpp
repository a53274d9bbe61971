#include "coupler/thin_walls.h"

#include <sstream>

#include "scene/thin_walls.h"

namespace porosph::coupler {

std::vector<std::string> thin_wall_warnings(const scene::Scene& scene) {
  std::vector<std::string> warnings;
  if (!scene.has_water()) return warnings;
  const bool separating = scene.water->thin_walls == "separating";
  const double dp = scene.run.dp;
  const int needed = scene::separating_wall_layers(scene.h(), dp);
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    const scene::Shape& wall = scene.walls[w];
    if (separating && wall.moves_with.empty()) continue;  // filled on both sides
    const int axis = scene::thin_wall_axis(scene, wall, "water");
    if (axis < 0) continue;
    const long layers = scene::lattice_count(wall.min[axis], wall.max[axis], dp);  // as filled
    std::ostringstream text;
    text << "walls[" << w << "]" << (wall.label.empty() ? "" : " '" + wall.label + "'");
    if (wall.source_line > 0) text << " (line " << wall.source_line << ")";
    text << " is " << layers << " particle layer" << (layers == 1 ? "" : "s") << " thick along "
         << "xyz"[axis] << " at dp = " << dp << " m; a wall between two bodies of water needs "
         << needed << " at h = " << scene.run.h_factor
         << " dp, else (water.thin_walls = \"shared\", or a wall that moves) the water on its "
            "two sides interacts through it and, under a head difference, passes through it "
            "(docs/water-in-soil.md, "
            "section 2): use water.thin_walls = \"separating\", refine dp or thicken the wall";
    warnings.push_back(text.str());
  }
  return warnings;
}

}  // namespace porosph::coupler
