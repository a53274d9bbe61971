// The Monaghan artificial viscosity at a no-slip wall, on the wall-normal approach only.
//
// Between a water particle a and a wall particle w the Monaghan term (Monaghan 1992) acts on the
// velocity v_aw = v_a - v~_w (Adami et al. 2012, the mirrored no-slip velocity). With the whole
// v_aw it is also a wall friction of kinematic viscosity about alpha h c0 / 8, hundreds of times
// water's, that shrinks with h: a flow along a wall then does not converge under refinement (the
// dam break's front, docs/validation-studies.md). Its normal part is what keeps the water off a
// wall it approaches fast (a particle in the corner of a one-layer wall crosses it without).
// PoroSPH therefore gives the term the normal component only,
//   v_aw -> n_a (n_a . v_aw),   n_a = s_a / |s_a|,   s_a = sum_w V_w grad_a W_aw,
// the line of the gradient of the wall's kernel sum at a (normal to a straight wall; the bisector
// at a corner). Sliding along a wall then feels no artificial viscosity; the no-slip shear comes
// from water's viscous term alone. `water.artificial_viscosity_at_walls` (docs/terms.md).
#pragma once

#include <cstdint>

#include "sph/neighbour_list.h"
#include "sph/vector.h"

namespace porosph::water {

/// How the Monaghan term acts between water and no-slip wall particles.
enum class WallArtificialViscosity {
  none,    ///< not at all: the Morris term alone
  normal,  ///< on the wall-normal approach only (the default)
  full,    ///< on the whole velocity difference (a wall friction that shrinks with h)
};

/// n_a of particle a: the unit line of sum_w V_w grad_a W_aw over its wall neighbours (those of
/// neighbours.mid(a) .. end(a)); zero without wall neighbours.
template <int D, class Kernel>
sph::Vec<D> wall_normal_of(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                           const double* volume, std::int64_t a) {
  sph::Vec<D> sum = sph::Vec<D>::Zero();
  for (auto it = neighbours.mid(a); it != neighbours.end(a); ++it)
    sum += (volume[it->b] * kernel.grad_factor(it->r)) * it->x_ab;
  const double length = sum.norm();
  return length > 0.0 ? sph::Vec<D>(sum / length) : sph::Vec<D>::Zero();
}

/// The velocity difference the Monaghan term acts on at a wall pair.
template <int D>
sph::Vec<D> wall_damped_velocity(WallArtificialViscosity mode, const sph::Vec<D>& wall_normal,
                                 const sph::Vec<D>& v_aw) {
  if (mode == WallArtificialViscosity::normal) return wall_normal * wall_normal.dot(v_aw);
  return v_aw;
}

}  // namespace porosph::water
