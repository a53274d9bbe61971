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

HydrostaticCheck check_hydrostatic(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const double rho0 = parameters.at("water").at("rho0").get<double>();
  const double dp = parameters.at("run").at("dp").get<double>();
  const auto gravity = gravity_of(run);
  const double g = norm(gravity);
  const std::size_t dim = gravity.size();

  io::SnapshotReader reader(run_dir + "/fluid.h5");
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/fluid.h5 has no snapshot");
  const auto last = snapshots.back();
  const auto position = reader.read_f64(last.index, "position");
  const auto velocity = reader.read_f64(last.index, "velocity");
  const auto pressure = reader.read_f64(last.index, "pressure");
  const auto fixed = reader.read_u8(last.index, "fixed");

  HydrostaticCheck out;
  out.time = last.time;
  // Height along -g of every free particle.
  std::vector<double> height(position.rows, 0.0);
  double top = -INFINITY, bottom = INFINITY;
  for (std::size_t i = 0; i < position.rows; ++i) {
    double s = 0;
    for (std::size_t k = 0; k < dim; ++k) s -= position.values[i * dim + k] * gravity[k] / g;
    height[i] = s;
    if (fixed.values[i]) continue;
    top = std::max(top, s);
    bottom = std::min(bottom, s);
  }
  const double surface = top + 0.5 * dp;
  out.depth = surface - (bottom - 0.5 * dp);

  std::map<long, std::pair<double, double>> rows;  // row -> (sum of p, count)
  std::map<long, double> row_max_error;
  double sum_error = 0;
  for (std::size_t i = 0; i < position.rows; ++i) {
    if (fixed.values[i]) continue;
    double speed2 = 0;
    for (std::size_t k = 0; k < dim; ++k) speed2 += std::pow(velocity.values[i * dim + k], 2);
    out.max_speed_ratio = std::max(out.max_speed_ratio, std::sqrt(speed2 / (g * out.depth)));
    const long row = std::lround((top - height[i]) / dp);
    if (row < 2) continue;  // the top two rows are excluded (issue 2)
    const double exact = rho0 * g * (surface - height[i]);
    const double error = std::abs(pressure.values[i] - exact) / exact;
    out.max_rel_error = std::max(out.max_rel_error, error);
    sum_error += error;
    ++out.particles;
    row_max_error[row] = std::max(row_max_error[row], error);
    rows[row].first += pressure.values[i];
    rows[row].second += 1.0;
  }
  if (out.particles == 0) throw std::runtime_error(run_dir + ": no water below the top two rows");
  out.mean_rel_error = sum_error / static_cast<double>(out.particles);
  for (const auto& [row, sum_count] : rows) {
    const double exact = rho0 * g * (surface - (top - row * dp));
    const double mean = sum_count.first / sum_count.second;
    out.max_row_rel_error = std::max(out.max_row_rel_error, std::abs(mean - exact) / exact);
    out.rows.push_back({surface - (top - row * dp), exact, mean, row_max_error[row]});
  }
  return out;
}

}  // namespace porosph::validation
