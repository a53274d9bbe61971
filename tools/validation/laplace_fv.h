// Confined steady seepage on a rectangle by cell-centred finite volumes: the reference that the
// 2D SPH seepage cases are compared with (issue 30 item 5).
//
// Steady Darcy flow with a homogeneous conductivity K: q = -K grad h, div q = 0, so
//   div(K grad h) = 0   on [x0, x1] x [y0, y1],
// with per boundary segment either a fixed head h = h_b (Dirichlet) or no flow (the default), and
// thin impermeable barriers on cell faces (a sheet pile, a cut-off wall). N x M cells, the
// 5-point two-point-flux scheme: the flux through the face between cells a and b is
//   F_ab = K (h_a - h_b) A / d    (A the face length, d the centre distance),
// through a fixed-head boundary face F = K (h_cell - h_b) A / (d / 2), zero through a no-flow
// face or a barrier. The system (sum of face fluxes = 0 per cell) is symmetric positive definite
// when some face has a fixed head; it is solved by Eigen's SimplicialLDLT. The scheme is second
// order for smooth solutions; re-entrant corners (a barrier's tip: h ~ r^(1/2)) lower the
// observed order of global quantities to about 1 (grid_series.h estimates it).
#pragma once

#include <vector>

namespace porosph::validation {

/// A side of the rectangle.
enum class Side { kLeft, kRight, kBottom, kTop };

/// A fixed head h_b on the faces of `side` whose centres lie in [from, to] (x along the bottom
/// and top, y along the left and right side). Later segments override earlier ones.
struct FixedHeadSegment {
  Side side = Side::kTop;
  double from = 0.0, to = 0.0;
  double head = 0.0;  ///< [m]
};

/// A thin impermeable barrier on the grid line x = at (vertical) or y = at (horizontal), over
/// the faces whose centres lie in [from, to]. `at` must be a grid line (1e-6 of a cell).
struct Barrier {
  bool vertical = true;
  double at = 0.0;
  double from = 0.0, to = 0.0;
};

/// An impermeable solid of finite thickness inside the rectangle (a cut-off wall): the cells whose
/// centres lie in [x0, x1] x [y0, y1] are removed, every face they share is no-flow. Its edges must
/// be grid lines (1e-6 of a cell).
struct SolidBlock {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

/// The problem: rectangle, grid, conductivity, boundary segments, barriers, solid blocks.
struct LaplaceProblem {
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;  ///< [m]
  int cells_x = 10, cells_y = 10;
  double conductivity = 1.0;  ///< K [m/s]
  std::vector<FixedHeadSegment> fixed_heads;
  std::vector<Barrier> barriers;
  std::vector<SolidBlock> solids;
};

/// The solved head field and what is measured on it.
class LaplaceSolution {
 public:
  /// Head [m] at (x, y): bilinear in the cell-centre values, with the boundary-face values
  /// (h_b on a fixed-head face, the adjacent cell's head on a no-flow face, where dh/dn = 0)
  /// between the last centre and the boundary. Never interpolates across a barrier: a point on
  /// either side of one takes the value of its own side's cell (dh/dn = 0 there too); a point
  /// exactly on a barrier line counts as on its lower / left side.
  double head(double x, double y) const;
  /// The head of cell (i, j), i along x (NaN in a solid block).
  double cell_head(int i, int j) const { return head_[index(i, j)]; }

  /// Discharge per unit width [m^2/s] across the vertical line x = at, y in [from, to],
  /// positive towards +x: the sum of its face fluxes (faces whose centres lie in [from, to]);
  /// between grid lines, linear in x between the two neighbouring ones.
  double discharge_across_vertical(double at, double from, double to) const;
  /// The same across the horizontal line y = at, x in [from, to], positive towards +y.
  double discharge_across_horizontal(double at, double from, double to) const;

  /// Mean outward flux per unit K [-] through `side` over the stretch [from, to]: the sum of its
  /// boundary-face fluxes, each weighted by the fraction of the face inside the stretch, divided
  /// by K (to - from). On a fixed-head top face it is the mean upward gradient -dh/dy, the exit
  /// gradient (sheet_pile.h).
  double mean_outward_gradient(Side side, double from, double to) const;

  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }
  double cell_width() const { return dx_; }
  double cell_height() const { return dy_; }

 private:
  friend LaplaceSolution solve_laplace(const LaplaceProblem& problem);
  int index(int i, int j) const { return j * nx_ + i; }
  /// Flux [m^2/s] through vertical face i (0..nx, between cells i-1 and i) of row j, towards +x.
  double flux_x(int i, int j) const;
  /// Flux through horizontal face j (0..ny) of column i, towards +y.
  double flux_y(int i, int j) const;
  /// Head along row j (-1: the bottom edge, ny: the top edge) at x.
  double row_head(int j, double x) const;
  /// The value of a boundary face: h_b, or the adjacent cell's head when no-flow.
  double edge_value(Side side, int k) const;

  double x0_ = 0, y0_ = 0, dx_ = 1, dy_ = 1, k_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<double> head_;
  std::vector<char> blocked_x_;  ///< (nx + 1) * ny vertical faces, index j * (nx + 1) + i
  std::vector<char> blocked_y_;  ///< nx * (ny + 1) horizontal faces, index j * nx + i
  std::vector<double> left_, right_, bottom_, top_;  ///< fixed head per boundary face, NaN: none
};

/// Assembles and solves the problem. Throws std::invalid_argument for a barrier off the grid
/// lines, a solid block whose edges are not grid lines, a bad grid, or no fixed head at all (the
/// head would be undetermined).
LaplaceSolution solve_laplace(const LaplaceProblem& problem);

}  // namespace porosph::validation
