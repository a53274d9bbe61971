// Stress-divergence term of the soil momentum equation, seed paper eq. 5 / 16:
//   (dv_i/dt)_stress = sum_j m_j (sigma_i + sigma_j) / (rho_i rho_j) . grad_i W_ij,
// sigma the (effective) stress, tension positive, so an isotropic compression sigma = -p delta
// gives the familiar pressure repulsion -m_j (p_i + p_j)/(rho_i rho_j) grad_i W_ij. The pair
// contributions are antisymmetric: m_i a_i(j) = -m_j a_j(i) since grad_j W_ji = -grad_i W_ij.
// In 2D only the in-plane block of the 3x3 stress acts.
#pragma once

#include <Eigen/Core>

#include "soil_solver/velocity_gradient.h"
#include "sph/vector.h"

namespace porosph::soil {

/// Acceleration of i due to j: m_j (sigma_i + sigma_j) / (rho_i rho_j) grad_i W_ij.
template <int D>
inline sph::Vec<D> stress_divergence_acceleration(double m_j, const Eigen::Matrix3d& sigma_i,
                                                  const Eigen::Matrix3d& sigma_j, double rho_i,
                                                  double rho_j, const sph::Vec<D>& grad_w_ij) {
  // The blocks first: only D x D additions (a 3x3 sum would be evaluated in full).
  return (m_j / (rho_i * rho_j)) *
         ((in_plane_block<D>(sigma_i) + in_plane_block<D>(sigma_j)) * grad_w_ij);
}

}  // namespace porosph::soil
