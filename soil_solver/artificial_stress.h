// Artificial stress against the tensile instability, Gray, Monaghan & Swift (2001), "SPH elastic
// dynamics", Comput. Methods Appl. Mech. Engrg. 190, 6641-6662 (after Monaghan 2000), as used by
// Bui et al. 2008 and the seed paper (the R_ij f_ij^n term of eq. 16):
//   per particle, in the principal axes of its stress (sigma_k the principal stresses, tension
//   positive):  R_k = -epsilon sigma_k / rho^2 if sigma_k > 0, else 0;  R = Q diag(R_k) Q^T;
//   per pair:   R_ij = R_i + R_j,   f_ij = W(r_ij) / W(dp),   term  m_j R_ij f_ij^n grad_i W_ij,
// dp the initial particle spacing, epsilon ~ 0.5, n ~ 2.55 (docs/cases.md; the original inputs
// switch it on for materials with c > 0 - that choice is the scene's, not this header's). R is
// never positive-definite: it only adds a short-range repulsion between particles in tension, and
// vanishes in compression. In 2D (plane strain) the principal axes are those of the in-plane 2x2
// block, and R has zero out-of-plane row and column (only the in-plane block acts on the 2D kernel
// gradient).
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "soil_solver/velocity_gradient.h"
#include "sph/vector.h"

namespace porosph::soil {

struct ArtificialStressParameters {
  double epsilon = 0.5;    ///< strength, Gray et al. 2001 [-]
  double exponent = 2.55;  ///< n of f_ij^n [-]
};

/// True when no principal stress of the in-plane block is positive (negative semidefinite:
/// every principal minor of -sigma is >= 0), so R = 0 without an eigen decomposition. Most soil
/// particles are in compression; the eigen solver took 9 % of the soil solver's time on the
/// dp 0.01 m rockfill run.
template <int D>
inline bool no_principal_tension(const Eigen::Matrix3d& sigma) {
  static_assert(D == 2 || D == 3, "no_principal_tension: D must be 2 or 3");
  const double a = sigma(0, 0), b = sigma(1, 1), ab = sigma(0, 1);
  if (a > 0.0 || b > 0.0 || a * b < ab * ab) return false;
  if constexpr (D == 2) {
    return true;
  } else {
    const double c = sigma(2, 2), ac = sigma(0, 2), bc = sigma(1, 2);
    if (c > 0.0 || a * c < ac * ac || b * c < bc * bc) return false;
    return sigma.determinant() <= 0.0;  // det(-sigma) >= 0
  }
}

/// R_i of one particle with stress sigma (tension positive) and density rho.
template <int D>
inline Eigen::Matrix3d artificial_stress(const Eigen::Matrix3d& sigma, double rho, double epsilon) {
  static_assert(D == 2 || D == 3, "artificial_stress: D must be 2 or 3");
  if (no_principal_tension<D>(sigma)) return Eigen::Matrix3d::Zero();
  Eigen::SelfAdjointEigenSolver<MatD<D>> eig;
  eig.computeDirect(sigma.template topLeftCorner<D, D>());
  sph::Vec<D> r = sph::Vec<D>::Zero();
  const double scale = -epsilon / (rho * rho);
  for (int k = 0; k < D; ++k) {
    if (eig.eigenvalues()[k] > 0.0) r[k] = scale * eig.eigenvalues()[k];
  }
  const MatD<D>& q = eig.eigenvectors();
  return embed_in_3d<D>(MatD<D>(q * r.asDiagonal() * q.transpose()));
}

/// f_ij^n = (W(r_ij) / W(dp))^n, with the kernel values given (W(dp) > 0).
inline double artificial_stress_factor(double w_r, double w_dp, double exponent) {
  return std::pow(w_r / w_dp, exponent);
}

/// Acceleration of i due to j: m_j (R_i + R_j) f_ij^n grad_i W_ij (in-plane block in 2D).
template <int D>
inline sph::Vec<D> artificial_stress_acceleration(double m_j, const Eigen::Matrix3d& r_i,
                                                  const Eigen::Matrix3d& r_j, double f_n,
                                                  const sph::Vec<D>& grad_w_ij) {
  return (m_j * f_n) * ((in_plane_block<D>(r_i) + in_plane_block<D>(r_j)) * grad_w_ij);
}

}  // namespace porosph::soil
