// Unconfined steady seepage through a rectangular homogeneous dam: the free (phreatic) surface by
// Baiocchi's transformation (Baiocchi, "Su un problema di frontiera libera connesso a questioni
// di idraulica", Ann. Mat. Pura Appl. 92, 1972; Baiocchi, C. R. Acad. Sci. Paris 273, 1971; Crank,
// "Free and Moving Boundary Problems", Oxford 1984, sec. 2.3.1 and 8.5), the reference that the
// 2D SPH dam cases are compared with (issue 30 item 5).
//
// The dam: 0 < x < L on an impermeable base y = 0, water at the level h1 against its left face,
// h2 < h1 against its right face, a seepage face above h2 on the right (h = y there). The head h
// is harmonic in the wet region under the free surface y = phi(x), where h = y and dh/dn = 0.
// Baiocchi's function
//   w(x, y) = int_y^phi(x) (h(x, t) - t) dt   (y < phi(x)),   w = 0 above phi,
// satisfies Laplace w = 1 where w > 0 and the linear complementarity problem
//   w >= 0,   1 - Laplace w >= 0,   w (1 - Laplace w) = 0   on (0, L) x (0, h1),
// with data that are known on the whole boundary:
//   w(0, y) = (h1 - y)^2 / 2,   w(L, y) = (h2 - y)^2 / 2 for y < h2 and 0 above,   w(x, h1) = 0,
//   w(x, 0) = h1^2 / 2 - q x / K   with   q = K (h1^2 - h2^2) / (2 L),
// the discharge of Dupuit and Charnyi (Charnyi 1951: exact, whatever the free surface's shape;
// Polubarinova-Kochina, "Theory of Ground Water Movement", 1962, ch. VII). The free surface is
// the boundary of {w > 0}; it is not Dupuit's parabola h1^2 - (h1^2 - h2^2) x / L, which lies
// below it and ends at h2 where the real surface ends at the exit point h_s > h2 on the face.
//
// Discretisation: nodes (i dx, j dy), 5-point Laplacian; the discrete complementarity problem is
// solved exactly by a primal-dual active set method (Hintermueller, Ito & Kunisch, SIAM J. Optim.
// 13, 2003; an M-matrix: it converges monotonically, in finitely many steps), each step a sparse
// Cholesky (Eigen SimplicialLDLT) on the wet nodes: no relaxation tolerance in the result.
#pragma once

#include <vector>

#include "tools/validation/grid_series.h"

namespace porosph::validation {

/// The dam's geometry, water levels and conductivity.
struct RectangularDam {
  double length = 0.4;            ///< L [m]
  double head_upstream = 0.3;     ///< h1 [m], also the height of the computed box
  double head_downstream = 0.05;  ///< h2 [m], 0 <= h2 < h1
  double conductivity = 1.0;      ///< K [m/s]

  /// q = K (h1^2 - h2^2) / (2 L) [m^2/s], Dupuit-Charnyi, exact.
  double charnyi_discharge() const;
  /// Dupuit's parabola sqrt(h1^2 - (h1^2 - h2^2) x / L) [m] (below the real free surface).
  double dupuit_height(double x) const;
};

/// Baiocchi's w on the (cells_x + 1) x (cells_y + 1) nodes and what is measured on it.
class DamSolution {
 public:
  /// w at node (i, j) [m^2].
  double w(int i, int j) const { return w_[j * (nx_ + 1) + i]; }
  /// The free-surface height phi [m] at x: per node column, the top wet node j (w > 0) and the
  /// linear extrapolation to zero of sqrt(w) from the nodes j and j - 1 (near the surface
  /// w ~ (phi - y)^2: sqrt(w) is linear there); linear in x between columns. phi(0) = h1.
  double free_surface(double x) const;
  /// The exit point h_s [m]: the top of the seepage face, the limit of phi(x) at x = L, from the
  /// columns next to the face (see the definition in rectangular_dam.cpp).
  double exit_height() const;
  /// Discharge per unit width [m^2/s] across the node column nearest x, from the head h = y -
  /// dw/dy: q = -K int_0^phi dh/dx dy (central differences, trapezoidal rule over the wet nodes).
  double discharge(double x) const;
  /// The number of active-set steps the solve took.
  int iterations() const { return iterations_; }
  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }

 private:
  friend DamSolution solve_rectangular_dam(const RectangularDam& dam, int cells_x, int cells_y);
  /// phi at node column i (0 < i < nx).
  double column_surface(int i) const;

  RectangularDam dam_;
  int nx_ = 0, ny_ = 0, iterations_ = 0;
  double dx_ = 0, dy_ = 0;
  std::vector<double> w_;
};

/// Solves the complementarity problem on cells_x x cells_y cells (dx = L / cells_x, dy = h1 /
/// cells_y). Throws std::runtime_error if the active set does not settle in 500 steps.
DamSolution solve_rectangular_dam(const RectangularDam& dam, int cells_x, int cells_y);

/// The grid series base_x x base_y, 2x, 4x, ... (`levels`): phi at each x / L of
/// `surface_fractions` ("phi(x/L)"), the exit point ("h_s"), the discharge at L / 2 over
/// Charnyi's ("q/q_charnyi").
GridSeries rectangular_dam_series(const RectangularDam& dam, int base_cells_x, int base_cells_y,
                                  int levels, const std::vector<double>& surface_fractions);

}  // namespace porosph::validation
