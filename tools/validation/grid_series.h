// Grid convergence of a reference solution: a series of grids refined by a constant ratio r
// (2 here), the observed order of each scalar and its Richardson extrapolation (Roache,
// "Verification and Validation in Computational Science and Engineering", 1998, ch. 5).
// From the last three levels f1 (coarse), f2, f3 (fine):
//   p = log((f1 - f2) / (f2 - f3)) / log(r),        f_extrapolated = f3 + (f3 - f2) / (r^p - 1).
// Used by the seepage references (laplace_fv.h, sheet_pile.h, rectangular_dam.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace porosph::validation {

/// The observed order and the Richardson extrapolation of one scalar on a refined series.
struct RichardsonEstimate {
  double order = 0.0;           ///< p from the last three levels; NaN when they do not converge
                                ///< monotonically (differences of opposite sign) or one is 0
  double extrapolated = 0.0;    ///< f_fine + (f_fine - f_middle) / (r^p - 1); f_fine when p is NaN
  double error_estimate = 0.0;  ///< |extrapolated - f_fine|: the fine level's error estimate
  std::vector<double> orders;   ///< p of every successive triple (levels 0-2, 1-3, ...)
};

/// Richardson estimate of values on grids refined by `ratio` (values[0] coarsest); needs 3+.
RichardsonEstimate richardson(const std::vector<double>& values, double ratio = 2.0);

/// A grid series: every scalar at every level, the wall time of each level, the estimates.
struct GridSeries {
  std::vector<std::string> names;             ///< the scalars
  std::vector<int> refinement;                ///< 1, 2, 4, ...: the level's cells per base cell
  std::vector<std::vector<double>> values;    ///< [level][scalar]
  std::vector<double> seconds;                ///< wall time of each level
  std::vector<RichardsonEstimate> estimates;  ///< per scalar (empty with fewer than 3 levels)

  /// The column of one scalar over the levels.
  std::vector<double> column(std::size_t scalar) const;
};

/// Runs `evaluate(refinement)` for refinement = 1, 2, 4, ... (`levels` of them), each returning
/// the scalars `names` in that order, and estimates each scalar's order and limit.
GridSeries run_grid_series(const std::vector<std::string>& names, int levels,
                           const std::function<std::vector<double>(int refinement)>& evaluate);

/// The series as a Markdown table: one row per level (cells label, scalars, seconds), then the
/// observed order and the extrapolated value of each scalar.
std::string markdown_table(const GridSeries& series,
                           const std::function<std::string(int refinement)>& level_label,
                           int digits = 6);

}  // namespace porosph::validation
