// Drucker-Prager constants matched to Mohr-Coulomb in plane strain, seed paper eq. 10
// (Bui et al. 2008, Int. J. Numer. Anal. Meth. Geomech. 32, 1537-1570, eq. 21 there):
//   alpha_phi = tan(phi) / sqrt(9 + 12 tan^2(phi)),   k_c = 3 c / sqrt(9 + 12 tan^2(phi)),
// for the yield function (eq. 9, tension positive, see drucker_prager.h)
//   f(sigma) = sqrt(J2) + alpha_phi I1 - k_c.
//
// Dilatancy. The non-associated plastic potential is written here as
//   g(sigma) = sqrt(J2) + beta_psi I1,
// so that the plastic terms of eq. 12a/12b read  lambda_dot [3 K beta_psi delta + G s / sqrt(J2)]
// and  lambda_dot = (3 alpha_phi K eps_dot_kk + G s:eps_dot / sqrt(J2)) / (9 alpha_phi K beta_psi +
// G). Two forms of beta_psi exist:
//   * DilatancyForm::kPlaneStrainFit (the default): beta_psi = tan(psi) / sqrt(9 + 12 tan^2(psi)),
//     the alpha_psi of Bui et al. 2008 (their eq. 24), i.e. the same plane-strain fit as the yield
//     function. With psi = phi the flow becomes associated (g = f + const), which is the property
//     a dilatancy angle must have; this is why it is the default.
//   * DilatancyForm::kSeedPaperEq11: beta_psi = 3 sin(psi), the literal seed paper eq. 11
//     (g = sqrt(J2) + 3 I1 sin(psi)); it reproduces the "9 K sin(psi)" and "27 alpha K sin(psi)"
//     of eq. 12a/12b exactly. For small psi it is ~9 times the plane-strain fit, and psi = phi
//     does not give associated flow. Kept so the paper can be reproduced literally.
// For psi = 0 (every case in CASES.md) both forms give beta_psi = 0: plastically incompressible.
#pragma once

#include <cmath>
#include <stdexcept>

namespace porosph::soil {

/// Which expression turns the dilatancy angle into the potential coefficient beta_psi.
enum class DilatancyForm { kPlaneStrainFit, kSeedPaperEq11 };

/// The three constants of the yield function and the plastic potential.
struct DruckerPragerConstants {
  double alpha_phi = 0.0;  ///< friction coefficient of the yield function [-]
  double k_c = 0.0;        ///< cohesion term of the yield function [Pa]
  double beta_psi = 0.0;   ///< dilatancy coefficient of the plastic potential [-]
};

inline double degrees_to_radians(double degrees) { return degrees * M_PI / 180.0; }

/// alpha = tan(a) / sqrt(9 + 12 tan^2(a)) for an angle a in radians (eq. 10, first part).
inline double drucker_prager_alpha_plane_strain(double angle) {
  const double t = std::tan(angle);
  return t / std::sqrt(9.0 + 12.0 * t * t);
}

/// k_c = 3 c / sqrt(9 + 12 tan^2(phi)) for the friction angle phi in radians (eq. 10, second part).
inline double drucker_prager_k_plane_strain(double friction_angle, double cohesion) {
  const double t = std::tan(friction_angle);
  return 3.0 * cohesion / std::sqrt(9.0 + 12.0 * t * t);
}

/// All three constants from phi, c, psi (angles in radians, 0 <= psi <= phi < pi/2, c >= 0;
/// throws std::invalid_argument otherwise).
inline DruckerPragerConstants drucker_prager_plane_strain(
    double friction_angle, double cohesion, double dilatancy_angle,
    DilatancyForm form = DilatancyForm::kPlaneStrainFit) {
  if (!(friction_angle >= 0.0 && friction_angle < 0.5 * M_PI)) {
    throw std::invalid_argument("Drucker-Prager: friction angle must lie in [0, 90) degrees");
  }
  if (!(dilatancy_angle >= 0.0 && dilatancy_angle <= friction_angle)) {
    throw std::invalid_argument("Drucker-Prager: dilatancy angle must lie in [0, phi]");
  }
  if (!(cohesion >= 0.0)) throw std::invalid_argument("Drucker-Prager: cohesion must be >= 0");
  DruckerPragerConstants dp;
  dp.alpha_phi = drucker_prager_alpha_plane_strain(friction_angle);
  dp.k_c = drucker_prager_k_plane_strain(friction_angle, cohesion);
  dp.beta_psi = form == DilatancyForm::kPlaneStrainFit
                    ? drucker_prager_alpha_plane_strain(dilatancy_angle)
                    : 3.0 * std::sin(dilatancy_angle);
  return dp;
}

}  // namespace porosph::soil
