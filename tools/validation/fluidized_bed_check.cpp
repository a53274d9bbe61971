#include "tools/validation/fluidized_bed_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/run_files.h"
#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {

namespace {

/// Mean of values[i] over the outputs with t0 <= t[i] <= t1 (NaN if none).
double window_mean(const std::vector<double>& t, const std::vector<double>& values, double t0,
                   double t1) {
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t0 || t[i] > t1) continue;
    sum += values[i];
    ++count;
  }
  return count ? sum / count : std::nan("");
}

/// FluidizedBedCheck::velocity_ratio and mass_flux_ratio from the snapshots of water.h5 at or
/// after `window_start`.
void water_in_bed(const std::string& run_dir, const nlohmann::json& run, FluidizedBedCheck& out,
                  double window_start) {
  const auto& parameters = run.at("parameters");
  const auto& inflow = parameters.at("water").at("inflow").at(0);
  const auto dir = inflow.at("direction").get<std::vector<double>>();
  const auto zone_lo = inflow.at("min").get<std::vector<double>>();
  const auto zone_hi = inflow.at("max").get<std::vector<double>>();
  const double dp = parameters.at("run").at("dp").get<double>();
  const std::size_t dim = dir.size();
  out.superficial_velocity = out.max_flow_rate / inflow.at("cross_section").get<double>();
  double bed_bottom = INFINITY;  // lowest soil block face along the inflow direction
  for (const auto& block : parameters.at("soil").at("blocks")) {
    const auto lo = block.at("min").get<std::vector<double>>();
    const auto hi = block.at("max").get<std::vector<double>>();
    double a = 0, b = 0;
    for (std::size_t k = 0; k < dim; ++k) a += lo[k] * dir[k], b += hi[k] * dir[k];
    bed_bottom = std::min(bed_bottom, std::min(a, b));
  }
  const double from = bed_bottom + 2.0 * dp, to = out.bed_height_final - 2.0 * dp;
  // The region's volume: the inflow zone's extent across the flow (it spans the bed's section)
  // times the bed's height.
  double region = to - from;
  for (std::size_t k = 0; k < dim; ++k)
    if (dir[k] == 0.0) region *= zone_hi[k] - zone_lo[k];
  io::SnapshotReader reader(io::water_snapshot_path(run_dir));
  double velocity = 0, velocity_squared = 0, flux = 0, flux_density = 0, fill = 0;
  int snapshots = 0;
  for (const auto& snap : reader.snapshots()) {
    if (snap.time < window_start - 1e-12) continue;
    const auto x = reader.read_f64(snap.index, "position");
    const auto v = reader.read_f64(snap.index, "velocity");
    const auto rho = reader.read_f64(snap.index, "density");
    const auto mass = reader.read_f64(snap.index, "mass");
    const auto fixed = reader.read_u8(snap.index, "fixed");
    double sum_v = 0, sum_flux = 0, sum_inflow_rho = 0, sum_mv = 0, sum_volume = 0;
    std::size_t n = 0, n_inflow = 0;
    for (std::size_t i = 0; i < x.rows; ++i) {
      if (fixed.values[i]) continue;
      double s = 0, vs = 0;
      bool in_zone = true;
      for (std::size_t k = 0; k < dim; ++k) {
        const double xk = x.values[i * dim + k];
        s += xk * dir[k];
        vs += v.values[i * dim + k] * dir[k];
        in_zone = in_zone && xk >= zone_lo[k] && xk <= zone_hi[k];
      }
      if (in_zone) sum_inflow_rho += rho.values[i], ++n_inflow;
      if (s < from || s > to) continue;
      sum_v += vs;
      sum_flux += rho.values[i] * vs;
      sum_mv += mass.values[i] * vs;
      sum_volume += mass.values[i] / rho.values[i];
      ++n;
    }
    if (n == 0 || n_inflow == 0) continue;
    const double rho_inflow = sum_inflow_rho / n_inflow;
    const double ratio = sum_v / n / out.superficial_velocity;
    velocity += ratio;
    velocity_squared += ratio * ratio;
    flux += sum_flux / n / (rho_inflow * out.superficial_velocity);
    flux_density += sum_mv / region / (rho_inflow * out.superficial_velocity);
    fill += sum_volume / region;
    ++snapshots;
  }
  if (snapshots == 0) throw std::runtime_error(run_dir + ": no water in the bed in the window");
  out.velocity_ratio = velocity / snapshots;
  out.window_snapshots = snapshots;
  out.velocity_ratio_error = standard_error_of_mean(velocity, velocity_squared, snapshots);
  out.mass_flux_ratio = flux / snapshots;
  out.mass_flux_density_ratio = flux_density / snapshots;
  out.volume_fill = fill / snapshots;
}

