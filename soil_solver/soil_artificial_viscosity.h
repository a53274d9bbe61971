// Monaghan artificial viscosity between two soil particles (Monaghan 1992, Annu. Rev. Astron.
// Astrophys. 30, 543-574; Bui et al. 2008, eq. 41 there), the Pi_ij of seed paper eq. 16:
//   Pi_ij = (-alpha c_ij mu_ij + beta mu_ij^2) / rho_ij   if v_ij . x_ij < 0 (approaching), else 0,
//   mu_ij = h v_ij . x_ij / (r_ij^2 + 0.01 h^2),  c_ij = (c_i + c_j)/2,  rho_ij = (rho_i +
//   rho_j)/2,
// with v_ij = v_i - v_j, x_ij = x_i - x_j, alpha = beta = 0.1 for soil (docs/cases.md, Bui et al.
// 2008) and c the soil sound speed. Pi_ij >= 0.
//
// Sign: eq. 16 prints "+ Pi_ij delta" inside the stress sum, which with Pi_ij >= 0 would pull
// approaching particles together. We use the dissipative sign of Monaghan (1992) (the same as the
// water's eq. 17): a_i = -m_j Pi_ij grad_i W_ij, a repulsion between approaching particles that
// removes kinetic energy of relative motion and never adds it.
//
// Soil sound speed: c_s = sqrt(K / rho). docs/cases.md's convention passes the submerged density,
// c_s = sqrt(K / (rho_s - rho_w)).
#pragma once

#include <cmath>

#include "sph/vector.h"

namespace porosph::soil {

/// c = sqrt(K / rho).
inline double soil_sound_speed(double bulk_modulus, double density) {
  return std::sqrt(bulk_modulus / density);
}

struct SoilArtificialViscosity {
  double alpha = 0.1;  ///< linear (bulk) coefficient
  double beta = 0.1;   ///< quadratic (von Neumann-Richtmyer) coefficient
  double h = 0.0;      ///< smoothing length [m]

  /// Pi_ij from v_ij . x_ij, r_ij, the mean sound speed and the mean density of the pair.
  double pi(double v_dot_x, double r, double c_mean, double rho_mean) const {
    if (v_dot_x >= 0.0) return 0.0;
    const double mu = h * v_dot_x / (r * r + 0.01 * h * h);
    return (-alpha * c_mean * mu + beta * mu * mu) / rho_mean;
  }

  /// Acceleration of i due to j: -m_j Pi_ij grad_i W_ij; r_ij = |x_ij| (the pair's stored
  /// distance: no square root per pair).
  template <int D>
  sph::Vec<D> acceleration(double m_j, const sph::Vec<D>& v_ij, const sph::Vec<D>& x_ij,
                           double r_ij, double c_i, double c_j, double rho_i, double rho_j,
                           const sph::Vec<D>& grad_w_ij) const {
    const double p = pi(v_ij.dot(x_ij), r_ij, 0.5 * (c_i + c_j), 0.5 * (rho_i + rho_j));
    return (-m_j * p) * grad_w_ij;
  }
};

}  // namespace porosph::soil
