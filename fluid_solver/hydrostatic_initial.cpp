#include "fluid_solver/hydrostatic_initial.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace porosph::fluid {
namespace {

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

}  // namespace

template <int D>
void hydrostatic_state(const sph::Vec<D>* x, std::size_t n, const sph::Vec<D>& gravity, double dp,
                       const TaitEos& eos, double* pressure, double* density) {
  const double g = gravity.norm();
  if (!(g > 0.0) || n == 0) {
    for (std::size_t i = 0; i < n; ++i) {
      pressure[i] = 0.0;
      density[i] = eos.rho0();
    }
    return;
  }
  const sph::Vec<D> up = -gravity / g;
  const auto basis = perpendicular_basis<D>(up);
  // Bins anchored at the smallest perpendicular coordinate, so that lattice columns sit mid-bin.
  std::array<double, D - 1> t_min;
  t_min.fill(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D - 1; ++k) t_min[k] = std::min(t_min[k], x[i].dot(basis[k]));
  using Key = std::array<long, D - 1>;
  std::vector<Key> key(n);
  std::map<Key, double> top;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D - 1; ++k) {
      key[i][k] = static_cast<long>(std::floor((x[i].dot(basis[k]) - t_min[k]) / dp + 0.5));
    }
    const double s = x[i].dot(up);
    auto [it, inserted] = top.try_emplace(key[i], s);
    if (!inserted) it->second = std::max(it->second, s);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double s_top = top[key[i]] + 0.5 * dp;
    pressure[i] = eos.rho0() * g * (s_top - x[i].dot(up));
    density[i] = eos.density(pressure[i]);
  }
}

template void hydrostatic_state<2>(const sph::Vec<2>*, std::size_t, const sph::Vec<2>&, double,
                                   const TaitEos&, double*, double*);
template void hydrostatic_state<3>(const sph::Vec<3>*, std::size_t, const sph::Vec<3>&, double,
                                   const TaitEos&, double*, double*);

}  // namespace porosph::fluid
