#include "tools/validation/sheet_pile.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace porosph::validation {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// m = sin(pi s / (2 T)), checked 0 < s < T.
double modulus(double layer_depth, double pile_depth) {
  if (!(pile_depth >= 0.0 && pile_depth <= layer_depth))
    throw std::invalid_argument("sheet pile: needs 0 <= s <= T");
  return std::sin(kPi * pile_depth / (2.0 * layer_depth));
}

}  // namespace

double harr_discharge_factor(double layer_depth, double pile_depth) {
  const double m = modulus(layer_depth, pile_depth);
  if (m <= 0.0) return std::numeric_limits<double>::infinity();
  if (m >= 1.0) return 0.0;
  return std::comp_ellint_1(std::sqrt(1.0 - m * m)) / (2.0 * std::comp_ellint_1(m));
}

double harr_exit_gradient(double layer_depth, double pile_depth, double head_drop,
                          double from_pile) {
  const double m = modulus(layer_depth, pile_depth), t = layer_depth;
  if (m >= 1.0) return 0.0;
  const double c = std::cosh(kPi * from_pile / t) - std::cos(kPi * pile_depth / t);
  return kPi * head_drop / (2.0 * std::sqrt(2.0) * t * std::comp_ellint_1(m) * std::sqrt(c));
}

double harr_mean_exit_gradient(double layer_depth, double pile_depth, double head_drop,
                               double width) {
  const int n = 2000;  // even; i(x) is smooth and even in x for s > 0
  const double h = width / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += weight * harr_exit_gradient(layer_depth, pile_depth, head_drop, k * h);
  }
  return sum * h / (3.0 * width);
}

double harr_pile_face_head(const SheetPile& pile, double y, bool downstream) {
  const double t = pile.layer_depth, m = modulus(t, pile.pile_depth);
  const double sin_theta = std::min(1.0, std::cos(kPi * y / (2.0 * t)) / m);
  const double fraction = std::ellint_1(m, std::asin(sin_theta)) / std::comp_ellint_1(m);
  const double half = 0.5 * pile.head_drop() * fraction;
  return downstream ? pile.head_downstream + half : pile.head_upstream - half;
}

double harr_infinite_depth_exit_gradient(double pile_depth, double head_drop) {
  return head_drop / (kPi * pile_depth);
}

LaplaceProblem sheet_pile_problem(const SheetPile& pile, int cells_x, int cells_y) {
  const double tip_rows = cells_y * pile.pile_depth / pile.layer_depth;
  if (cells_x % 2 != 0 || std::fabs(tip_rows - std::lround(tip_rows)) > 1e-6)
    throw std::invalid_argument(
        "sheet_pile_problem: the pile must lie on grid lines (cells_x "
        "even, cells_y s / T an integer), got " +
        std::to_string(cells_x) + " x " + std::to_string(cells_y));
  LaplaceProblem p;
  p.x0 = 0.0, p.x1 = pile.width, p.y0 = 0.0, p.y1 = pile.layer_depth;
  p.cells_x = cells_x, p.cells_y = cells_y, p.conductivity = pile.conductivity;
  const double middle = 0.5 * pile.width;
  p.fixed_heads = {{Side::kTop, 0.0, middle, pile.head_upstream},
                   {Side::kTop, middle, pile.width, pile.head_downstream}};
  p.barriers = {{true, middle, pile.layer_depth - pile.pile_depth, pile.layer_depth}};
  return p;
}

SheetPileMeasures measure_sheet_pile(const SheetPile& pile, int cells_x, int cells_y,
                                     const std::vector<std::array<double, 2>>& probes,
                                     double exit_width) {
  const LaplaceSolution s = solve_laplace(sheet_pile_problem(pile, cells_x, cells_y));
  const double middle = 0.5 * pile.width;
  SheetPileMeasures m;
  m.discharge = s.discharge_across_vertical(middle, 0.0, pile.layer_depth);
  m.discharge_factor = m.discharge / (pile.conductivity * pile.head_drop());
  for (const auto& p : probes) m.heads.push_back(s.head(p[0], p[1]));
  m.exit_gradient_cell = s.mean_outward_gradient(Side::kTop, middle, middle + s.cell_width());
  m.exit_gradient_mean = s.mean_outward_gradient(Side::kTop, middle, middle + exit_width);
  return m;
}

GridSeries sheet_pile_series(const SheetPile& pile, int base_cells_x, int base_cells_y, int levels,
                             const std::vector<std::array<double, 2>>& probes, double exit_width) {
  std::vector<std::string> names = {"q/(K dh)"};
  for (const auto& p : probes)
    names.push_back("h(" + std::to_string(p[0]).substr(0, 6) + "," +
                    std::to_string(p[1]).substr(0, 6) + ")");
  names.insert(names.end(), {"i_exit cell", "i_exit mean"});
  return run_grid_series(names, levels, [&](int r) {
    const auto m = measure_sheet_pile(pile, r * base_cells_x, r * base_cells_y, probes, exit_width);
    std::vector<double> v = {m.discharge_factor};
    v.insert(v.end(), m.heads.begin(), m.heads.end());
    v.insert(v.end(), {m.exit_gradient_cell, m.exit_gradient_mean});
    return v;
  });
}

}  // namespace porosph::validation
