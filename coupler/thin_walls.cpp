#include "coupler/thin_walls.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sph/geometry.h"

namespace porosph::coupler {

int separating_wall_layers(double h, double dp) {
  const int m = static_cast<int>(std::ceil(2.0 * h / dp - 1e-9)) - 1;
  return 2 * m;
}

namespace {

/// The bounding box of a block (box: its corners; polygon: its vertices' range).
void bounds(const scene::Shape& s, std::vector<double>& lo, std::vector<double>& hi) {
  if (s.kind != scene::Shape::Kind::Polygon) {
    lo = s.min, hi = s.max;
    return;
  }
  lo.assign(2, 1e300), hi.assign(2, -1e300);
  for (const auto& v : s.vertices) {
    for (std::size_t k = 0; k < 2 && k < v.size(); ++k) {
      lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
  }
}

/// True if a water block lies within `reach` of the wall's face on side `side` (-1: below min,
/// +1: above max) along `axis`, overlapping the wall's span across it.
bool water_beside(const scene::Scene& scene, const scene::Shape& wall, std::size_t axis, int side,
                  double reach) {
  const double face = side < 0 ? wall.min[axis] : wall.max[axis];
  const double slab_lo = side < 0 ? face - reach : face, slab_hi = side < 0 ? face : face + reach;
  std::vector<double> lo, hi;
  for (const scene::Shape& block : scene.water->blocks) {
    bounds(block, lo, hi);
    if (lo.size() < wall.min.size() || hi.size() < wall.max.size()) continue;
    bool overlaps = lo[axis] < slab_hi && hi[axis] > slab_lo;
    for (std::size_t k = 0; k < wall.min.size() && overlaps; ++k) {
      if (k != axis) overlaps = lo[k] < wall.max[k] && hi[k] > wall.min[k];
    }
    if (overlaps) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> thin_wall_warnings(const scene::Scene& scene) {
  std::vector<std::string> warnings;
  if (!scene.has_water()) return warnings;
  const double dp = scene.run.dp;
  const int needed = separating_wall_layers(scene.h(), dp);
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    const scene::Shape& wall = scene.walls[w];
    if (wall.kind != scene::Shape::Kind::Box) continue;  // containers: water on one side only
    bool on_water = wall.phases.empty();
    for (const std::string& phase : wall.phases) on_water = on_water || phase == "water";
    if (!on_water) continue;
    for (std::size_t axis = 0; axis < wall.min.size() && axis < wall.max.size(); ++axis) {
      const long layers = sph::lattice_count(wall.min[axis], wall.max[axis], dp);  // as filled
      if (layers >= needed) continue;
      // A wall with water on one side only (a floor, a lid, an end wall) needs fewer layers.
      if (!water_beside(scene, wall, axis, -1, 2.0 * scene.h()) ||
          !water_beside(scene, wall, axis, +1, 2.0 * scene.h()))
        continue;
      std::ostringstream text;
      text << "walls[" << w << "]" << (wall.label.empty() ? "" : " '" + wall.label + "'");
      if (wall.source_line > 0) text << " (line " << wall.source_line << ")";
      text << " is " << layers << " particle layer" << (layers == 1 ? "" : "s") << " thick along "
           << "xyz"[axis] << " at dp = " << dp << " m; a wall between two bodies of water needs "
           << needed << " at h = " << scene.run.h_factor
           << " dp, else the water on its two sides interacts through it and, under a head "
              "difference, passes through it (docs/water-in-soil.md, section 2): refine dp or "
              "thicken the wall";
      warnings.push_back(text.str());
      break;
    }
  }
  return warnings;
}

}  // namespace porosph::coupler
