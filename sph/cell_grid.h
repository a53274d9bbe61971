// The uniform grid of a cell-list neighbour search (sph/neighbour_list.h, and the coupler's
// soil-water search coupler/interaction/cross_neighbours.h): cells of size >= the kernel support
// over the particles' bounding box, or over the domain on periodic axes, so that a 3^D stencil
// finds every pair.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "sph/domain_box.h"
#include "sph/vector.h"

namespace porosph::sph {

template <int D>
struct CellGrid {
  Vec<D> origin = Vec<D>::Zero();
  Vec<D> inv_cell_size = Vec<D>::Ones();
  std::int64_t cells_per_axis[D] = {};
  std::int64_t cell_count = 0;

  /// Lays the grid over [lo, hi] (the finite bounding box of `n` particles; an axis with lo > hi
  /// has no finite coordinate and gets one cell) and over the domain on the periodic axes of
  /// `box`. The cell size starts at `support` and grows while the grid would have far more cells
  /// than particles (sparse particles in a large box): that only adds candidate checks, never
  /// misses a pair.
  void lay_out(Vec<D> lo, Vec<D> hi, double support, const DomainBox<D>& box, std::size_t n) {
    const double max_cells = std::max(64.0, 4.0 * static_cast<double>(n));
    double cell = support;
    for (int attempt = 0; attempt < 64; ++attempt) {
      double total = 1.0;
      for (int k = 0; k < D; ++k) {
        std::int64_t nk = 1;
        if (box.periodic[k]) {
          origin[k] = box.min[k];
          nk = std::max<std::int64_t>(1, static_cast<std::int64_t>(box.length(k) / cell));
          inv_cell_size[k] = static_cast<double>(nk) / box.length(k);
        } else {
          if (!(lo[k] <= hi[k])) lo[k] = hi[k] = 0.0;  // no finite coordinate at all
          origin[k] = lo[k];
          nk = static_cast<std::int64_t>((hi[k] - lo[k]) / cell) + 1;
          inv_cell_size[k] = 1.0 / cell;
        }
        cells_per_axis[k] = nk;
        total *= static_cast<double>(nk);
      }
      if (total <= max_cells) break;
      cell *= 1.5;
    }
    cell_count = 1;
    for (int k = 0; k < D; ++k) cell_count *= cells_per_axis[k];
  }

  /// Linear index of the cell holding x. Clamped: stray or non-finite coordinates land in the
  /// grid (cell 0 for NaN); adjacent cells stay adjacent.
  std::int64_t cell_of(const Vec<D>& x) const {
    std::int64_t linear = 0, stride = 1;
    for (int k = 0; k < D; ++k) {
      const double s = (x[k] - origin[k]) * inv_cell_size[k];
      const std::int64_t nk = cells_per_axis[k];
      std::int64_t c = 0;
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
};

}  // namespace porosph::sph
