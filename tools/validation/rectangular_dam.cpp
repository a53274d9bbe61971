#include "tools/validation/rectangular_dam.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace porosph::validation {

double RectangularDam::charnyi_discharge() const {
  return conductivity * (head_upstream * head_upstream - head_downstream * head_downstream) /
         (2.0 * length);
}

double RectangularDam::dupuit_height(double x) const {
  const double h1 = head_upstream, h2 = head_downstream;
  return std::sqrt(std::max(0.0, h1 * h1 - (h1 * h1 - h2 * h2) * x / length));
}

namespace {

/// Baiocchi's boundary data w on the edge node (x, y) of the box (0, L) x (0, h1).
double boundary_w(const RectangularDam& d, double x, double y, bool left, bool right, bool base) {
  const double h1 = d.head_upstream, h2 = d.head_downstream;
  if (left) return 0.5 * (h1 - y) * (h1 - y);
  if (right) return y < h2 ? 0.5 * (h2 - y) * (h2 - y) : 0.0;
  if (base) return 0.5 * h1 * h1 - d.charnyi_discharge() * x / d.conductivity;
  return 0.0;  // the top y = h1 is dry
}

/// Where a profile f(k) (k = 0, 1, ..., spacing apart; f > 0 up to k = last, 0 beyond) that
/// vanishes quadratically reaches zero: the least-squares line through sqrt(f) at the three
/// nodes last - 1, last - 2, last - 3 (the last wet node itself is left out: the discrete
/// free boundary perturbs it most), extrapolated to zero. Fewer nodes near the start: mid-cell.
template <class Profile>
double surface_from_profile(int last, const Profile& f, double spacing) {
  if (last < 4) return (last + 0.5) * spacing;
  double sk = 0, ss = 0, skk = 0, sks = 0;
  for (int k = last - 3; k <= last - 1; ++k) {
    const double s = std::sqrt(f(k));
    sk += k, ss += s, skk += k * k, sks += k * s;
  }
  const double slope = (3 * sks - sk * ss) / (3 * skk - sk * sk), mean_k = sk / 3;
  if (slope >= 0.0) return (last + 0.5) * spacing;
  return (mean_k - (ss / 3) / slope) * spacing;
}

}  // namespace

double DamSolution::column_surface(int i) const {
  int top = 0;
  for (int j = 0; j <= ny_; ++j)
    if (w(i, j) > 0.0) top = j;
  return surface_from_profile(
      top, [&](int j) { return w(i, j); }, dy_);
}

double DamSolution::free_surface(double x) const {
  if (x <= 0.0) return dam_.head_upstream;
  const double s = std::min(x / dx_, static_cast<double>(nx_ - 1));
  const int i = std::min(static_cast<int>(std::floor(s)), nx_ - 2);
  const double left = i == 0 ? dam_.head_upstream : column_surface(i);
  return left + (s - i) * (column_surface(i + 1) - left);
}

double DamSolution::exit_height() const {
  // g(y) = -dw/dx at x = L (second order, one-sided; w = 0 on the face above h2) = Q(L, y) / K,
  // the outflow through the face above y, which vanishes like (h_s - y)^2 at the exit point.
  auto g = [&](int j) { return std::max(0.0, (4 * w(nx_ - 1, j) - w(nx_ - 2, j)) / (2 * dx_)); };
  int top = 0;
  for (int j = 0; j <= ny_; ++j)
    if (j * dy_ > dam_.head_downstream && g(j) > 0.0) top = j;
  return surface_from_profile(top, g, dy_);
}

double DamSolution::discharge(double x) const {
  const int i = std::clamp(static_cast<int>(std::lround(x / dx_)), 1, nx_ - 1);
  // h = y - dw/dy at the nodes of columns i - 1 and i + 1; one-sided at the base.
  auto head = [&](int c, int j) {
    const double dwdy = j == 0 ? (-3 * w(c, 0) + 4 * w(c, 1) - w(c, 2)) / (2 * dy_)
                               : (w(c, j + 1) - w(c, j - 1)) / (2 * dy_);
    return j * dy_ - dwdy;
  };
  double q = 0.0;
  for (int j = 0; j < ny_; ++j) {
    const double gradient = (head(i + 1, j) - head(i - 1, j)) / (2 * dx_);
    q += (j == 0 ? 0.5 : 1.0) * gradient * dy_;
  }
  return -dam_.conductivity * q;
}

