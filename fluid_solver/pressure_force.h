// Pressure gradient in the symmetric form of the seed paper eq. 3, first term (Monaghan 1992):
//   (dv_a/dt)_p = - sum_b m_b (p_a + p_b) / (rho_a rho_b) grad_a W_ab.
// Antisymmetric in a, b (grad_a W_ab = -grad_b W_ba), so it conserves linear momentum exactly.
#pragma once

#include "sph/vector.h"

namespace porosph::fluid {

/// Acceleration of a due to b from the pressure term of eq. 3; the densities enter as their
/// inverses 1/rho (computed once per particle and step: no division per pair).
template <int D>
inline sph::Vec<D> pressure_acceleration(double m_b, double p_a, double p_b, double inv_rho_a,
                                         double inv_rho_b, const sph::Vec<D>& grad_w) {
  return (-m_b * (p_a + p_b) * (inv_rho_a * inv_rho_b)) * grad_w;
}

}  // namespace porosph::fluid
