// Comparison of a finished consolidation run (cases/consolidation) with Terzaghi's closed form
// (terzaghi.h; issue 23; docs/verification.md "Terzaghi 1D consolidation").
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

/// One output after the load started: measured and closed-form values.
struct ConsolidationSample {
  double time_factor = 0;    ///< T = c_v (t - t_load) / H^2
  double degree = 0;         ///< U measured from the settlement
  double degree_closed = 0;  ///< U of the closed form
  double settlement = 0;     ///< top row, since the load started [m]
  double settlement_closed = 0;
  double bottom_pressure = 0;  ///< excess pore pressure of the lowest row / p0
  double bottom_pressure_closed = 0;
};

/// An isochrone: the excess pore pressure per row of height dp around one time, per p0 (measured
/// and closed form both averaged over the outputs of one undrained period centred on it).
struct Isochrone {
  double time_factor = 0;
  std::vector<double> depth;  ///< below the drained top [m]
  std::vector<double> measured, closed;
  double max_error = 0;  ///< max |measured - closed| [p0]
};

struct ConsolidationCheck {
  // The model's constants (from run.json; the formulas are in terzaghi.h).
  double height = 0, dp = 0, p0 = 0, load_time = 0, ramp_time = 0;
  double m_v = 0, bulk_water = 0, c_v = 0, b_model = 0, b_textbook = 0;
  double undrained_period = 0;  ///< 4 (column + pool) / undrained wave speed [s]
  std::vector<ConsolidationSample> samples;
  std::vector<Isochrone> isochrones;  ///< at T = 0.1, 0.2, 0.5
  double max_degree_error = 0;        ///< over 0.05 <= T <= 1
  double b_measured = 0;              ///< B from the lowest row's pore pressure after the ramp
  double b_error = 0;                 ///< b_measured / b_model - 1
  double final_settlement = 0, final_settlement_closed = 0, final_time_factor = 0;
  double settlement_error = 0;  ///< relative, at the end of the run
  bool met = false;             ///< every target of issue 23
};

/// Reads run.json (material, water, load), soil.h5 (settlement of the loaded top row) and water.h5
/// (pore pressure per row, minus its mean over the outputs of one undrained period before the
/// load started). Throws std::runtime_error on
/// a run that is not a consolidation run or lacks outputs.
ConsolidationCheck check_consolidation(const std::string& run_dir);

}  // namespace porosph::validation
