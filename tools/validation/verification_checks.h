// Closed-form verification cases (issue 23, docs/verification.md): the Taylor-Green vortex
// (cases/taylor_green) and the elastic soil column loaded suddenly by gravity
// (cases/elastic_column). Each reads a finished run directory and compares one measured number
// with its closed form.
#pragma once

#include <cstddef>
#include <string>

namespace porosph::validation {

/// Taylor-Green vortex (Taylor & Green 1937): the water kinetic energy of timeseries.csv decays as
/// E(0) exp(-4 nu k^2 t), k = 2 pi / L. The measured rate is minus the least-squares slope of
/// ln E against t over the fixed window [kWindowStart, kWindowEnd] L / U.
struct TaylorGreenCheck {
  static constexpr double kWindowStart = 0.1;  ///< in convective times L / U
  static constexpr double kWindowEnd = 1.0;
  static constexpr double kTarget = 0.02;  ///< issue 23: rate within 2 %

  double dp = 0, speed = 0, wavelength = 0, nu = 0;
  double window_start = 0, window_end = 0;   ///< [s]
  std::size_t samples = 0;                   ///< outputs inside the window
  double rate_analytic = 0;                  ///< 4 nu k^2 [1/s]
  double rate_simulated = 0;                 ///< -d ln E / dt, least squares [1/s]
  double rel_error = 0;                      ///< (simulated - analytic) / analytic
  double fit_residual = 0;                   ///< max |ln E - fit| over the window
  double energy0 = 0, energy0_analytic = 0;  ///< E(0) [J/m] and rho0 U^2 A / 4
  /// Mean over the window of the observable `mean_density` / rho0 - 1 (NaN when the run has no
  /// such observable): the box's volume is fixed, so the mean density must stay at rho0.
  double density_drift = 0;
  double wall_seconds = 0;  ///< of the run (coupler)
  bool met() const;
};

/// Throws std::runtime_error when the run is no Taylor-Green run or ends before the window does.
TaylorGreenCheck check_taylor_green(const std::string& run_dir);

/// Laterally confined elastic column of height H on a rigid floor, loaded suddenly by gravity from
/// zero stress: its top displacement (observable `top_displacement`) is periodic with
/// T = 4 H / c_p, c_p = sqrt(M / rho), about the static settlement rho g H^2 / (2 M),
/// M = E (1 - nu) / ((1 + nu) (1 - 2 nu)). The period is the mean spacing of the upward crossings
/// of the mean; the settlement is the time mean between the first and the last crossing (whole
/// periods).
struct ElasticColumnCheck {
  static constexpr double kTarget = 0.03;  ///< issue 23: within 3 %

  double dp = 0, height = 0, density = 0, constrained_modulus = 0, gravity = 0;
  double wave_speed = 0;                                     ///< c_p [m/s]
  double period_analytic = 0, period_simulated = 0;          ///< [s]
  double settlement_analytic = 0, settlement_simulated = 0;  ///< [m]
  double period_error = 0, settlement_error = 0;             ///< relative, signed
  std::size_t periods = 0;                                   ///< whole periods measured
  double max_plastic_strain = 0;  ///< at the last snapshot: 0 when elastic
  double wall_seconds = 0;
  bool elastic() const { return max_plastic_strain <= 0.0; }
  bool met() const;
};

/// Throws std::runtime_error when the run lacks the observable or holds fewer than two periods.
ElasticColumnCheck check_elastic_column(const std::string& run_dir);

}  // namespace porosph::validation
