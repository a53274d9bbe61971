// Reading a finished run directory (docs/design.md section 6) for validation: run.json,
// timeseries.csv.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace porosph::validation {

/// timeseries.csv as columns by name.
struct TimeSeries {
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> columns;
  const std::vector<double>& column(const std::string& name) const;  ///< throws naming the column
};

/// Reads OUT/run.json. Throws std::runtime_error naming the file.
nlohmann::json read_run_json(const std::string& run_dir);
/// Reads OUT/timeseries.csv. Throws std::runtime_error naming the file.
TimeSeries read_timeseries(const std::string& run_dir);
/// Reads a two-or-more column CSV with a header line; lines starting with '#' are comments.
TimeSeries read_csv(const std::string& path);

/// Linear interpolation of y(x) at x0 (x ascending); NaN outside [x.front(), x.back()].
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double x0);
/// Time mean of y(t) over [from, to] inside [t.front(), t.back()] (t ascending): trapezoids on the
/// rows, y linear between them, the ends interpolated in their own interval.
double time_mean(const std::vector<double>& t, const std::vector<double>& y, double from,
                 double to);
/// Standard error of the mean of n samples from their sum and sum of squares (0 for n < 2).
double standard_error_of_mean(double sum, double sum_squared, int n);

}  // namespace porosph::validation
