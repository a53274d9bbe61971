#include "scene/thin_walls.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace porosph::scene {

long lattice_count(double min, double max, double dp) {
  constexpr double kTolerance = 1e-9;  // relative to dp
  if (!(max > min) || !(dp > 0)) return 0;
  return std::max(0L, static_cast<long>(std::ceil((max - min) / dp - 0.5 - kTolerance)));
}

int separating_wall_layers(double h, double dp) {
  const int m = static_cast<int>(std::ceil(2.0 * h / dp - 1e-9)) - 1;
  return 2 * m;
}

namespace {

/// The bounding box of a block (box: its corners; polygon: its vertices' range).
void bounds(const Shape& s, std::vector<double>& lo, std::vector<double>& hi) {
  if (s.kind != Shape::Kind::Polygon) {
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

/// True if one of `blocks` lies within `reach` of the wall's face on side `side` (-1: below min,
/// +1: above max) along `axis`, overlapping the wall's span across it.
bool block_beside(const std::vector<Shape>& blocks, const Shape& wall, std::size_t axis, int side,
                  double reach) {
  const double face = side < 0 ? wall.min[axis] : wall.max[axis];
  const double slab_lo = side < 0 ? face - reach : face, slab_hi = side < 0 ? face : face + reach;
  std::vector<double> lo, hi;
  for (const Shape& block : blocks) {
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

int thin_wall_axis(const Scene& scene, const Shape& wall, const std::string& phase) {
  const bool water = phase == "water";
  if ((water ? !scene.has_water() : !scene.has_soil()) || wall.kind != Shape::Kind::Box) return -1;
  bool acts = wall.phases.empty();
  for (const std::string& p : wall.phases) acts = acts || p == phase;
  if (!acts) return -1;
  const std::vector<Shape>& blocks = water ? scene.water->blocks : scene.soil->blocks;
  const double dp = scene.run.dp, reach = 2.0 * scene.h();
  const int needed = separating_wall_layers(scene.h(), dp);
  for (std::size_t axis = 0; axis < wall.min.size() && axis < wall.max.size(); ++axis) {
    if (lattice_count(wall.min[axis], wall.max[axis], dp) >= needed) continue;  // as filled
    // A wall with the phase on one side only (a floor, a lid, an end wall) needs fewer layers.
    if (block_beside(blocks, wall, axis, -1, reach) && block_beside(blocks, wall, axis, +1, reach))
      return static_cast<int>(axis);
  }
  return -1;
}

bool has_thin_walls(const Scene& scene, const std::string& phase) {
  for (const Shape& wall : scene.walls)
    if (wall.moves_with.empty() && thin_wall_axis(scene, wall, phase) >= 0) return true;
  return false;
}

}  // namespace porosph::scene
