// Comparison of a finished Mandel run (cases/mandel) with the closed form of mandel.h (issue 23;
// docs/verification.md "Mandel's problem").
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

/// One output after the load started: the centre's pore pressure and the plate's displacement.
struct MandelSample {
  double time = 0;                       ///< since the load started [s]
  double time_factor = 0;                ///< c t / a^2
  double centre = 0, centre_closed = 0;  ///< pore pressure of the centre column / p0
  double plate = 0, plate_closed = 0;    ///< the plate's displacement [m] (negative: down)
};

/// A profile p(x) / p0 over columns of width dp, averaged over the sample's height below the plate
/// and, like the closed form, over the outputs of one undrained period around its time.
struct MandelProfile {
  double time_factor = 0;
  std::vector<double> x, measured, closed;
  double max_error = 0;  ///< [p0]
  /// Whether the target applies: not while the load is still ramped up, nor in the undrained
  /// period after it (the sample rings there, which the quasi-static closed form does not).
  bool judged = true;
};

struct MandelCheck {
  double a = 0, b = 0, dp = 0, sigma0 = 0, load_time = 0, ramp_time = 0;
  double nu = 0, nu_u = 0, skempton = 0, c = 0, p0 = 0;
  double undrained_period = 0;  ///< 4 b / sqrt((K + 4 G / 3 + K_w) / rho_sat) [s]
  std::vector<MandelSample> samples;
  std::vector<MandelProfile> profiles;  ///< at c t / a^2 = 0.01, 0.05, 0.1, 0.2, 0.3
  // The centre's peak: the vertex of the least-squares parabola through the outputs where the
  // closed form is within 2 % of its largest value, for both series.
  double peak = 0, peak_closed = 0;            ///< [p0]
  double peak_time = 0, peak_time_closed = 0;  ///< since the load started [s]
  double peak_error = 0, peak_time_error = 0;  ///< relative
  double initial = 0, initial_error = 0;       ///< the sample's mean pressure over one undrained
                                               ///< period after the ramp / its closed form, - 1
  double final_plate_error = 0;                ///< relative, at the end of the run
  bool met = false;  ///< peak and its time within 5 %, the judged profiles within 0.05 p0
};

/// Reads run.json (the sample's material, the water, the first load: the plate), soil.h5 (the
/// plate's displacement) and water.h5 (the pore pressure of the water inside the sample, below the
/// plate's row). Throws std::runtime_error on a run that is not a Mandel run or lacks outputs.
MandelCheck check_mandel(const std::string& run_dir);

/// Prints the comparison and one summary line per target; writes the series (t, T, centre and
/// plate, measured and closed) to `series` when not empty. Returns 0 when every target is met.
int report_mandel(const MandelCheck& m, const std::string& series);

}  // namespace porosph::validation
