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
// For psi = 0 (every case in docs/cases.md) both forms give beta_psi = 0: plastically
// incompressible.
//
// Which plastic flow eq. 10 assumes. Eq. 10 matches Mohr-Coulomb in plane strain at plastic flow
// with ASSOCIATED flow (psi = phi). With the potential above, plane-strain plastic flow
// (eps_dot_zz = 0) makes s_zz = -2 beta_psi sqrt(J2), so sqrt(J2) = t / sqrt(1 - 3 beta^2) with t
// the in-plane maximum shear stress and I1 = 3 p_in - 3 beta sqrt(J2) (p_in the in-plane mean);
// equating f = 0 with t = c cos(phi) - p_in sin(phi) gives
//   alpha_phi = sin(phi) / (3 sqrt(1 - 3 beta^2) + 3 beta sin(phi)),
//   k_c = c cos(phi) (1 - 3 alpha_phi beta) / sqrt(1 - 3 beta^2),
// which is eq. 10 for beta = alpha_phi (associated) and alpha_phi = sin(phi) / 3, k_c = c cos(phi)
// for psi = 0. YieldFit::kFlowRule uses it; with psi = 0 eq. 10's cone is narrower (phi 41: 3
// alpha_phi = 0.614 instead of sin 41 = 0.656, the friction of a Mohr-Coulomb soil of 37.8 deg).
#pragma once

#include <cmath>
#include <stdexcept>

namespace porosph::soil {

/// Which expression turns the dilatancy angle into the potential coefficient beta_psi.
enum class DilatancyForm { kPlaneStrainFit, kSeedPaperEq11 };

/// Which plane-strain plastic flow the yield function is matched to Mohr-Coulomb for.
enum class YieldFit {
  kSeedPaperEq10,  ///< associated flow: eq. 10 (the seed paper, Bui et al. 2008)
  kFlowRule,       ///< the material's own flow rule (dilatancy psi)
};

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
    DilatancyForm form = DilatancyForm::kPlaneStrainFit, YieldFit fit = YieldFit::kSeedPaperEq10) {
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
  if (fit == YieldFit::kFlowRule) {
    const double root = 1.0 - 3.0 * dp.beta_psi * dp.beta_psi;
    if (!(root > 0.0)) {
      throw std::invalid_argument(
          "Drucker-Prager: the flow-rule fit needs beta_psi < 1 / sqrt(3) (a smaller psi)");
    }
    const double s = std::sin(friction_angle);
    dp.alpha_phi = s / (3.0 * std::sqrt(root) + 3.0 * dp.beta_psi * s);
    dp.k_c = cohesion * std::cos(friction_angle) * (1.0 - 3.0 * dp.alpha_phi * dp.beta_psi) /
             std::sqrt(root);
  }
  return dp;
}

}  // namespace porosph::soil
