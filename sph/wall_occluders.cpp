#include "sph/wall_occluders.h"

#include <algorithm>
#include <cmath>

#include "sph/geometry.h"

namespace porosph::sph {

template <int D>
WallOccluder<D> occluder_of(const scene::Shape& wall, int axis) {
  WallOccluder<D> o;
  o.axis = axis;
  o.plane = 0.5 * (wall.min[axis] + wall.max[axis]);
  for (int k = 0; k < D; ++k) o.lo[k] = wall.min[k], o.hi[k] = wall.max[k];
  return o;
}

template <int D>
WallOccluder<D> thin_wall_occluder(const scene::Shape& wall, int axis,
                                   const std::vector<scene::Shape>& walls, double h, double dp) {
  WallOccluder<D> o = occluder_of<D>(wall, axis);
  o.reach =
      static_cast<double>(std::max<long>(scene::lattice_count(wall.min[axis], wall.max[axis], dp),
                                         scene::separating_wall_layers(h, dp) / 2)) *
      dp;
  Vec<D> centre = 0.5 * (o.lo + o.hi);
  centre[axis] = o.plane;
  for (int k = 0; k < D; ++k) {
    if (k == axis) continue;
    for (int end : {-1, 1}) {
      Vec<D> beyond = centre;  // half a spacing past this end, on the mid-plane
      beyond[k] = end < 0 ? o.lo[k] - 0.5 * dp : o.hi[k] + 0.5 * dp;
      bool meets = false;
      for (const scene::Shape& other : walls) {
        const bool same = other.kind == wall.kind && other.min == wall.min && other.max == wall.max;
        meets = meets || (!same && inside_shape<D>(other, beyond, dp));
      }
      if (!meets) continue;
      if (end < 0) {
        o.lo[k] -= 2.0 * h;
      } else {
        o.hi[k] += 2.0 * h;
      }
    }
  }
  return o;
}

template <int D>
ThinWallSet<D> thin_walls_of(const scene::Scene& scene, const std::vector<scene::Shape>& walls,
                             const std::string& phase, bool separating) {
  ThinWallSet<D> set;
  set.occluder_of_wall.assign(walls.size(), -1);
  set.axis_of_wall.assign(walls.size(), -1);
  if (!separating) return set;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    const scene::Shape& wall = walls[j];
    if (!wall.moves_with.empty()) continue;
    const int axis = scene::thin_wall_axis(scene, wall, phase);
    if (axis < 0) continue;
    set.axis_of_wall[j] = axis;
    set.occluder_of_wall[j] =
        set.occluders.add(thin_wall_occluder<D>(wall, axis, walls, scene.h(), scene.run.dp));
  }
  return set;
}

template <int D>
void two_sided_wall_fill(const scene::Shape& wall, int axis, int k, double h, double dp,
                         std::vector<Vec<D>>& points, std::vector<std::int32_t>& tags) {
  const long layers = lattice_count(wall.min[axis], wall.max[axis], dp);
  const long per_side = std::max<long>(layers, scene::separating_wall_layers(h, dp) / 2);
  for (int side : {-1, 1}) {
    scene::Shape half = wall;  // per_side layers from this side's face inwards
    if (side < 0) {
      half.max[axis] = wall.min[axis] + static_cast<double>(per_side) * dp;
    } else {
      half.min[axis] = wall.max[axis] - static_cast<double>(per_side) * dp;
    }
    for (const Vec<D>& x : fill_shape<D>(half, dp)) {
      points.push_back(x);
      tags.push_back(wall_side_tag(k, side));
    }
  }
}

template <int D>
void ThinWallSet<D>::fill(std::size_t j, const scene::Shape& wall, double h, double dp,
                          std::vector<Vec<D>>& points, std::vector<std::int32_t>& tags) const {
  points.clear(), tags.clear();
  if (occluder_of_wall[j] >= 0) {
    two_sided_wall_fill<D>(wall, axis_of_wall[j], occluder_of_wall[j], h, dp, points, tags);
  } else {
    points = fill_shape<D>(wall, dp);
    tags.assign(points.size(), 0);
  }
}

#define POROSPH_INSTANTIATE(D)                                                                    \
  template WallOccluder<D> occluder_of<D>(const scene::Shape&, int);                              \
  template WallOccluder<D> thin_wall_occluder<D>(                                                 \
      const scene::Shape&, int, const std::vector<scene::Shape>&, double, double);                \
  template ThinWallSet<D> thin_walls_of<D>(const scene::Scene&, const std::vector<scene::Shape>&, \
                                           const std::string&, bool);                             \
  template void two_sided_wall_fill<D>(const scene::Shape&, int, int, double, double,             \
                                       std::vector<Vec<D>>&, std::vector<std::int32_t>&);
POROSPH_INSTANTIATE(2)
POROSPH_INSTANTIATE(3)
template struct ThinWallSet<2>;
template struct ThinWallSet<3>;
#undef POROSPH_INSTANTIATE

}  // namespace porosph::sph
