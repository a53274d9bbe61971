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

}  // namespace porosph::validation
