#include "coupler/interaction/cross_neighbours.h"

#include <algorithm>
#include <limits>

namespace porosph::coupler {

template <int D>
void CrossNeighbours<D>::build(const double* positions, std::size_t n, double support,
                               const sph::DomainBox<D>& box) {
  support_ = support;
  box_ = box;
  order_.resize(n);
  sorted_position_.resize(n);
  cell_of_particle_.resize(n);
  if (n == 0) return;
  setup_grid(positions, n);
  std::int64_t cell_count = 1;
  for (int k = 0; k < D; ++k) cell_count *= cells_per_axis_[k];
  // Counting sort by cell (stable: a cell keeps the input order of its particles).
  cell_start_.assign(static_cast<std::size_t>(cell_count) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    sph::Vec<D> x = Eigen::Map<const sph::Vec<D>>(positions + i * D);
    box_.wrap(x);
    cell_of_particle_[i] = cell_of(x);
    ++cell_start_[cell_of_particle_[i] + 1];
  }
  for (std::int64_t c = 0; c < cell_count; ++c) cell_start_[c + 1] += cell_start_[c];
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t slot = cell_start_[cell_of_particle_[i]]++;
    order_[slot] = static_cast<std::int32_t>(i);
    sorted_position_[slot] = Eigen::Map<const sph::Vec<D>>(positions + i * D);
    box_.wrap(sorted_position_[slot]);
  }
  // The cursors advanced each start to the next cell's start: shift back by one cell.
  for (std::int64_t c = cell_count; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

template <int D>
void CrossNeighbours<D>::setup_grid(const double* positions, std::size_t n) {
  sph::Vec<D> lo = sph::Vec<D>::Constant(std::numeric_limits<double>::infinity());
  sph::Vec<D> hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      const double v = positions[i * D + k];
      if (!std::isfinite(v)) continue;
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    }
  }
  // Cell size >= support; grown when a sparse soil set in a large box would give far more cells
  // than particles (that only adds candidate checks, never misses a pair).
  const double max_cells = std::max(64.0, 4.0 * static_cast<double>(n));
  double cell = support_;
  for (int attempt = 0; attempt < 64; ++attempt) {
    double total = 1.0;
    for (int k = 0; k < D; ++k) {
      std::int64_t nk = 1;
      if (box_.periodic[k]) {
        origin_[k] = box_.min[k];
        nk = std::max<std::int64_t>(1, static_cast<std::int64_t>(box_.length(k) / cell));
        inv_cell_size_[k] = static_cast<double>(nk) / box_.length(k);
      } else {
        if (!(lo[k] <= hi[k])) lo[k] = hi[k] = 0.0;  // no finite coordinate at all
        origin_[k] = lo[k];
        nk = static_cast<std::int64_t>((hi[k] - lo[k]) / cell) + 1;
        inv_cell_size_[k] = 1.0 / cell;
      }
      cells_per_axis_[k] = nk;
      total *= static_cast<double>(nk);
    }
    if (total <= max_cells) break;
    cell *= 1.5;
  }
}

template <int D>
std::int64_t CrossNeighbours<D>::cell_of(const sph::Vec<D>& x) const {
  std::int64_t linear = 0, stride = 1;
  for (int k = 0; k < D; ++k) {
    const double s = (x[k] - origin_[k]) * inv_cell_size_[k];
    const std::int64_t nk = cells_per_axis_[k];
    std::int64_t c = 0;  // clamped: round-off at the upper face, non-finite coordinates -> 0
    if (s >= static_cast<double>(nk)) {
      c = nk - 1;
    } else if (s > 0.0) {
      c = static_cast<std::int64_t>(s);
    }
    linear += c * stride;
    stride *= nk;
  }
  return linear;
}

template class CrossNeighbours<2>;
template class CrossNeighbours<3>;

}  // namespace porosph::coupler
