// porosph_validate consolidation: prints the comparison with Terzaghi's closed form
// (consolidation_check.h), its summary lines, and optionally the series for the plot.
#include "tools/validation/consolidation_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "tools/validation/consolidation_check.h"

namespace porosph::validation {
namespace {

void summary(const char* quantity, double value, const char* unit, const char* reference,
             double error, const char* target, bool met) {
  std::printf("summary\t%s\t%.4g%s\t%s\t%+.4g\t%s\t%s\n", quantity, value, unit, reference, error,
              target, met ? "met" : "not met");
}

/// FILE: T, U, U_closed, settlement, settlement_closed, bottom u / p0 (both);
/// FILE_isochrones.csv: T, depth, u / p0 measured and closed.
void write_series(const ConsolidationCheck& c, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  out << "T,U,U_closed,settlement,settlement_closed,bottom_u,bottom_u_closed\n";
  for (const auto& x : c.samples) {
    out << x.time_factor << ',' << x.degree << ',' << x.degree_closed << ',' << x.settlement << ','
        << x.settlement_closed << ',' << x.bottom_pressure << ',' << x.bottom_pressure_closed
        << '\n';
  }
  const std::string iso_path = path.substr(0, path.rfind('.')) + "_isochrones.csv";
  std::ofstream iso(iso_path);
  if (!iso) throw std::runtime_error(iso_path + ": cannot write");
  iso << "T,depth,u,u_closed\n";
  for (const auto& i : c.isochrones)
    for (std::size_t r = 0; r < i.depth.size(); ++r)
      iso << i.time_factor << ',' << i.depth[r] << ',' << i.measured[r] << ',' << i.closed[r]
          << '\n';
}

}  // namespace

int report_consolidation(const ConsolidationCheck& c, const std::string& series) {
  std::printf(
      "consolidation: H = %.4f m, dp = %.4g m, p0 = %.0f Pa from t = %.3f s over %.3f s\n"
      "m_v = %.4g 1/Pa, K_w = rho c^2 = %.4g Pa, c_v = k / (gamma_w (m_v + 1 / K_w)) = %.5g m^2/s\n"
      "B = 1 / (1 + 1 / (m_v K_w)) = %.4f (with n / K_w, pore water of a real soil: %.4f)\n",
      c.height, c.dp, c.p0, c.load_time, c.ramp_time, c.m_v, c.bulk_water, c.c_v, c.b_model,
      c.b_textbook);
  std::printf("%8s %8s %8s %8s %10s %10s\n", "T_v", "U", "U_closed", "dU", "u_bot/p0", "closed");
  for (const double t : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0}) {
    const ConsolidationSample* best = nullptr;
    for (const auto& x : c.samples)
      if (!best || std::abs(x.time_factor - t) < std::abs(best->time_factor - t)) best = &x;
    if (!best || std::abs(best->time_factor - t) > 0.05 * t) continue;
    std::printf("%8.3f %8.4f %8.4f %+8.4f %10.4f %10.4f\n", best->time_factor, best->degree,
                best->degree_closed, best->degree - best->degree_closed, best->bottom_pressure,
                best->bottom_pressure_closed);
  }
  for (const auto& i : c.isochrones)
    std::printf("isochrone T_v = %.3f: max |u - u_closed| = %.4f p0 (target 0.05)\n", i.time_factor,
                i.max_error);
  std::printf(
      "B measured %.4f (lowest row over one undrained period, %.4f s, after the ramp): %+.2f%%\n"
      "settlement at T_v = %.3f: %.4g m, closed form %.4g m: %+.2f%%\n",
      c.b_measured, c.undrained_period, 100 * c.b_error, c.final_time_factor, c.final_settlement,
      c.final_settlement_closed, 100 * c.settlement_error);
  summary("degree of consolidation U, max |error| for 0.05 <= T_v <= 1", c.max_degree_error, "",
          "Terzaghi (1943)", c.max_degree_error, "0.03", c.max_degree_error <= 0.03);
  for (const auto& i : c.isochrones) {
    char quantity[96];
    std::snprintf(quantity, sizeof quantity, "isochrone T_v = %.2f, max |error| [p0]",
                  i.time_factor);
    summary(quantity, i.max_error, "", "Terzaghi (1943)", i.max_error, "0.05", i.max_error <= 0.05);
  }
  summary("loading pore-pressure ratio B", c.b_measured, "", "1 / (1 + 1 / (m_v K_w))",
          100 * c.b_error, "3 %", std::abs(c.b_error) <= 0.03);
  summary("final settlement [m]", c.final_settlement, "", "m_v H (p0 - u)",
          100 * c.settlement_error, "3 %", std::abs(c.settlement_error) <= 0.03);
  if (!series.empty()) write_series(c, series);
  return c.met ? 0 : 1;
}

}  // namespace porosph::validation
