#include "tools/validation/verification_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {
namespace {

double norm_of(const std::vector<double>& v) {
  double s = 0;
  for (double c : v) s += c * c;
  return std::sqrt(s);
}

double wall_seconds_of(const nlohmann::json& run) {
  const auto& wall = run.value("wall_seconds", nlohmann::json::object());
  return wall.value("total", 0.0);
}

/// Least-squares line y = a + b x through the points; returns b and writes the largest residual.
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y,
                           double* max_residual) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i];
  const double mx = sx / n, my = sy / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double slope = sxy / sxx;
  *max_residual = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    *max_residual = std::max(*max_residual, std::abs(y[i] - (my + slope * (x[i] - mx))));
  return slope;
}

/// Times at which u - level crosses zero upwards, linearly interpolated between samples.
std::vector<double> upward_crossings(const std::vector<double>& t, const std::vector<double>& u,
                                     double level) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double a = u[i - 1] - level, b = u[i] - level;
    if (a < 0 && b >= 0) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a));
  }
  return crossings;
}

double max_plastic_strain_at_end(const std::string& run_dir) {
  io::SnapshotReader reader(run_dir + "/soil.h5");
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/soil.h5 has no snapshot");
  const auto strain = reader.read_f64(snapshots.back().index, "plastic_strain").values;
  double largest = 0;
  for (double e : strain) largest = std::max(largest, std::abs(e));
  return largest;
}

}  // namespace

bool TaylorGreenCheck::met() const { return std::abs(rel_error) <= kTarget; }

TaylorGreenCheck check_taylor_green(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const auto& water = parameters.at("water");
  if (water.value("initial_velocity", std::string("none")) != "taylor_green")
    throw std::runtime_error(run_dir + ": not a Taylor-Green run (water.initial_velocity)");
  TaylorGreenCheck c;
  c.dp = parameters.at("run").at("dp").get<double>();
  c.speed = water.at("taylor_green_speed").get<double>();
  c.wavelength = water.at("taylor_green_wavelength").get<double>();
  const double rho0 = water.at("rho0").get<double>();
  c.nu = water.at("viscosity").get<double>() / rho0;
  const double k = 2.0 * M_PI / c.wavelength;
  c.rate_analytic = 4.0 * c.nu * k * k;
  const double convective_time = c.wavelength / c.speed;
  c.window_start = TaylorGreenCheck::kWindowStart * convective_time;
  c.window_end = TaylorGreenCheck::kWindowEnd * convective_time;
  c.wall_seconds = wall_seconds_of(run);

  const auto series = read_timeseries(run_dir);
  const auto& t = series.column("t");
  const auto& energy = series.column("water_kinetic_energy");
  if (t.empty() || t.back() < c.window_end * (1 - 1e-9)) {
    throw std::runtime_error(run_dir + ": the run ends before the fit window closes at t = " +
                             std::to_string(c.window_end) + " s");
  }
  const auto& domain = parameters.at("domain");
  const auto lo = domain.at("min").get<std::vector<double>>();
  const auto hi = domain.at("max").get<std::vector<double>>();
  c.energy0 = energy.front();
  c.energy0_analytic = 0.25 * rho0 * c.speed * c.speed * (hi[0] - lo[0]) * (hi[1] - lo[1]);

  const bool has_density = series.columns.count("mean_density") != 0;
  const std::vector<double>* density = has_density ? &series.column("mean_density") : nullptr;
  std::vector<double> x, y;
  double density_sum = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < c.window_start * (1 - 1e-9) || t[i] > c.window_end * (1 + 1e-9)) continue;
    if (!(energy[i] > 0)) throw std::runtime_error(run_dir + ": kinetic energy not positive");
    x.push_back(t[i]);
    y.push_back(std::log(energy[i]));
    if (density) density_sum += (*density)[i];
  }
  if (x.size() < 5) throw std::runtime_error(run_dir + ": fewer than 5 outputs in the fit window");
  c.samples = x.size();
  c.density_drift = density ? density_sum / static_cast<double>(x.size()) / rho0 - 1.0
                            : std::numeric_limits<double>::quiet_NaN();
  c.rate_simulated = -least_squares_slope(x, y, &c.fit_residual);
  c.rel_error = (c.rate_simulated - c.rate_analytic) / c.rate_analytic;
  return c;
}

bool ElasticColumnCheck::met() const {
  return elastic() && std::abs(period_error) <= kTarget && std::abs(settlement_error) <= kTarget;
}

ElasticColumnCheck check_elastic_column(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const auto& soil = parameters.at("soil");
  const auto& material = soil.at("materials").at(0);
  const auto& block = soil.at("blocks").at(0);
  ElasticColumnCheck c;
  c.dp = parameters.at("run").at("dp").get<double>();
  c.gravity = norm_of(parameters.at("run").at("gravity").get<std::vector<double>>());
  c.density = material.at("density").get<double>();
  if (material.contains("young_modulus")) {
    const double e = material.at("young_modulus").get<double>();
    const double nu = material.at("poisson_ratio").get<double>();
    c.constrained_modulus = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  } else {
    c.constrained_modulus = material.at("bulk_modulus").get<double>() +
                            4.0 / 3.0 * material.at("shear_modulus").get<double>();
  }
  const auto lo = block.at("min").get<std::vector<double>>();
  const auto hi = block.at("max").get<std::vector<double>>();
  c.height = hi[1] - lo[1];  // gravity along -y (the scene's convention)
  c.wave_speed = std::sqrt(c.constrained_modulus / c.density);
  c.period_analytic = 4.0 * c.height / c.wave_speed;
  c.settlement_analytic = c.density * c.gravity * c.height * c.height / (2 * c.constrained_modulus);
  c.wall_seconds = wall_seconds_of(run);

  const auto series = read_timeseries(run_dir);
  const auto& t = series.column("t");
  const auto& u = series.column("top_displacement");
  // The mean level from the whole record, then twice from whole periods between crossings.
  double level = time_mean(t, u, t.front(), t.back());
  std::vector<double> crossings;
  for (int pass = 0; pass < 3; ++pass) {
    crossings = upward_crossings(t, u, level);
    if (crossings.size() < 3)
      throw std::runtime_error(run_dir + ": fewer than two whole periods of top_displacement");
    level = time_mean(t, u, crossings.front(), crossings.back());
  }
  c.periods = crossings.size() - 1;
  c.period_simulated = (crossings.back() - crossings.front()) / static_cast<double>(c.periods);
  c.settlement_simulated = level;
  c.period_error = (c.period_simulated - c.period_analytic) / c.period_analytic;
  c.settlement_error = (c.settlement_simulated - c.settlement_analytic) / c.settlement_analytic;
  c.max_plastic_strain = max_plastic_strain_at_end(run_dir);
  return c;
}

}  // namespace porosph::validation
