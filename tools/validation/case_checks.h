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
};

/// The simulated front is the leading particle centre plus half a spacing (the particle's extent),
/// from the observable `front` in timeseries.csv, interpolated linearly in time.
DamBreakComparison compare_dam_break(const std::string& run_dir, const std::string& reference_csv);

/// Still water in a tank: pressure against rho0 |g| (H - s) (s height along -g, H the free surface
/// = top particle centre + dp/2), in the last snapshot of fluid.h5.
struct HydrostaticCheck {
  double depth = 0;              ///< H - bottom [m]
  std::size_t particles = 0;     ///< free particles checked (below the top two rows)
  double max_rel_error = 0;      ///< per particle, max |p - p_exact| / p_exact
  double mean_rel_error = 0;     ///< per particle, mean
  double max_row_rel_error = 0;  ///< per lattice row: |mean p - p_exact(row)| / p_exact(row)
  double max_speed_ratio = 0;    ///< max |v| / sqrt(|g| H) at the last snapshot
  double time = 0;               ///< time of the snapshot
  /// Per lattice row below the surface (row 0 = top): depth of the row centre, exact pressure,
  /// mean simulated pressure, and the largest per-particle relative error in the row.
  struct Row {
    double depth, exact, mean, max_rel_error;
  };
  std::vector<Row> rows;
};

HydrostaticCheck check_hydrostatic(const std::string& run_dir);

}  // namespace porosph::validation
