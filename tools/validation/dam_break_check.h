// The dam break against Martin & Moyce (1952): the surge front Z = z/a against T = t sqrt(2 g / a).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace porosph::validation {

/// Capillary length of clean water at 20 C, sqrt(sigma / (rho g)) with sigma = 0.0728 N/m [m].
/// Thinner than this, surface tension (which the model lacks) governs a tip advancing over a dry
/// bed (de Gennes, Brochard-Wyart & Quere 2004, ch. 2), so the bulk front is judged from this
/// depth.
constexpr double kCapillaryLengthOfWater = 2.72e-3;

/// Which point of the simulated water is the surge front.
enum class DamBreakFront {
  /// The leading particle centre plus half a spacing: the observable `front` of timeseries.csv.
  /// At fine dp it is a film one particle thick that runs ahead of the water behind it.
  farthest_particle,
  /// The far edge of the farthest dp-wide column (counted from the back wall) that holds a water
  /// depth (particles x dp) of at least kCapillaryLengthOfWater, from the snapshots of water.h5.
  bulk,
};

struct DamBreakComparison {
  DamBreakFront front = DamBreakFront::bulk;
  double a = 0;  ///< column width [m], from the run's resolved scene (first water block)
  double dp = 0;
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
  /// The whole simulated front: T and Z at every output (bulk) or timeseries row (farthest).
  std::vector<double> T_front, Z_front;
};

/// Compares a finished run's front with the table (T,Z); the front is interpolated linearly in time
/// between outputs. Throws std::runtime_error naming the file on unreadable input.
DamBreakComparison compare_dam_break(const std::string& run_dir, const std::string& reference_csv,
                                     DamBreakFront front = DamBreakFront::bulk);

/// The bulk front [m from the back wall x_wall] of one 2D snapshot: position (x, y interleaved) and
/// fixed of every water particle; depth is scratch (resized as needed). 0 when no column is deep
/// enough.
double bulk_front(const std::vector<double>& position, const std::vector<std::uint8_t>& fixed,
                  double x_wall, double dp, double min_depth, std::vector<double>& depth);

/// The bulk front z [m] from the back wall at each snapshot time t [s] of OUT/water.h5.
void bulk_front_series(const std::string& run_dir, double dp, double min_depth,
                       std::vector<double>& t, std::vector<double>& z);

/// Prints both fronts against the table and the summary lines; the verdict is the bulk front's mean
/// |dZ| <= 0.10 (issue 23). Returns the exit code: 0 met, 1 not met.
int report_dam_break(const DamBreakComparison& bulk, const DamBreakComparison& farthest);

}  // namespace porosph::validation
