// Elastic-perfectly-plastic Drucker-Prager soil with non-associated flow: the pieces of the stress
// update of Bui et al. 2008 (Int. J. Numer. Anal. Meth. Geomech. 32, 1537-1570, section 3.2-3.3)
// as used by the seed paper (eq. 9-12).
//
// Sign convention: TENSION POSITIVE, compression negative, I1 = trace(sigma) (so I1 < 0 in a soil
// at rest). With this convention eq. 9 reads
//   f(sigma) = sqrt(J2) + alpha_phi I1 - k_c,   f < 0 elastic, f = 0 on the yield surface,
// i.e. compression (I1 < 0) raises the admissible shear stress sqrt(J2) <= k_c - alpha_phi I1.
// The cone's apex (sqrt(J2) = 0) lies at I1 = k_c / alpha_phi >= 0.
//
// Plastic flow (eq. 11-12, potential g = sqrt(J2) + beta_psi I1, see drucker_prager_constants.h):
//   lambda_dot = (3 alpha_phi K eps_dot_kk + (G / sqrt(J2)) s:eps_dot) / (9 alpha_phi K beta_psi +
//   G) plastic stress rate = -lambda_dot [3 K beta_psi delta + (G / sqrt(J2)) s]
// (the seed paper's 27 alpha K sin(psi) and 9 K sin(psi) are the case beta_psi = 3 sin(psi)).
// lambda_dot is applied only when the state is on the yield surface (f = 0 within a relative
// round-off tolerance) and loading (lambda_dot > 0), as in Bui et al. 2008.
//
// After the explicit update two corrections keep the state admissible (Bui et al. 2008, 3.3):
//   (a) tension cracking: if k_c - alpha_phi I1 < 0 (the state lies beyond the apex, on the
//       tensile side) shift the hydrostatic part onto the apex:
//         sigma <- sigma - (I1 - k_c / alpha_phi) / 3 delta;
//   (b) stress scaling back: if sqrt(J2) > k_c - alpha_phi I1 (outside the cone) scale the
//       deviator: s <- s (k_c - alpha_phi I1) / sqrt(J2), which puts the state on f = 0.
// For alpha_phi = 0 (phi = 0) there is no apex and (a) never applies.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "soil_solver/soil_material.h"
#include "soil_solver/stress_invariants.h"

namespace porosph::soil {

/// Relative tolerance of the "on the yield surface" test: after a scaling back f is zero to
/// round-off (~1e-16 of the stress scale), far below this.
constexpr double kYieldSurfaceTolerance = 1e-10;

/// f = sqrt(J2) + alpha_phi I1 - k_c (eq. 9; tension positive).
inline double yield_function(const Material& m, const Eigen::Matrix3d& sigma) {
  return sqrt_j2(sigma) + m.alpha_phi * first_invariant(sigma) - m.k_c;
}

/// Stress scale against which f is judged: |k_c| + |alpha_phi I1| + sqrt(J2).
inline double yield_scale(const Material& m, const Eigen::Matrix3d& sigma) {
  return std::abs(m.k_c) + std::abs(m.alpha_phi * first_invariant(sigma)) + sqrt_j2(sigma);
}

/// True if f >= -kYieldSurfaceTolerance * yield_scale (on, or numerically beyond, the surface).
inline bool on_yield_surface(const Material& m, const Eigen::Matrix3d& sigma) {
  return yield_function(m, sigma) >= -kYieldSurfaceTolerance * yield_scale(m, sigma);
}

/// The consistency-condition value of eq. 12b,
///   (3 alpha_phi K eps_dot_kk + (G / sqrt(J2)) s:eps_dot) / (9 alpha_phi K beta_psi + G),
/// without the on-surface / loading checks (negative means elastic unloading). At sqrt(J2) = 0
/// (the apex) the deviatoric term is dropped: s = 0 there.
inline double plastic_multiplier_rate_unchecked(const Material& m, const Eigen::Matrix3d& sigma,
                                                const Eigen::Matrix3d& strain_rate) {
  const double q = sqrt_j2(sigma);
  double numerator = 3.0 * m.alpha_phi * m.bulk_modulus * strain_rate.trace();
  if (q > 0.0) {
    numerator += (m.shear_modulus / q) * deviator(sigma).cwiseProduct(strain_rate).sum();
  }
  return numerator / (9.0 * m.alpha_phi * m.bulk_modulus * m.beta_psi + m.shear_modulus);
}

/// lambda_dot of eq. 12b: the unchecked value if the state is on the yield surface and loading,
/// 0 otherwise.
inline double plastic_multiplier_rate(const Material& m, const Eigen::Matrix3d& sigma,
                                      const Eigen::Matrix3d& strain_rate) {
  if (!on_yield_surface(m, sigma)) return 0.0;
  return std::max(0.0, plastic_multiplier_rate_unchecked(m, sigma, strain_rate));
}

/// Plastic part of the stress rate, eq. 12a's last term:
///   -lambda_dot [3 K beta_psi delta + (G / sqrt(J2)) s]   (deviatoric term dropped at J2 = 0).
inline Eigen::Matrix3d plastic_stress_rate(const Material& m, const Eigen::Matrix3d& sigma,
                                           double lambda_dot) {
  Eigen::Matrix3d rate =
      (-lambda_dot * 3.0 * m.bulk_modulus * m.beta_psi) * Eigen::Matrix3d::Identity();
  const double q = sqrt_j2(sigma);
  if (q > 0.0) rate -= (lambda_dot * m.shear_modulus / q) * deviator(sigma);
  return rate;
}

/// Correction (a), tension cracking: if k_c - alpha_phi I1 < 0 moves the state along the
/// hydrostatic axis to I1 = k_c / alpha_phi. Returns true if it did.
inline bool apply_tension_cracking(const Material& m, Eigen::Matrix3d& sigma) {
  const double i1 = first_invariant(sigma);
  if (!(m.alpha_phi > 0.0) || m.k_c - m.alpha_phi * i1 >= 0.0) return false;
  sigma.diagonal().array() -= (i1 - m.k_c / m.alpha_phi) / 3.0;
  return true;
}

/// Correction (b), stress scaling back: if sqrt(J2) > k_c - alpha_phi I1 scales the deviator by
/// r = (k_c - alpha_phi I1) / sqrt(J2) (r >= 0 once (a) has run). Returns true if it did.
inline bool apply_stress_scaling_back(const Material& m, Eigen::Matrix3d& sigma) {
  const double q = sqrt_j2(sigma);
  const double i1 = first_invariant(sigma);
  const double capacity = m.k_c - m.alpha_phi * i1;
  // q == 0: nothing to scale; beyond the apex by round-off (capacity ~ -1e-17 after a tension
  // cracking) r would be 0 / 0.
  if (q <= capacity || q == 0.0) return false;
  const double r = std::max(0.0, capacity) / q;
  const Eigen::Matrix3d hydrostatic = (i1 / 3.0) * Eigen::Matrix3d::Identity();
  sigma = hydrostatic + r * (sigma - hydrostatic);
  return true;
}

/// Both corrections in the order of Bui et al. 2008: (a) then (b). Returns true if either acted.
inline bool apply_return_corrections(const Material& m, Eigen::Matrix3d& sigma) {
  const bool cracked = apply_tension_cracking(m, sigma);
  const bool scaled = apply_stress_scaling_back(m, sigma);
  return cracked || scaled;
}

}  // namespace porosph::soil
