// Invariants of a (symmetric, 3x3) stress tensor used by the Drucker-Prager model (seed paper
// eq. 9): I1 = sigma_kk, deviator s = sigma - I1/3 delta, J2 = s:s / 2. Sign convention of the
// whole soil model: tension positive, so a soil at rest has I1 < 0.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace porosph::soil {

/// I1 = trace(sigma).
inline double first_invariant(const Eigen::Matrix3d& sigma) { return sigma.trace(); }

/// s = sigma - (I1 / 3) delta.
inline Eigen::Matrix3d deviator(const Eigen::Matrix3d& sigma) {
  return sigma - (sigma.trace() / 3.0) * Eigen::Matrix3d::Identity();
}

/// J2 = s:s / 2 = s^{ab} s^{ab} / 2.
inline double second_deviatoric_invariant(const Eigen::Matrix3d& sigma) {
  return 0.5 * deviator(sigma).squaredNorm();
}

/// sqrt(J2).
inline double sqrt_j2(const Eigen::Matrix3d& sigma) {
  return std::sqrt(second_deviatoric_invariant(sigma));
}

}  // namespace porosph::soil
