// Laminar viscosity of Morris, Fox & Zhu (1997), J. Comput. Phys. 136, 214-226, eq. 8 there; the
// second term of the seed paper eq. 3:
//   (dv_a/dt)_visc = sum_b m_b (mu_a + mu_b) / (rho_a rho_b) (1/r_ab dW/dr) v_ab,
// with the regularised factor (1/r dW/dr) -> x_ab . grad_a W_ab / (r_ab^2 + eta^2), eta^2 = 0.01
// h^2, which is finite when r_ab -> 0 and equal to (1/r) dW/dr for r >> eta. Since dW/dr <= 0 the
// term opposes v_ab: it is dissipative.
#pragma once

#include "sph/vector.h"

namespace porosph::water {

/// x_ab . grad_a W_ab / (r_ab^2 + eta^2) from x_ab . grad_a W_ab and 1 / (r_ab^2 + eta^2): the
/// regularised (1/r) dW/dr shared by the Morris term and the density diffusion (one division per
/// pair for both).
inline double regularised_gradient_factor(double x_dot_grad_w, double inv_r2_eta2) {
  return x_dot_grad_w * inv_r2_eta2;
}

/// Acceleration of a due to b from the Morris term; `factor` = regularised_gradient_factor(),
/// the densities as their inverses.
template <int D>
inline sph::Vec<D> morris_viscous_acceleration(double m_b, double mu_a, double mu_b,
                                               double inv_rho_a, double inv_rho_b, double factor,
                                               const sph::Vec<D>& v_ab) {
  return (m_b * (mu_a + mu_b) * (inv_rho_a * inv_rho_b) * factor) * v_ab;
}

}  // namespace porosph::water
