// Velocity gradient, strain rate and spin of a soil particle, seed paper eq. 7-8.
//
// The SPH estimate of the velocity gradient of particle i is
//   L_i^{ab} = (dv^a/dx^b)_i = sum_j (m_j / rho_j) (v_j^a - v_i^a) dW_ij/dx_i^b,
// accumulated one neighbour j at a time with accumulate_velocity_gradient (the neighbour loop is
// the solver's). From L (embedded into 3x3, zero out-of-plane row and column in 2D: plane strain,
// v_z = 0 and nothing varies along z):
//   strain rate  eps_dot = (L + L^T) / 2                          (eq. 7)
//   spin         omega   = (L - L^T) / 2,  omega^{ab} = (dv^a/dx^b - dv^b/dx^a) / 2   (eq. 8)
// Both eq. 7 and eq. 8 are exactly these symmetric / antisymmetric parts of the one sum L.
#pragma once

#include <Eigen/Core>

#include "sph/vector.h"

namespace porosph::soil {

/// D x D matrix (velocity gradients, in-plane blocks).
template <int D>
using MatD = Eigen::Matrix<double, D, D>;

/// Adds neighbour j's contribution to the velocity gradient of i:
///   L += (m_j / rho_j) v_ji (x) grad_i W_ij,  v_ji = v_j - v_i,  grad_i W_ij = dW_ij/dx_i.
template <int D>
inline void accumulate_velocity_gradient(MatD<D>& velocity_gradient, double volume_j,
                                         const sph::Vec<D>& v_ji, const sph::Vec<D>& grad_w_ij) {
  velocity_gradient.noalias() += volume_j * v_ji * grad_w_ij.transpose();
}

/// Embeds a D x D tensor into 3x3 (top-left block; the rest zero). D = 3 is the identity map.
template <int D>
inline Eigen::Matrix3d embed_in_3d(const MatD<D>& m) {
  static_assert(D == 2 || D == 3, "embed_in_3d: D must be 2 or 3");
  Eigen::Matrix3d out = Eigen::Matrix3d::Zero();
  out.template topLeftCorner<D, D>() = m;
  return out;
}

/// The in-plane D x D block of a 3x3 tensor (what acts on D-dimensional kernel gradients).
template <int D>
inline MatD<D> in_plane_block(const Eigen::Matrix3d& m) {
  static_assert(D == 2 || D == 3, "in_plane_block: D must be 2 or 3");
  return m.template topLeftCorner<D, D>();
}

/// Embeds a D-vector into 3D (zero z component in 2D).
template <int D>
inline Eigen::Vector3d embed_in_3d(const sph::Vec<D>& v) {
  static_assert(D == 2 || D == 3, "embed_in_3d: D must be 2 or 3");
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  out.template head<D>() = v;
  return out;
}

/// eps_dot = (L + L^T) / 2, eq. 7.
inline Eigen::Matrix3d strain_rate(const Eigen::Matrix3d& velocity_gradient) {
  return 0.5 * (velocity_gradient + velocity_gradient.transpose());
}

/// omega = (L - L^T) / 2, eq. 8 (omega^{ab} = (dv^a/dx^b - dv^b/dx^a) / 2).
inline Eigen::Matrix3d spin(const Eigen::Matrix3d& velocity_gradient) {
  return 0.5 * (velocity_gradient - velocity_gradient.transpose());
}

}  // namespace porosph::soil
