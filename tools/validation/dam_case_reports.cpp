#include "tools/validation/dam_case_reports.h"

#include <cmath>
#include <cstdio>

#include "tools/validation/series_csv.h"
#include "tools/validation/summary_line.h"

namespace porosph::validation {
namespace {
constexpr auto* fmt = &format_value;
}  // namespace

int report_rockfill(const RockfillCheck& c, const std::string& series) {
  std::printf(
      "rockfill_overtopping at t = %.2f s: Q = %.2f l/s, q = Q / W = %.3e m^2/s (flume width W = "
      "%.2f m"
      " = cross_section / sheet), %zu soil particles, dp %.3f m, toe x = %.3f m\n",
      c.time, 1e3 * c.flow_rate, c.discharge_per_metre, c.flume_width, c.particles, c.dp, c.x_toe);
  for (int k = 0; k < 3; ++k) {
    std::printf("B (moved > %.1f mm = %.1f D15): wet particles %.3f m, all particles %.3f m\n",
                1e3 * c.thresholds[k], c.thresholds[k] / c.d15, c.b_wet[k], c.b[k]);
  }
  const double b = c.b_wet[1];
  const std::size_t n = c.times.size();
  if (n > 10) {
    std::printf(
        "B (wet, D15) over the run: %.3f m at t = %.1f s, %.3f m at t = %.1f s, %.3f at the end\n",
        c.b_wet_history[n / 2], c.times[n / 2], c.b_wet_history[(9 * n) / 10],
        c.times[(9 * n) / 10], b);
  }
  std::printf("seepage (eq. 13, initial porosity): a = %.4f s/m, b = %.3f s^2/m^2\n", c.seepage_a,
              c.seepage_b);
  for (std::size_t k = 0; k < c.levels.size(); ++k) {
    std::printf(
        "steady water level %s (x = %.2f m): %.3f m; Dupuit-Forchheimer %.3f m (exit at the toe)\n",
        c.level_names[k].c_str(), c.level_x[k], c.levels[k], c.level_dupuit[k]);
  }
  write_series(series, {"t", "B_wet", "B_all"}, {&c.times, &c.b_wet_history, &c.b_history});
  if (!series.empty()) {  // the reference water table beside it: SERIES_dupuit.csv
    const auto stem = series.substr(0, series.rfind(".csv"));
    write_series(stem + "_dupuit.csv", {"x", "h"}, {&c.dupuit_x, &c.dupuit_h});
  }
  if (c.b_experiment < 0) {
    std::printf("no experiment for this flow rate\n");
    print_summary("B parameter (wet, D15)", fmt("%.3f m", b), "none for this Q", "-", "-", -1);
    return 0;
  }
  const double error = (b - c.b_experiment) / c.b_experiment;
  std::printf("B = %.3f m vs experiment %.2f m: error %+.1f%% (target 10%%; paper's SPH %.3f m)\n",
              b, c.b_experiment, 100 * error, c.b_paper_sph);
  print_summary(fmt("B parameter (wet, D15), Q = %.2f l/s", 1e3 * c.flow_rate), fmt("%.3f m", b),
                fmt("%.2f m (experiment)", c.b_experiment), fmt("%+.1f %%", 100 * error), "10 %",
                std::abs(error) <= 0.10);
  return std::abs(error) <= 0.10 ? 0 : 1;
}

int report_heave(const HeaveCheck& c, const std::string& series) {
  std::printf(
      "hydraulic_heave: damping ends at %.3f s (times below are counted from there), pile tip y ="
      " %.3f m\n%8s %14s %12s %22s %22s\n",
      c.damping_end, c.pile_tip, "t[s]", "gravel_bottom", "advance[m]", "sand_crossed[cm^2/m]",
      "gravel_settlement[mm]");
  for (std::size_t i = 0; i < c.times.size(); i += 10) {
    std::printf("%8.2f %14.4f %12.4f %22.2f %22.2f\n", c.times[i], c.gravel_bottom[i],
                c.gravel_top_of_sand - c.gravel_bottom[i], 1e4 * c.sand_crossed[i],
                1e3 * c.gravel_settlement[i]);
  }
  std::printf("overall head (upstream - downstream level): %.4f m at the start\n", c.head_at_start);
  write_series(series, {"t", "gravel_bottom", "sand_crossed", "gravel_settlement"},
               {&c.times, &c.gravel_bottom, &c.sand_crossed, &c.gravel_settlement});
  int verdict = 1;
  if (c.failure_time < 0) {
    std::printf(
        "no complete failure by t = %.2f s (the gravel next to the pile never reached the"
        " pile tip); experiment 4.4 s\n",
        c.end_time);
    print_summary("time of complete failure", fmt("none by %.2f s", c.end_time),
                  "4.4 s (experiment)", "-", "10 %", 0);
  } else {
    const double error = (c.failure_time - 4.4) / 4.4;
    std::printf(
        "complete failure (gravel next to the pile at the pile tip) at t = %.2f s, head %.4f m;"
        " experiment 4.4 s: error %+.1f%% (target 10%%)\n",
        c.failure_time, c.head_at_failure, 100 * error);
    verdict = std::abs(error) <= 0.10 ? 0 : 1;
    print_summary("time of complete failure", fmt("%.2f s", c.failure_time), "4.4 s (experiment)",
                  fmt("%+.1f %%", 100 * error), "10 %", verdict == 0);
  }
  // The bulk measures at the end of the run: figures for self-convergence, no experiment.
  if (!c.times.empty()) {
    const std::string by = fmt(" by %.2f s", c.end_time);
    print_summary("sand crossed under the pile" + by,
                  fmt("%.2f cm^2 per m", 1e4 * c.sand_crossed.back()), "no reference", "-", "-",
                  -1);
    print_summary("mean settlement of the gravel beside the pile" + by,
                  fmt("%.1f mm", 1e3 * c.gravel_settlement.back()), "no reference", "-", "-", -1);
  }
  return verdict;
}

}  // namespace porosph::validation
