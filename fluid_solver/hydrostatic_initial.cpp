#include "fluid_solver/hydrostatic_initial.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "fluid_solver/water_bodies.h"

namespace porosph::water {
namespace {

/// Runs of one column break where consecutive centres are farther apart than this (spacings).
constexpr double kRunGapSpacings = 1.5;
/// A wall particle this close above a run's top (spacings, along g) covers the run.
constexpr double kCoverSpacings = 2.0;

/// D-1 unit vectors spanning the plane perpendicular to the unit vector `up`.
template <int D>
std::array<sph::Vec<D>, D - 1> perpendicular_basis(const sph::Vec<D>& up) {
  std::array<sph::Vec<D>, D - 1> basis;
  if constexpr (D == 2) {
    basis[0] = sph::Vec<D>(-up[1], up[0]);
  } else {
    int least = 0;  // the axis least aligned with up
    for (int k = 1; k < D; ++k)
      if (std::abs(up[k]) < std::abs(up[least])) least = k;
    const sph::Vec<D> axis = sph::Vec<D>::Unit(least);
    basis[0] = axis.cross(up).normalized();
    basis[1] = up.cross(basis[0]);
  }
  return basis;
}

/// The frame of the columns: height s along up, column key from the perpendicular coordinates.
template <int D>
struct ColumnFrame {
  sph::Vec<D> up;
  std::array<sph::Vec<D>, D - 1> basis;
  std::array<double, D - 1> t_min;  ///< bins anchored here, so lattice columns sit mid-bin
  double dp;

  std::array<long, D - 1> key(const sph::Vec<D>& x) const {
    std::array<long, D - 1> k;
    for (int d = 0; d < D - 1; ++d)
      k[d] = static_cast<long>(std::floor((x.dot(basis[d]) - t_min[d]) / dp + 0.5));
    return k;
  }
  double height(const sph::Vec<D>& x) const { return x.dot(up); }
};

/// True if a wall particle lies in the column of x (every perpendicular offset within dp/2) and
/// above x by less than kCoverSpacings dp.
template <int D>
bool covered(const sph::Vec<D>& x, const ColumnFrame<D>& f, const PointGrid<D>& grid,
             const sph::Vec<D>* walls) {
  bool found = false;
  grid.for_each_near(x, [&](std::size_t w) {
    const sph::Vec<D> r = walls[w] - x;
    const double above = r.dot(f.up);
    if (found || !(above > 0.0) || above >= kCoverSpacings * f.dp) return;
    for (int d = 0; d < D - 1; ++d)
      if (std::abs(r.dot(f.basis[d])) > 0.5 * f.dp * (1.0 + 1e-9)) return;
    found = true;
  });
  return found;
}

}  // namespace

template <int D>
void hydrostatic_state(const sph::Vec<D>* x, std::size_t n, const sph::Vec<D>* walls,
                       std::size_t n_walls, const sph::Vec<D>& gravity, double dp,
                       const TaitEos& eos, double* pressure, double* density) {
  const double g = gravity.norm();
  if (!(g > 0.0) || n == 0) {
    for (std::size_t i = 0; i < n; ++i) {
      pressure[i] = 0.0;
      density[i] = eos.rho0();
    }
    return;
  }
  ColumnFrame<D> f;
  f.up = -gravity / g;
  f.basis = perpendicular_basis<D>(f.up);
  f.dp = dp;
  f.t_min.fill(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < D - 1; ++d) f.t_min[d] = std::min(f.t_min[d], x[i].dot(f.basis[d]));

  std::size_t bodies = 0;
  const std::vector<std::int32_t> body = water_bodies<D>(x, n, dp, &bodies);
  std::vector<double> body_top(bodies, -std::numeric_limits<double>::infinity());
  std::vector<std::array<long, D - 1>> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    body_top[body[i]] = std::max(body_top[body[i]], f.height(x[i]));
    key[i] = f.key(x[i]);
  }
  // Particles grouped by (body, column), each group from the top down.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (body[a] != body[b]) return body[a] < body[b];
    if (key[a] != key[b]) return key[a] < key[b];
    const double sa = f.height(x[a]), sb = f.height(x[b]);
    return sa != sb ? sa > sb : a < b;
  });
  const PointGrid<D> wall_grid(walls, n_walls, (kCoverSpacings + 0.5) * dp);
  double level = 0.0, previous = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const double s = f.height(x[i]);
    const bool new_group = k == 0 || body[i] != body[order[k - 1]] || key[i] != key[order[k - 1]];
    if (new_group || previous - s > kRunGapSpacings * dp) {  // the top of a run
      const bool lid = n_walls > 0 && covered<D>(x[i], f, wall_grid, walls);
      level = (lid ? body_top[body[i]] : s) + 0.5 * dp;
    }
    previous = s;
    pressure[i] = eos.still_water_pressure(level - s, g);  // weakly compressible still water
    density[i] = eos.density(pressure[i]);
  }
}

template void hydrostatic_state<2>(const sph::Vec<2>*, std::size_t, const sph::Vec<2>*, std::size_t,
                                   const sph::Vec<2>&, double, const TaitEos&, double*, double*);
template void hydrostatic_state<3>(const sph::Vec<3>*, std::size_t, const sph::Vec<3>*, std::size_t,
                                   const sph::Vec<3>&, double, const TaitEos&, double*, double*);

}  // namespace porosph::water
