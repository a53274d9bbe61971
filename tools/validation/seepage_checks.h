// Comparison of a finished darcy_column run with the seepage law it uses (issue 4).
#pragma once

#include <string>

namespace porosph::validation {

/// Gravity-driven flow through a fixed porous block, periodic: unit hydraulic gradient along g,
/// so the steady superficial velocity q solves i = a q + b q^2 = 1 with a, b of the first soil
/// material at its initial porosity (Darcy: q = 1 / a = K). The simulated q is the observable
/// `darcy_velocity` (mean water velocity along the up axis, negative downwards): its mean over the
/// last lattice period dp / q of the run where the run covers one after 15 relaxation times
/// 1 / (g (a + 2 b q)) (Darcy: K / g), else its final value. The velocity swings over that period
/// as the water lattice slides through the soil lattice (lattice_registry.h), so a final value
/// depends on where in the swing the run ends: at a fixed end time, on dp.
struct DarcyColumnCheck {
  std::string seepage;          ///< the material's seepage law
  double a = 0, b = 0;          ///< eq. 13 coefficients [s/m], [s^2/m^2]
  double expected = 0;          ///< q from i = 1 [m/s]
  double simulated = 0;         ///< |darcy_velocity|: period_mean where covered, else final [m/s]
  double final_value = 0;       ///< |final darcy_velocity| [m/s]
  bool period_covered = false;  ///< the run covers a lattice period after the relaxation
  double period = 0;            ///< dp / expected [s]
  double period_mean = 0;       ///< time mean of |darcy_velocity| over the last period [m/s]
  double period_swing = 0;      ///< (max - min) / 2 of it over that period, relative to expected
  /// The period mean predicted for a water lattice sliding through the soil's in registry along
  /// gravity: the mean over a spacing of the law's q with the drag scaled by the kernel's lattice
  /// sum S (lattice_registry.h; Darcy: expected x the mean of 1 / S); 0 for an unknown kernel.
  double registry_prediction = 0;
  double rel_error = 0;        ///< |simulated - expected| / expected
  double quadratic_share = 0;  ///< b q^2 / (a q + b q^2) at the expected q
  double settling = 0;         ///< relative change of darcy_velocity over the last output interval
  double time = 0;
};

DarcyColumnCheck check_darcy_column(const std::string& run_dir);

}  // namespace porosph::validation