DamSolution solve_rectangular_dam(const RectangularDam& dam, int cells_x, int cells_y) {
  if (cells_x < 2 || cells_y < 2 || !(dam.head_downstream >= 0.0) ||
      !(dam.head_downstream < dam.head_upstream) || !(dam.length > 0.0))
    throw std::invalid_argument("solve_rectangular_dam: bad dam or grid");
  DamSolution s;
  s.dam_ = dam, s.nx_ = cells_x, s.ny_ = cells_y;
  s.dx_ = dam.length / cells_x, s.dy_ = dam.head_upstream / cells_y;
  const int nx = cells_x, ny = cells_y, n = (nx - 1) * (ny - 1);
  const double ax = 1.0 / (s.dx_ * s.dx_), ay = 1.0 / (s.dy_ * s.dy_), diagonal = 2 * (ax + ay);
  s.w_.assign((nx + 1) * (ny + 1), 0.0);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      if (i == 0 || i == nx || j == 0 || j == ny)
        s.w_[j * (nx + 1) + i] = boundary_w(dam, i * s.dx_, j * s.dy_, i == 0, i == nx, j == 0);
  // A = -Laplace_h on the interior nodes, f = boundary contributions - 1: the problem is
  // w >= 0, lambda = A w - f >= 0, w lambda = 0.
  auto unknown = [&](int i, int j) { return (j - 1) * (nx - 1) + (i - 1); };
  Eigen::VectorXd f(n);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(5 * n);
  for (int j = 1; j < ny; ++j)
    for (int i = 1; i < nx; ++i) {
      const int k = unknown(i, j);
      f[k] = -1.0;
      entries.emplace_back(k, k, diagonal);
      const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
      for (int e = 0; e < 4; ++e) {
        const int a = i + di[e], b = j + dj[e];
        const double c = e < 2 ? ax : ay;
        if (a == 0 || a == nx || b == 0 || b == ny)
          f[k] += c * s.w_[b * (nx + 1) + a];
        else
          entries.emplace_back(k, unknown(a, b), -c);
      }
    }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  // Primal-dual active set: start with every node wet (no constraint), then w = 0 on the active
  // set {lambda - c w > 0} and A w = f on the rest, until the active set repeats.
  std::vector<char> active(n, 0), next(n, 0);
  Eigen::VectorXd wv = Eigen::VectorXd::Zero(n);
  for (int step = 1; step <= 500; ++step) {
    std::vector<int> map(n, -1), wet;
    for (int k = 0; k < n; ++k)
      if (!active[k]) map[k] = static_cast<int>(wet.size()), wet.push_back(k);
    std::vector<Eigen::Triplet<double>> reduced;
    reduced.reserve(entries.size());
    for (const auto& t : entries)
      if (map[t.row()] >= 0 && map[t.col()] >= 0)
        reduced.emplace_back(map[t.row()], map[t.col()], t.value());
    const int m = static_cast<int>(wet.size());
    Eigen::SparseMatrix<double> aw(m, m);
    aw.setFromTriplets(reduced.begin(), reduced.end());
    Eigen::VectorXd fw(m);
    for (int r = 0; r < m; ++r) fw[r] = f[wet[r]];
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(aw);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("solve_rectangular_dam: factorisation failed");
    const Eigen::VectorXd ww = solver.solve(fw);
    wv.setZero();
    for (int r = 0; r < m; ++r) wv[wet[r]] = ww[r];
    const Eigen::VectorXd lambda = a * wv - f;
    for (int k = 0; k < n; ++k) next[k] = (active[k] ? lambda[k] : -diagonal * wv[k]) > 0.0;
    s.iterations_ = step;
    if (next == active) {
      for (int j = 1; j < ny; ++j)
        for (int i = 1; i < nx; ++i) s.w_[j * (nx + 1) + i] = wv[unknown(i, j)];
      return s;
    }
    active.swap(next);
  }
  throw std::runtime_error("solve_rectangular_dam: the active set did not settle in 500 steps");
}

GridSeries rectangular_dam_series(const RectangularDam& dam, int base_cells_x, int base_cells_y,
                                  int levels, const std::vector<double>& surface_fractions) {
  std::vector<std::string> names;
  for (double f : surface_fractions) names.push_back("phi(" + std::to_string(f).substr(0, 4) + ")");
  names.insert(names.end(), {"h_s", "q/q_charnyi"});
  return run_grid_series(names, levels, [&](int r) {
    const DamSolution s = solve_rectangular_dam(dam, r * base_cells_x, r * base_cells_y);
    std::vector<double> v;
    for (double f : surface_fractions) v.push_back(s.free_surface(f * dam.length));
    v.push_back(s.exit_height());
    v.push_back(s.discharge(0.5 * dam.length) / dam.charnyi_discharge());
    return v;
  });
}

}  // namespace porosph::validation
