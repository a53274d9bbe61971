#include "tools/validation/case_checks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {

namespace {

std::vector<double> gravity_of(const nlohmann::json& run) {
  return run.at("parameters").at("run").at("gravity").get<std::vector<double>>();
}

/// Least-squares slope of y over x for the points with x >= from (NaN with fewer than two).
double slope_from(const std::vector<double>& x, const std::vector<double>& y, double from) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] < from) continue;
    n += 1, sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  }
  const double d = n * sxx - sx * sx;
  return n >= 2 && d > 0 ? (n * sxy - sx * sy) / d : std::nan("");
}

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace

DamBreakComparison compare_dam_break(const std::string& run_dir, const std::string& reference_csv) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const auto& block = parameters.at("water").at("blocks").at(0);
  DamBreakComparison out;
  out.a = block.at("max").at(0).get<double>() - block.at("min").at(0).get<double>();
  const double dp = parameters.at("run").at("dp").get<double>();
  const double g = norm(gravity_of(run));
  const double time_scale = std::sqrt(2.0 * g / out.a);  // T = t sqrt(2 g / a)

  const auto series = read_timeseries(run_dir);
  const auto& t = series.column("t");
  std::vector<double> z(series.column("front"));
  for (double& value : z) value = (value + 0.5 * dp) / out.a;

  const auto reference = read_csv(reference_csv);
  const auto& T_ref = reference.column("T");
  const auto& Z_ref = reference.column("Z");
  double sum = 0;
  for (std::size_t i = 0; i < T_ref.size(); ++i) {
    const double Z_sim = interpolate(t, z, T_ref[i] / time_scale);
    if (std::isnan(Z_sim)) continue;
    out.T.push_back(T_ref[i]);
    out.Z_reference.push_back(Z_ref[i]);
    out.Z_simulated.push_back(Z_sim);
    const double error = std::abs(Z_sim - Z_ref[i]);
    sum += error;
    out.max_abs_error = std::max(out.max_abs_error, error);
  }
  if (out.T.empty()) throw std::runtime_error(run_dir + ": the run covers no reference time");
  out.mean_abs_error = sum / static_cast<double>(out.T.size());
  out.late_speed = slope_from(out.T, out.Z_simulated, DamBreakComparison::kLateSpeedFrom);
  out.late_speed_reference = slope_from(out.T, out.Z_reference, DamBreakComparison::kLateSpeedFrom);
  out.mean_abs_error_shifted = out.mean_abs_error;
  for (int k = 1; k <= 60; ++k) {
    const double shift = 0.01 * k;
    double shifted_sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < out.T.size(); ++i) {
      const double Z_sim = interpolate(t, z, (out.T[i] - shift) / time_scale);
      if (std::isnan(Z_sim)) continue;
      shifted_sum += std::abs(Z_sim - out.Z_reference[i]);
      ++count;
    }
    if (count == out.T.size() && shifted_sum / count < out.mean_abs_error_shifted) {
      out.mean_abs_error_shifted = shifted_sum / count;
      out.best_shift = shift;
    }
  }
  return out;
}

}  // namespace porosph::validation
