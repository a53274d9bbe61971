// Artificial viscosity of Monaghan (1992), Annu. Rev. Astron. Astrophys. 30, 543-574, eq. 4.1
// there:
//   (dv_a/dt)_av = - sum_b m_b Pi_ab grad_a W_ab,
//   Pi_ab = (-alpha c_ab mu_ab + beta mu_ab^2) / rho_ab   if v_ab . x_ab < 0 (approaching), else 0,
//   mu_ab = h v_ab . x_ab / (r_ab^2 + eta^2),  c_ab = (c_a + c_b)/2,  rho_ab = (rho_a + rho_b)/2,
// eta^2 = 0.01 h^2. Pi_ab >= 0, so the force pushes approaching particles apart and is zero for
// receding ones: purely dissipative.
#pragma once

#include "sph/vector.h"

namespace porosph::fluid {

struct ArtificialViscosity {
  double alpha = 0.05, beta = 0.0, h = 0.0;

  /// Pi_ab from v_ab . x_ab, 1 / (r_ab^2 + eta^2) (shared with the other regularised terms of
  /// the pair), the mean sound speed and the mean density of the pair.
  double pi(double v_dot_x, double inv_r2_eta2, double c_mean, double rho_mean) const {
    if (v_dot_x >= 0.0) return 0.0;
    const double mu = h * v_dot_x * inv_r2_eta2;
    return (-alpha * c_mean * mu + beta * mu * mu) / rho_mean;
  }

  /// Acceleration of a due to b.
  template <int D>
  sph::Vec<D> acceleration(double m_b, const sph::Vec<D>& v_ab, const sph::Vec<D>& x_ab,
                           double inv_r2_eta2, double c_a, double c_b, double rho_a, double rho_b,
                           const sph::Vec<D>& grad_w) const {
    const double p = pi(v_ab.dot(x_ab), inv_r2_eta2, 0.5 * (c_a + c_b), 0.5 * (rho_a + rho_b));
    return (-m_b * p) * grad_w;
  }
};

}  // namespace porosph::fluid
