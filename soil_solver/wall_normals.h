// Outward normals of wall particles from the wall geometry, for the free-slip stress reflection of
// soil_walls.h. A wall particle probes the lattice along each axis direction (+-e_k, steps of dp)
// for the nearest point outside every wall shape: the open side of the wall. If exactly one
// direction is nearest, that is its normal (pointing away from the wall, into the space the soil
// may occupy). If two or more tie - the particle sits at a corner, where the mirror image of a
// point is its point reflection, which leaves a stress tensor unchanged - the normal is zero
// (no reflection). If no direction opens within `reach` steps (a sloped wall whose open side is not
// along an axis) the normal is NaN: the caller then estimates it from the soil around the particle
// each step.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "scene/scene.h"
#include "sph/geometry.h"
#include "sph/vector.h"

namespace porosph::soil {

template <int D>
sph::Vec<D> wall_normal_from_geometry(const sph::Vec<D>& x, const std::vector<scene::Shape>& walls,
                                      double dp, int reach) {
  auto inside_any = [&](const sph::Vec<D>& p) {
    for (const auto& w : walls)
      if (sph::inside_shape<D>(w, p, dp)) return true;
    return false;
  };
  int best = reach + 1, ties = 0;
  sph::Vec<D> normal = sph::Vec<D>::Zero();
  for (int k = 0; k < D; ++k) {
    for (int sign : {-1, 1}) {
      for (int m = 1; m <= reach && m <= best; ++m) {
        const sph::Vec<D> p = x + (sign * m * dp) * sph::Vec<D>::Unit(k);
        if (inside_any(p)) continue;
        if (m < best) {
          best = m;
          ties = 1;
          normal = sign * sph::Vec<D>::Unit(k);
        } else {
          ++ties;
        }
        break;
      }
    }
  }
  if (best > reach) return sph::Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());
  return ties == 1 ? normal : sph::Vec<D>::Zero();
}

}  // namespace porosph::soil
