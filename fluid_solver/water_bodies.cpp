#include "fluid_solver/water_bodies.h"

#include <cmath>
#include <numeric>

namespace porosph::water {
namespace {

/// Union-find root of i, with path halving.
std::size_t root_of(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

template <int D>
PointGrid<D>::PointGrid(const sph::Vec<D>* x, std::size_t n, double cell) : cell_(cell) {
  cells_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) cells_[key_of(x[i])].push_back(i);
}

template <int D>
typename PointGrid<D>::Key PointGrid<D>::key_of(const sph::Vec<D>& x) const {
  Key k;
  for (int d = 0; d < D; ++d) k[d] = static_cast<std::int64_t>(std::floor(x[d] / cell_));
  return k;
}

template <int D>
std::vector<std::int32_t> water_bodies(const sph::Vec<D>* x, std::size_t n, double dp,
                                       std::size_t* count) {
  const double link = kBodyLinkSpacings * dp;
  const PointGrid<D> grid(x, n, link);
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < n; ++i) {
    grid.for_each_near(x[i], [&](std::size_t j) {
      if (j <= i || (x[j] - x[i]).squaredNorm() > link * link) return;
      const std::size_t a = root_of(parent, i), b = root_of(parent, j);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    });
  }
  // Bodies numbered in the order of their first particle.
  std::vector<std::int32_t> body(n, -1), label_of_root(n, -1);
  std::int32_t bodies = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root_of(parent, i);
    if (label_of_root[r] < 0) label_of_root[r] = bodies++;
    body[i] = label_of_root[r];
  }
  if (count != nullptr) *count = static_cast<std::size_t>(bodies);
  return body;
}

template class PointGrid<2>;
template class PointGrid<3>;
template std::vector<std::int32_t> water_bodies<2>(const sph::Vec<2>*, std::size_t, double,
                                                   std::size_t*);
template std::vector<std::int32_t> water_bodies<3>(const sph::Vec<3>*, std::size_t, double,
                                                   std::size_t*);

}  // namespace porosph::water
