#include "tools/validation/grid_series.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace porosph::validation {
namespace {

/// p from three successive levels; NaN when the differences change sign or vanish.
double order_of(double coarse, double middle, double fine, double ratio) {
  const double d1 = coarse - middle, d2 = middle - fine;
  if (d1 == 0.0 || d2 == 0.0 || (d1 > 0) != (d2 > 0))
    return std::numeric_limits<double>::quiet_NaN();
  return std::log(d1 / d2) / std::log(ratio);
}

}  // namespace

RichardsonEstimate richardson(const std::vector<double>& values, double ratio) {
  if (values.size() < 3) throw std::invalid_argument("richardson: needs three levels or more");
  RichardsonEstimate e;
  for (std::size_t k = 2; k < values.size(); ++k)
    e.orders.push_back(order_of(values[k - 2], values[k - 1], values[k], ratio));
  e.order = e.orders.back();
  const double fine = values.back(), middle = values[values.size() - 2];
  e.extrapolated =
      std::isnan(e.order) ? fine : fine + (fine - middle) / (std::pow(ratio, e.order) - 1.0);
  e.error_estimate = std::fabs(e.extrapolated - fine);
  return e;
}

std::vector<double> GridSeries::column(std::size_t scalar) const {
  std::vector<double> c;
  for (const auto& level : values) c.push_back(level.at(scalar));
  return c;
}

GridSeries run_grid_series(const std::vector<std::string>& names, int levels,
                           const std::function<std::vector<double>(int refinement)>& evaluate) {
  GridSeries s;
  s.names = names;
  for (int level = 0, refinement = 1; level < levels; ++level, refinement *= 2) {
    const auto start = std::chrono::steady_clock::now();
    s.values.push_back(evaluate(refinement));
    if (s.values.back().size() != names.size())
      throw std::logic_error("run_grid_series: evaluate returned the wrong number of scalars");
    s.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    s.refinement.push_back(refinement);
  }
  if (levels >= 3)
    for (std::size_t k = 0; k < names.size(); ++k) s.estimates.push_back(richardson(s.column(k)));
  return s;
}

std::string markdown_table(const GridSeries& series,
                           const std::function<std::string(int refinement)>& level_label,
                           int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << "| cells |";
  for (const auto& n : series.names) out << ' ' << n << " |";
  out << " wall [s] |\n| ---";
  for (std::size_t k = 0; k <= series.names.size(); ++k) out << " | ---";
  out << " |\n";
  for (std::size_t l = 0; l < series.values.size(); ++l) {
    out << "| " << level_label(series.refinement[l]) << " |";
    for (double v : series.values[l]) out << ' ' << v << " |";
    out.precision(3);
    out << ' ' << series.seconds[l] << " |\n";
    out.precision(digits);
  }
  if (series.estimates.empty()) return out.str();
  out << "| observed order |";
  out.precision(3);
  for (const auto& e : series.estimates) {
    out << ' ';
    for (std::size_t k = 0; k < e.orders.size(); ++k) out << (k ? ", " : "") << e.orders[k];
    out << " |";
  }
  out << " |\n| Richardson |";
  out.precision(digits);
  for (const auto& e : series.estimates) out << ' ' << e.extrapolated << " |";
  out << " |\n";
  return out.str();
}

}  // namespace porosph::validation
