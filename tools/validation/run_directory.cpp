#include "tools/validation/run_directory.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace porosph::validation {

const std::vector<double>& TimeSeries::column(const std::string& name) const {
  const auto it = columns.find(name);
  if (it == columns.end()) throw std::runtime_error("no column '" + name + "' in the time series");
  return it->second;
}

nlohmann::json read_run_json(const std::string& run_dir) {
  const std::string path = run_dir + "/run.json";
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  try {
    return nlohmann::json::parse(file);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

TimeSeries read_csv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  TimeSeries series;
  std::string line;
  int line_number = 0;
  while (std::getline(file, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    std::stringstream cells(line);
    std::string cell;
    if (series.names.empty()) {
      while (std::getline(cells, cell, ',')) series.names.push_back(cell);
      continue;
    }
    std::size_t k = 0;
    while (std::getline(cells, cell, ',')) {
      if (k >= series.names.size()) {
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": too many cells");
      }
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      series.columns[series.names[k]].push_back(
          end == cell.c_str() ? std::numeric_limits<double>::quiet_NaN() : value);
      ++k;
    }
  }
  if (series.names.empty()) throw std::runtime_error(path + ": no header line");
  return series;
}

TimeSeries read_timeseries(const std::string& run_dir) {
  return read_csv(run_dir + "/timeseries.csv");
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double x0) {
  if (x.empty() || x0 < x.front() || x0 > x.back()) return std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x0 <= x[i]) {
      const double w = (x[i] > x[i - 1]) ? (x0 - x[i - 1]) / (x[i] - x[i - 1]) : 1.0;
      return y[i - 1] + w * (y[i] - y[i - 1]);
    }
  }
  return y.back();
}

double time_mean(const std::vector<double>& t, const std::vector<double>& y, double from,
                 double to) {
  double integral = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (t[k] <= from || t[k - 1] >= to) continue;
    const double span = t[k] - t[k - 1];
    const auto at = [&](double s) {
      return span > 0.0 ? y[k - 1] + (s - t[k - 1]) / span * (y[k] - y[k - 1]) : y[k];
    };
    const double t0 = std::max(t[k - 1], from), t1 = std::min(t[k], to);
    integral += 0.5 * (at(t0) + at(t1)) * (t1 - t0);
  }
  return integral / (to - from);
}

double standard_error_of_mean(double sum, double sum_squared, int n) {
  if (n < 2) return 0.0;
  const double variance = std::max(0.0, (sum_squared - sum * sum / n) / (n - 1));
  return std::sqrt(variance / n);
}

}  // namespace porosph::validation