/// The water rises as lattice rows, one every dp / U, and the inflow's handover of a row and the
/// outflow's removal of one (without water.outflow[].stagger) send pulses through the bed, so a
/// mean over snapshots depends on how many pulses the window happens to catch. From the observables
/// bed_water_velocity, bed_water_density and inflow_water_mass (sampled every
/// run.timeseries_interval), the verdicts are time means over the whole inflow periods that fit in
/// the steady window (at least one), ending at the last row; their standard errors are those of the
/// periods' means (0 with one period). No-op without those columns.
void water_in_bed_over_periods(const std::string& run_dir, const TimeSeries& series, double dp,
                               int dimension, FluidizedBedCheck& out) {
  for (const char* name : {"bed_water_velocity", "bed_water_density", "inflow_water_mass"})
    if (!series.columns.count(name)) return;
  const auto& t = series.column("t");
  const auto& v = series.column("bed_water_velocity");
  const auto& rho_bed = series.column("bed_water_density");
  const auto& inflow_mass = series.column("inflow_water_mass");
  const double volume = std::pow(dp, dimension);  // a particle's volume dp^D
  out.inflow_period = dp / out.superficial_velocity;
  out.whole_periods =
      std::max(1, static_cast<int>(std::floor(out.steady_window / out.inflow_period + 1e-9)));
  const int n = out.whole_periods;
  const double end = t.back();
  if (end - n * out.inflow_period < t.front())
    throw std::runtime_error(run_dir + ": the run is shorter than one inflow period dp / U");
  double sum_v = 0, sum_v2 = 0, sum_flux = 0, sum_flux2 = 0;
  for (int p = 0; p < n; ++p) {
    const double to = end - p * out.inflow_period, from = to - out.inflow_period;
    const double ratio = time_mean(t, v, from, to) / out.superficial_velocity;
    // rho_bed v / (m_inflow / dp^D U) from the periods' means: the covariance of density and
    // velocity is of order (their relative swings)^2, below 1e-5 here.
    const double flux =
        ratio * time_mean(t, rho_bed, from, to) / (time_mean(t, inflow_mass, from, to) / volume);
    sum_v += ratio, sum_v2 += ratio * ratio;
    sum_flux += flux, sum_flux2 += flux * flux;
  }
  out.snapshot_velocity_ratio = out.velocity_ratio;
  out.snapshot_velocity_ratio_error = out.velocity_ratio_error;
  out.velocity_ratio = sum_v / n;
  out.velocity_ratio_error = standard_error_of_mean(sum_v, sum_v2, n);
  out.period_mass_flux_ratio = sum_flux / n;
  out.period_mass_flux_ratio_error = standard_error_of_mean(sum_flux, sum_flux2, n);
  out.velocity_over_periods = true;
}

}  // namespace

FluidizedBedCheck check_fluidized_bed(const std::string& run_dir, double steady_window) {
  const auto run = read_run_json(run_dir);
  const auto& inflows = run.at("parameters").at("water").at("inflow");
  if (inflows.empty()) throw std::runtime_error(run_dir + ": the scene has no water inflow");
  const auto& inflow = inflows.at(0);
  const double q_max = inflow.at("flow_rate").get<double>();
  const double t_start = inflow.at("start_time").get<double>();
  const double t_ramp = inflow.at("ramp_time").get<double>();
  const auto flow_rate = [&](double t) {
    if (t <= t_start) return 0.0;
    return t_ramp > 0 ? q_max * std::min(1.0, (t - t_start) / t_ramp) : q_max;
  };

  const auto series = read_timeseries(run_dir);
  const auto& t = series.column("t");
  const auto& porosity = series.column("sand_porosity");
  const auto& height = series.column("bed_height");
  const auto& stress = series.column("sand_stress_yy");
  if (t.size() < 4) throw std::runtime_error(run_dir + ": fewer than four outputs");

  FluidizedBedCheck out;
  out.max_flow_rate = q_max;
  out.time = t.back();
  out.steady_window = std::min(steady_window, 0.5 * (out.time - t_start));
  std::size_t first = 0;  // first output after the flow started
  while (first + 1 < t.size() && t[first] <= t_start) ++first;
  out.initial_porosity = porosity[first];
  out.bed_height_initial = height[first];
  out.stress_initial = stress[first];
  const double w0 = out.time - out.steady_window, w_mid = out.time - 0.5 * out.steady_window;
  out.steady_porosity = window_mean(t, porosity, w0, out.time);
  out.porosity_drift =
      window_mean(t, porosity, w_mid, out.time) - window_mean(t, porosity, w0, w_mid);
  out.bed_height_final = window_mean(t, height, w0, out.time);
  out.bed_rise_rate =
      (window_mean(t, height, w_mid, out.time) - window_mean(t, height, w0, w_mid)) /
      (0.5 * out.steady_window);
  out.stress_ratio = window_mean(t, stress, w0, out.time) / out.stress_initial;
  for (std::size_t i = first; i < t.size(); ++i) {
    if (out.onset_time < 0 && std::abs(stress[i]) < 0.1 * std::abs(out.stress_initial)) {
      out.onset_time = t[i];
      out.onset_flow_rate = flow_rate(t[i]);
    }
    if (out.expansion_time < 0 && porosity[i] >= out.initial_porosity + 0.005) {
      out.expansion_time = t[i];
      out.expansion_flow_rate = flow_rate(t[i]);
    }
  }
  water_in_bed(run_dir, run, out, w0);
  const auto& run_keys = run.at("parameters").at("run");
  water_in_bed_over_periods(run_dir, series, run_keys.at("dp").get<double>(),
                            run_keys.at("dimension").get<int>(), out);
  out.porosity_in_target = std::abs(out.steady_porosity - 0.51) <= 0.02;
  out.onset_in_target = out.onset_flow_rate >= 0.07e-3 && out.onset_flow_rate <= 0.12e-3;
  return out;
}

}  // namespace porosph::validation
