#include "tools/validation/verification_report.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace porosph::validation {
namespace {

/// "summary<TAB>quantity<TAB>value<TAB>reference<TAB>error<TAB>target<TAB>met|not met".
void summary(const std::string& quantity, const std::string& value, const std::string& reference,
             const std::string& error, const std::string& target, bool met) {
  std::printf("summary\t%s\t%s\t%s\t%s\t%s\t%s\n", quantity.c_str(), value.c_str(),
              reference.c_str(), error.c_str(), target.c_str(), met ? "met" : "not met");
}

std::string fmt(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

int report_taylor_green(const TaylorGreenCheck& c) {
  std::printf(
      "taylor_green: dp %.4g m, U = %.4g m/s, L = %.4g m, nu = %.4g m^2/s, Re = %.1f\n"
      "E(0) = %.6g J/m (analytic rho0 U^2 A / 4 = %.6g)\n"
      "kinetic-energy decay rate, fit of ln E over t = %.3g .. %.3g s (%zu outputs): %.5f 1/s;"
      " analytic 4 nu k^2 = %.5f 1/s; error %+.2f%% (target 2%%)\n"
      "largest deviation of ln E from the fitted line %.2e; wall time %.1f s\n",
      c.dp, c.speed, c.wavelength, c.nu, c.speed * c.wavelength / c.nu, c.energy0,
      c.energy0_analytic, c.window_start, c.window_end, c.samples, c.rate_simulated,
      c.rate_analytic, 100 * c.rel_error, c.fit_residual, c.wall_seconds);
  summary("kinetic-energy decay rate", fmt("%.5f 1/s", c.rate_simulated),
          fmt("%.5f 1/s (4 nu k^2)", c.rate_analytic), fmt("%+.2f %%", 100 * c.rel_error), "2 %",
          c.met());
  return c.met() ? 0 : 1;
}

int report_elastic_column(const ElasticColumnCheck& c) {
  std::printf(
      "elastic_column: dp %.4g m, H = %.4g m, rho = %.4g kg/m^3, M = %.5g Pa, c_p = %.4f m/s\n"
      "period over %zu whole periods %.6f s; analytic 4 H / c_p = %.6f s; error %+.2f%%"
      " (target 3%%)\n"
      "static settlement (time mean of the top displacement) %.6e m; analytic rho g H^2 / (2 M)"
      " = %.6e m; error %+.2f%% (target 3%%)\n"
      "largest plastic strain at the end %.3e (%s); wall time %.1f s\n",
      c.dp, c.height, c.density, c.constrained_modulus, c.wave_speed, c.periods, c.period_simulated,
      c.period_analytic, 100 * c.period_error, c.settlement_simulated, c.settlement_analytic,
      100 * c.settlement_error, c.max_plastic_strain,
      c.elastic() ? "elastic" : "yielded: not an elastic test", c.wall_seconds);
  const bool period_met = c.elastic() && std::abs(c.period_error) <= ElasticColumnCheck::kTarget;
  const bool settlement_met =
      c.elastic() && std::abs(c.settlement_error) <= ElasticColumnCheck::kTarget;
  summary("period of the top displacement", fmt("%.6f s", c.period_simulated),
          fmt("%.6f s (4 H / c_p)", c.period_analytic), fmt("%+.2f %%", 100 * c.period_error),
          "3 %", period_met);
  summary("static settlement of the top", fmt("%.4e m", c.settlement_simulated),
          fmt("%.4e m (rho g H^2 / (2 M))", c.settlement_analytic),
          fmt("%+.2f %%", 100 * c.settlement_error), "3 %", settlement_met);
  return c.met() ? 0 : 1;
}

}  // namespace porosph::validation
