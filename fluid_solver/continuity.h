// Continuity equation, seed paper eq. 2 (Monaghan 1992; Liu & Liu 2003):
//   drho_a/dt = rho_a sum_b (m_b / rho_b) v_ab . grad_a W_ab,   v_ab = v_a - v_b.
#pragma once

#include "sph/vector.h"

namespace porosph::water {

/// Contribution of neighbour b to the sum of eq. 2: V_b v_ab . grad_a W_ab with the volume
/// V_b = m_b / rho_b (computed once per particle and step, not per pair). The caller multiplies
/// the sum by rho_a.
template <int D>
inline double continuity_term(double volume_b, const sph::Vec<D>& v_ab, const sph::Vec<D>& grad_w) {
  return volume_b * v_ab.dot(grad_w);
}

}  // namespace porosph::water
