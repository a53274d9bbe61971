// A sheet pile in a permeable layer: Harr's closed forms and the finite-volume reference
// (laplace_fv.h) that the SPH seepage cases are compared with (issue 30 item 5).
//
// Geometry: soil from the impermeable base y = 0 to the surface y = T, width L, a thin
// impermeable pile at x = L/2 from the surface down to depth s (tip at y = T - s); the surface
// has the fixed head h1 upstream (x < L/2) and h2 downstream (x > L/2), the sides x = 0, L are
// no-flow. By antisymmetry h = (h1 + h2) / 2 on the line x = L/2 below the tip, at the tip too.
//
// Closed forms for the layer of infinite horizontal extent (Harr, "Groundwater and Seepage",
// McGraw-Hill 1962 / Dover 1991, ch. 5, the sheet pile in a layer of finite depth), dh = h1 - h2,
// m = sin(pi s / (2 T)), m' = sqrt(1 - m^2), K(k) the complete elliptic integral of the first
// kind of modulus k (std::comp_ellint_1(k) = int_0^{pi/2} dθ / sqrt(1 - k^2 sin^2 θ)):
//   discharge        q / (K dh) = K(m') / (2 K(m))
//   exit gradient    i(x) = pi dh / (2 sqrt(2) T K(m) sqrt(cosh(pi x / T) - cos(pi s / T)))
//                    at the distance x downstream of the pile; at the pile i(0) = pi dh / (4 T m
//                    K(m)), which tends to Harr's dh / (pi s) of an infinitely deep layer (T >> s)
//   pile face        h(y) = h2 + (dh / 2) F(θ, m) / K(m), sin θ = cos(pi y / (2 T)) / m,
//                    downstream face; upstream h1 - (dh / 2) F(θ, m) / K(m); F incomplete.
// Derivation (reproduced in docs/verification.md): the half domain x > 0 (pile at x = 0) maps to
// the upper half t-plane by t = cosh(pi z / T); the downstream surface is t < -1, the pile
// -1 < t < a = -cos(pi s / T), the line below the tip a < t < 1 (h = (h1 + h2) / 2), the base
// t > 1. The Schwarz-Christoffel map W = int dt / sqrt((t + 1)(t - a)(t - 1)) takes this to a
// rectangle in which h is linear; its side ratio gives the discharge (Landen's transformation
// turns it into Harr's form), dW/dz at t = -cosh(pi x / T) the exit gradient, W along the pile
// the pile-face head. Limits: s -> 0: q -> infinity (no pile, infinite extent); s -> T: q -> 0.
#pragma once

#include <array>
#include <vector>

#include "tools/validation/grid_series.h"
#include "tools/validation/laplace_fv.h"

namespace porosph::validation {

/// The sheet-pile geometry, heads and conductivity.
struct SheetPile {
  double layer_depth = 0.2;      ///< T [m]
  double width = 1.2;            ///< L [m]
  double pile_depth = 0.1;       ///< s [m], below the surface
  double head_upstream = 0.05;   ///< h1 [m]
  double head_downstream = 0.0;  ///< h2 [m]
  double conductivity = 1.0;     ///< K [m/s]

  double head_drop() const { return head_upstream - head_downstream; }
};

/// Harr: q / (K dh) = K(m') / (2 K(m)), infinite horizontal extent.
double harr_discharge_factor(double layer_depth, double pile_depth);
/// Harr: the exit gradient at the distance `from_pile` downstream of the pile, infinite extent.
double harr_exit_gradient(double layer_depth, double pile_depth, double head_drop,
                          double from_pile);
/// The mean of harr_exit_gradient over [0, width] downstream of the pile (Simpson's rule).
double harr_mean_exit_gradient(double layer_depth, double pile_depth, double head_drop,
                               double width);
/// Harr: the head on the downstream (or upstream) face of the pile at height y (T - s <= y <= T).
double harr_pile_face_head(const SheetPile& pile, double y, bool downstream);
/// Infinitely deep layer (Harr 1962): the exit gradient at the pile, dh / (pi s).
double harr_infinite_depth_exit_gradient(double pile_depth, double head_drop);

/// The finite-volume problem of the geometry on cells_x x cells_y cells. The pile must lie on
/// grid lines: cells_x even, cells_y s / T an integer (else std::invalid_argument).
LaplaceProblem sheet_pile_problem(const SheetPile& pile, int cells_x, int cells_y);

/// What is measured on one finite-volume solution.
struct SheetPileMeasures {
  double discharge = 0;           ///< q [m^2/s] under the pile tip (across x = L/2)
  double discharge_factor = 0;    ///< q / (K dh)
  std::vector<double> heads;      ///< h at the probe points [m]
  double exit_gradient_cell = 0;  ///< mean -dh/dy over the first cell downstream of the pile
                                  ///< (its top-face flux / (K dx)): tends to i(0) as dx -> 0
  double exit_gradient_mean = 0;  ///< mean -dh/dy over [L/2, L/2 + exit_width]
};

/// Solves the geometry on cells_x x cells_y cells and measures it.
SheetPileMeasures measure_sheet_pile(const SheetPile& pile, int cells_x, int cells_y,
                                     const std::vector<std::array<double, 2>>& probes,
                                     double exit_width);

/// The grid series base_x x base_y, 2x, 4x, ... (`levels`) of the measures; scalars in order:
/// "q/(K dh)", "h(x,y)" per probe, "i_exit cell", "i_exit mean".
GridSeries sheet_pile_series(const SheetPile& pile, int base_cells_x, int base_cells_y, int levels,
                             const std::vector<std::array<double, 2>>& probes, double exit_width);

}  // namespace porosph::validation
