#include "tools/validation/fluidized_bed_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  out.porosity_in_target = std::abs(out.steady_porosity - 0.51) <= 0.02;
  out.onset_in_target = out.onset_flow_rate >= 0.07e-3 && out.onset_flow_rate <= 0.12e-3;
  return out;
}

}  // namespace porosph::validation
