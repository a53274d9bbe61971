// One explicit stress update of a soil particle, seed paper eq. 12a/12b with the corrections of
// Bui et al. 2008 (see drucker_prager.h for the formulas and the sign convention, tension
// positive):
//   1. dsigma/dt = co-rotation + Hooke (eq. 6, jaumann_rate.h) - lambda_dot [...] (eq. 12a),
//      lambda_dot from eq. 12b evaluated at the OLD stress, non-zero only on the yield surface
//      while loading;
//   2. sigma_new = sigma + dt dsigma/dt (forward Euler; update_stress_modified_euler() below is
//      the second-order alternative, soil.stress_integration; a solver with a different
//      integrator uses stress_rate() and apply_return_corrections() itself);
//   3. tension cracking, then stress scaling back, on sigma_new.
// PlasticState accumulates lambda = sum lambda_dot dt. The return corrections of step 3 are not
// counted in lambda (they are a projection, not a flow-rule increment).
#pragma once

#include <Eigen/Core>

#include "soil_solver/drucker_prager.h"
#include "soil_solver/jaumann_rate.h"
#include "soil_solver/soil_material.h"

namespace porosph::soil {

/// Per-particle plastic history.
struct PlasticState {
  double plastic_multiplier = 0.0;   ///< accumulated lambda = sum lambda_dot dt [-]
  bool plastic_last_update = false;  ///< last update had lambda_dot > 0 or a return correction
};

/// Stress rate of eq. 12a at stress sigma; writes the lambda_dot it used (eq. 12b, >= 0).
inline Eigen::Matrix3d stress_rate(const Material& m, const Eigen::Matrix3d& sigma,
                                   const Eigen::Matrix3d& strain_rate, const Eigen::Matrix3d& spin,
                                   double& lambda_dot) {
  lambda_dot = plastic_multiplier_rate(m, sigma, strain_rate);
  Eigen::Matrix3d rate =
      elastic_stress_rate(m.bulk_modulus, m.shear_modulus, sigma, strain_rate, spin);
  if (lambda_dot > 0.0) rate += plastic_stress_rate(m, sigma, lambda_dot);
  return rate;
}

/// Step 3 on the integrated stress `next`, and lambda_dot dt into `state` (both updates end so).
inline Eigen::Matrix3d corrected_stress(const Material& m, Eigen::Matrix3d next, double lambda_dot,
                                        double dt, PlasticState& state) {
  const bool corrected = apply_return_corrections(m, next);
  state.plastic_multiplier += lambda_dot * dt;
  state.plastic_last_update = corrected || lambda_dot > 0.0;
  return next;
}

/// New stress after dt (steps 1-3 above); accumulates lambda_dot dt in `state`.
inline Eigen::Matrix3d update_stress(const Material& m, const Eigen::Matrix3d& sigma,
                                     const Eigen::Matrix3d& strain_rate,
                                     const Eigen::Matrix3d& spin, double dt, PlasticState& state) {
  double lambda_dot = 0.0;
  const Eigen::Matrix3d next = sigma + dt * stress_rate(m, sigma, strain_rate, spin, lambda_dot);
  return corrected_stress(m, next, lambda_dot, dt, state);
}

/// New stress after dt by the modified Euler (Heun) step of the same rate, the explicit scheme
/// of Sloan (1987, Int. J. Numer. Meth. Engng 24, 893-911) without its error-
/// controlled substeps: the rate of eq. 12a at the old stress and at the Euler-predicted stress
///   sigma* = sigma + dt R(sigma),   sigma_new = sigma + dt/2 [R(sigma) + R(sigma*)],
/// both at the step's strain rate and spin, then the corrections of step 3. For a fixed velocity
/// gradient it is second order in dt where the forward Euler step is first: the co-rotation, and
/// the plastic multiplier that forward Euler takes at the old stress only (eq. 12b), are
/// evaluated at both ends. A state that crosses the surface within the step gets the mean of the
/// elastic rate and the plastic rate at the (outside) predictor, as in Sloan (1987). The cost is
/// one more rate evaluation per particle, no neighbour pass. Accumulates dt/2 (lambda_dot +
/// lambda_dot*) in `state`.
inline Eigen::Matrix3d update_stress_modified_euler(const Material& m, const Eigen::Matrix3d& sigma,
                                                    const Eigen::Matrix3d& strain_rate,
                                                    const Eigen::Matrix3d& spin, double dt,
                                                    PlasticState& state) {
  double lambda_dot_old = 0.0, lambda_dot_predicted = 0.0;
  const Eigen::Matrix3d rate_old = stress_rate(m, sigma, strain_rate, spin, lambda_dot_old);
  const Eigen::Matrix3d predicted = sigma + dt * rate_old;
  const Eigen::Matrix3d rate_predicted =
      stress_rate(m, predicted, strain_rate, spin, lambda_dot_predicted);
  const Eigen::Matrix3d next = sigma + (0.5 * dt) * (rate_old + rate_predicted);
  return corrected_stress(m, next, 0.5 * (lambda_dot_old + lambda_dot_predicted), dt, state);
}

}  // namespace porosph::soil
