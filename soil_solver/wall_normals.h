// Outward normals of wall particles from the wall geometry, for the free-slip stress reflection of
// soil_walls.h. A wall particle probes the lattice along each axis direction (+-e_k, steps of dp)
// for the nearest point outside every wall shape: the open side of the wall. If exactly one
// direction is nearest, that is its normal (pointing away from the wall, into the space the soil
// may occupy). If directions along two different axes tie - the particle sits at a corner, where
// the mirror image of a point is its point reflection, which leaves a stress tensor unchanged - the
// normal is zero (no reflection). The two directions of one axis tying is the middle layer of a
// wall (an odd number of layers, open at the same distance on both faces): its normal is that
// axis (the first direction found; the reflection and the wall form of eq. 5 do not depend on the
// sign). Before 2026-12-06 (session 29) such a layer counted as a corner: the middle of the soil
// column's three-layer frictionless walls was not mirrored and passed the soil's shear on to the
// wall (docs/validation-studies.md, soil_column). If no direction opens within `reach` steps (a
// sloped wall whose open side is not along an axis) the normal is NaN: the caller then estimates it
// from the soil around the particle each step.
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
  int best = reach + 1, best_axis = -1;
  bool corner = false;  // nearest openings tie along two different axes
  sph::Vec<D> normal = sph::Vec<D>::Zero();
  for (int k = 0; k < D; ++k) {
    for (int sign : {-1, 1}) {
      for (int m = 1; m <= reach && m <= best; ++m) {
        const sph::Vec<D> p = x + (sign * m * dp) * sph::Vec<D>::Unit(k);
        if (inside_any(p)) continue;
        if (m < best) {
          best = m;
          best_axis = k;
          corner = false;
          normal = sign * sph::Vec<D>::Unit(k);
        } else if (k != best_axis) {
          corner = true;
        }  // else: the other side of the same axis at the same distance (a wall's middle layer)
        break;
      }
    }
  }
  if (best > reach) return sph::Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());
  return corner ? sph::Vec<D>::Zero() : normal;
}

}  // namespace porosph::soil
