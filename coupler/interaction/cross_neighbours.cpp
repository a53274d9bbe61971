#include "coupler/interaction/cross_neighbours.h"

#include <algorithm>
#include <cmath>
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
  const std::int64_t cell_count = grid_.cell_count;
  // Counting sort by cell (stable: a cell keeps the input order of its particles).
  cell_start_.assign(static_cast<std::size_t>(cell_count) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    sph::Vec<D> x = Eigen::Map<const sph::Vec<D>>(positions + i * D);
    box_.wrap(x);
    cell_of_particle_[i] = grid_.cell_of(x);
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
  grid_.lay_out(lo, hi, support_, box_, n);
}

template class CrossNeighbours<2>;
template class CrossNeighbours<3>;

}  // namespace porosph::coupler
