// Seepage-law coefficients a, b of seed paper eq. 13 as functions of the porosity n (used by the
// coupler; with variable permeability n follows eq. 20, see porosity.h):
//   f_seepage = gamma_w (a v_r + b |v_r| v_r),   v_r = v_water - v_soil      (eq. 13)
// Darcy with Kozeny-Carman (eq. 14):
//   k = (1/180) n^3 / (1 - n)^2 (g / nu) d_e^2,   a = 1 / k,   b = 0,
// k the hydraulic conductivity [m/s], d_e the effective grain diameter, nu the water's kinematic
// viscosity. Forchheimer with Den Adel's coefficients (eq. 15; Den Adel 1987, van Gent 1995):
//   a = alpha (1 - n)^2 / n^3 nu / (g d15^2),   b = beta / n^2 / (g d15),
// alpha = 150, beta = 0.4 in the seed paper. Units: a [s/m], b [s^2/m^2]; a |v| and b v^2 are
// hydraulic gradients (per unit weight of water, as eq. 13 multiplies by gamma_w).
// Pure functions: 0 < n < 1, d > 0, g > 0, nu > 0 are the caller's to ensure.
#pragma once

namespace porosph::porous {

/// The two coefficients of eq. 13.
struct SeepageCoefficients {
  double a = 0.0;  ///< linear (Darcy) coefficient [s/m]
  double b = 0.0;  ///< quadratic (Forchheimer) coefficient [s^2/m^2]
};

/// Hydraulic conductivity k of eq. 14 [m/s].
inline double kozeny_carman_conductivity(double porosity, double effective_diameter, double gravity,
                                         double kinematic_viscosity) {
  const double n = porosity;
  return (1.0 / 180.0) * n * n * n / ((1.0 - n) * (1.0 - n)) * (gravity / kinematic_viscosity) *
         effective_diameter * effective_diameter;
}

/// Darcy + Kozeny-Carman: a = 1/k (eq. 14), b = 0.
inline SeepageCoefficients darcy_kozeny_carman(double porosity, double effective_diameter,
                                               double gravity, double kinematic_viscosity) {
  return {
      1.0 / kozeny_carman_conductivity(porosity, effective_diameter, gravity, kinematic_viscosity),
      0.0};
}

/// Darcy with a given constant conductivity k: a = 1/k, b = 0.
inline SeepageCoefficients darcy_constant(double conductivity) { return {1.0 / conductivity, 0.0}; }

/// Den Adel's empirical constants of eq. 15 as the seed paper uses them: the defaults of the
/// scene's den_adel_alpha / den_adel_beta (porous/seepage_laws.h takes them from here).
inline constexpr double kDenAdelAlpha = 150.0;
inline constexpr double kDenAdelBeta = 0.4;

/// Forchheimer with Den Adel's coefficients, eq. 15.
inline SeepageCoefficients forchheimer_den_adel(double porosity, double d15, double gravity,
                                                double kinematic_viscosity,
                                                double alpha = kDenAdelAlpha,
                                                double beta = kDenAdelBeta) {
  const double n = porosity;
  SeepageCoefficients c;
  c.a = alpha * (1.0 - n) * (1.0 - n) / (n * n * n) * kinematic_viscosity / (gravity * d15 * d15);
  c.b = beta / (n * n) / (gravity * d15);
  return c;
}

}  // namespace porosph::porous
