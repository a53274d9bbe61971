// Which wall particles lie inside a straight stretch of wall, for the wall form of eq. 5
// (wall_stress_divergence_acceleration, stress_divergence.h). That form drops the walls' sum along
// the wall's plane, sum_w grad W . t, which is a lattice ripple where the wall runs on past the
// kernel's reach on both sides, and a real force where it ends: the end face of a sheet pile
// pushes the soil beneath it through that sum. So a wall particle counts as interior when the
// lattice sites at m dp (m = 1 .. reach) on both sides of it, along every axis of its plane, hold
// wall particles whose normal lies on the same axis and that leave the run at the same time
// (remove_at: a gate next to a wall is not a continuation of it). Normals are the axis-aligned
// geometric ones of wall_normals.h (or a thin wall's side); a particle with a zero (corner) or
// non-finite (sloped wall, fixed soil) normal is never interior. Periodic axes wrap.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "sph/domain_box.h"
#include "sph/vector.h"

namespace porosph::soil {

/// The axis a normal lies on, or -1 when it is zero, non-finite or not along an axis.
template <int D>
inline int normal_axis(const sph::Vec<D>& n) {
  if (!n.allFinite()) return -1;
  int axis = -1;
  for (int k = 0; k < D; ++k) {
    if (n[k] == 0.0) continue;
    if (axis >= 0) return -1;
    axis = k;
  }
  return axis;
}

/// 1 for each fixed particle [n_free, size) inside a straight stretch of wall (see above), 0 for
/// the others and for the free particles. `reach` = lattice steps the kernel reaches (ceil(2h/dp)).
template <int D>
std::vector<std::uint8_t> straight_wall_interior(const std::vector<sph::Vec<D>>& position,
                                                 const std::vector<sph::Vec<D>>& normal,
                                                 const std::vector<double>& remove_at,
                                                 std::size_t n_free, double dp, int reach,
                                                 const sph::DomainBox<D>& box) {
  // Sites on a half-dp lattice, so that walls offset by half a spacing from each other stay apart.
  using Key = std::array<long long, D>;
  auto key = [&](sph::Vec<D> x) {
    box.wrap(x);
    Key k;
    for (int d = 0; d < D; ++d) k[d] = std::llround(2.0 * x[d] / dp);
    return k;
  };
  struct Site {
    int axis;
    double remove_at;
  };
  std::multimap<Key, Site> sites;  // set-up only: a few thousand sites
  const std::size_t n = position.size();
  for (std::size_t w = n_free; w < n; ++w) {
    const int axis = normal_axis<D>(normal[w]);
    if (axis >= 0) sites.insert({key(position[w]), Site{axis, remove_at[w]}});
  }
  auto continues_at = [&](const sph::Vec<D>& x, int axis, double removal) {
    auto [first, last] = sites.equal_range(key(x));
    for (auto it = first; it != last; ++it)
      if (it->second.axis == axis && it->second.remove_at == removal) return true;
    return false;
  };
  std::vector<std::uint8_t> interior(n, 0);
  for (std::size_t w = n_free; w < n; ++w) {
    const int axis = normal_axis<D>(normal[w]);
    if (axis < 0) continue;
    bool inside = true;
    for (int t = 0; t < D && inside; ++t) {
      if (t == axis) continue;
      for (int m = 1; m <= reach && inside; ++m) {
        const sph::Vec<D> step = (m * dp) * sph::Vec<D>::Unit(t);
        inside = continues_at(position[w] + step, axis, remove_at[w]) &&
                 continues_at(position[w] - step, axis, remove_at[w]);
      }
    }
    interior[w] = inside ? 1 : 0;
  }
  return interior;
}

/// True when every fixed neighbour of free particle i (the list's [mid, end) range) lies inside a
/// straight stretch of wall (`straight_wall` above, whose normals are axis-aligned) with its normal
/// on one axis (one wall, or the two faces of a thin one); `unit_normal` is then that axis. False
/// without fixed neighbours, or near a corner, a wall's end, a sloped wall or two walls at an
/// angle.
template <int D, class NeighbourList>
inline bool sees_one_straight_wall(const NeighbourList& nl, std::int64_t i,
                                   const std::vector<sph::Vec<D>>& wall_normals,
                                   const std::vector<std::uint8_t>& straight_wall,
                                   sph::Vec<D>& unit_normal) {
  int axis = -1;
  for (auto it = nl.mid(i); it != nl.end(i); ++it) {
    if (!straight_wall[it->b]) return false;
    const int a = normal_axis<D>(wall_normals[it->b]);
    if (a < 0 || (axis >= 0 && a != axis)) return false;
    axis = a;
  }
  if (axis < 0) return false;
  unit_normal = sph::Vec<D>::Unit(axis);
  return true;
}

}  // namespace porosph::soil
