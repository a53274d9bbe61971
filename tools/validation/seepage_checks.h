// Comparison of a finished darcy_column run with the seepage law it uses (issue 4).
#pragma once

#include <string>

namespace porosph::validation {

/// Gravity-driven flow through a fixed porous block, periodic: unit hydraulic gradient along g,
/// so the steady superficial velocity q solves i = a q + b q^2 = 1 with a, b of the first soil
/// material at its initial porosity (Darcy: q = 1 / a = K). The simulated q is the final value of
/// the observable `darcy_velocity` (mean water velocity along the up axis, negative downwards).
struct DarcyColumnCheck {
  std::string seepage;         ///< the material's seepage law
  double a = 0, b = 0;         ///< eq. 13 coefficients [s/m], [s^2/m^2]
  double expected = 0;         ///< q from i = 1 [m/s]
  double simulated = 0;        ///< |final darcy_velocity| [m/s]
  double rel_error = 0;        ///< |simulated - expected| / expected
  double quadratic_share = 0;  ///< b q^2 / (a q + b q^2) at the expected q
  double settling = 0;         ///< relative change of darcy_velocity over the last output interval
  double time = 0;
};

DarcyColumnCheck check_darcy_column(const std::string& run_dir);

}  // namespace porosph::validation
