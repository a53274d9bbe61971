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

/// Acceleration of a free soil particle i due to a fixed (wall) particle w with unit normal n:
///   m_w / (rho_i rho_w) [(sigma_i + sigma_w) . (gW)_n + (sigma_w - sigma_i) . (gW)_t],
/// gW = grad_i W_iw,
/// (.)_n = (. n) n the part along the wall's unit normal n, (.)_t the rest (along its plane).
/// The normal part is eq. 5's symmetric form: its zeroth-order term 2 sigma_i sum_w (grad W)_n is
/// how a wall carries a load (a floor holds a column's weight through it). The tangential part of
/// that zeroth-order term, 2 sigma_i sum_w (grad W)_t, vanishes for a wall whose lattice is in
/// registry with the soil's, as it does in the continuum for any half-space of wall, but not once
/// the soil has slid along the wall by a fraction o of a spacing: then it is sigma_i / dp times a
/// lattice ripple that grows with o / dp, a force along the wall of order weight x settlement /
/// dp. Used only where every fixed neighbour of i lies inside one straight wall
/// (sees_one_straight_wall, straight_walls.h): near a corner or a wall's end (the end face of a
/// sheet pile) the walls' tangential sum is a real force, and the symmetric form is kept there. In
/// a column settling between frictionless walls it hung 0.32 / 0.56 % of the weight on the walls at
/// dp 10 / 5 mm (docs/validation-studies.md, soil_column). The difference form along the plane
/// keeps the walls' share of the stress divergence (exact for a linear stress field) without that
/// term. Reference: the zeroth-order consistency of SPH gradients, Bonet & Lok (1999) eq. 21;
/// Adami, Hu & Adams (2012) for the wall's extrapolated stress.
template <int D>
inline sph::Vec<D> wall_stress_divergence_acceleration(double m_w, const Eigen::Matrix3d& sigma_i,
                                                       const Eigen::Matrix3d& sigma_w, double rho_i,
                                                       double rho_w, const sph::Vec<D>& grad_w_iw,
                                                       const sph::Vec<D>& wall_normal) {
  const sph::Vec<D> grad_normal = grad_w_iw.dot(wall_normal) * wall_normal;
  const sph::Vec<D> grad_plane = grad_w_iw - grad_normal;
  const MatD<D> s_i = in_plane_block<D>(sigma_i), s_w = in_plane_block<D>(sigma_w);
  return (m_w / (rho_i * rho_w)) * ((s_i + s_w) * grad_normal + (s_w - s_i) * grad_plane);
}

}  // namespace porosph::soil
