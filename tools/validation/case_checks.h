// Comparisons of finished runs with each case's reference (analytic or experimental).
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

/// Martin & Moyce (1952) surge front: Z = z/a against T = t sqrt(2 g / a).
struct DamBreakComparison {
  double a = 0;  ///< column width [m], from the run's resolved scene (first water block)
  std::vector<double> T, Z_reference, Z_simulated;  ///< reference points inside the simulated time
  double mean_abs_error = 0, max_abs_error = 0;
  /// Diagnostic only: the time shift dT (in T units, 0..0.6) that minimises the mean |dZ| of
  /// Z_sim(T - dT) against the table, and that minimum. It measures how much of the error is a
  /// constant delay of the experiment's release rather than a wrong front speed.
  double best_shift = 0, mean_abs_error_shifted = 0;
  /// Needs no time origin: the late front speed dZ/dT, the least-squares slope over the table's
  /// points with T >= kLateSpeedFrom (after the release, where the lag has stopped building), of
  /// the simulated front and of the table (1.381 for Martin & Moyce's n^2 = 2 column).
  static constexpr double kLateSpeedFrom = 2.2;
  double late_speed = 0, late_speed_reference = 0;
};

/// The simulated front is the leading particle centre plus half a spacing (the particle's extent),
/// from the observable `front` in timeseries.csv, interpolated linearly in time.
DamBreakComparison compare_dam_break(const std::string& run_dir, const std::string& reference_csv);

}  // namespace porosph::validation
