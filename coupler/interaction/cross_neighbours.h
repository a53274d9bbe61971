// Soil-water neighbour search of the coupler: a cell list over the soil overlap particles, queried
// with each water overlap particle (DESIGN.md section 1, step 3). O(N): cells of size >= the kernel
// support, so a query scans at most 3^D cells. The grid covers the soil's bounding box on
// non-periodic axes and the domain box on periodic ones, where displacements follow the minimum
// image (sph::DomainBox) and every pair is found exactly once, also when the periodic axis holds
// fewer than 3 cells. Buffers are reused: no allocation in steady state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/cell_grid.h"
#include "sph/domain_box.h"
#include "sph/vector.h"

namespace porosph::coupler {

template <int D>
class CrossNeighbours {
 public:
  /// Sorts the `n` soil particles at `positions` (flattened, n x D) into cells of size >=
  /// `support`. Non-finite coordinates are tolerated (such a particle has no neighbours).
  void build(const double* positions, std::size_t n, double support, const sph::DomainBox<D>& box);

  std::size_t size() const { return order_.size(); }
  double support() const { return support_; }
  /// Slot -> index into the arrays given to build(); slots are ordered by cell.
  const std::vector<std::int32_t>& order() const { return order_; }

  /// Calls visit(slot, x_ws, r) for every soil particle within r < support of the point `x`
  /// (a water particle), with x_ws = x - x_soil (minimum image) and r = |x_ws|.
  template <class Visit>
  void for_each_within(sph::Vec<D> x, Visit&& visit) const;

 private:
  void setup_grid(const double* positions, std::size_t n);

  double support_ = 0.0;
  sph::DomainBox<D> box_;
  sph::CellGrid<D> grid_;
  std::vector<std::int64_t> cell_of_particle_;
  std::vector<std::int32_t> cell_start_;  ///< per cell + 1: first slot of the cell
  std::vector<std::int32_t> order_;
  std::vector<sph::Vec<D>> sorted_position_;
};

template <int D>
template <class Visit>
void CrossNeighbours<D>::for_each_within(sph::Vec<D> x, Visit&& visit) const {
  if (order_.empty() || !x.allFinite()) return;
  box_.wrap(x);
  // Per axis the distinct cell coordinates to scan (1 to 3 of them).
  std::int64_t axis_cells[D][3];
  int axis_count[D];
  for (int k = 0; k < D; ++k) {
    const std::int64_t nk = grid_.cells_per_axis[k];
    const double s = (x[k] - grid_.origin[k]) * grid_.inv_cell_size[k];
    int m = 0;
    if (box_.periodic[k]) {
      const std::int64_t c = std::min<std::int64_t>(
          nk - 1, std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(s))));
      if (nk >= 3) {
        axis_cells[k][m++] = (c + nk - 1) % nk;
        axis_cells[k][m++] = c;
        axis_cells[k][m++] = (c + 1) % nk;
      } else {
        for (std::int64_t j = 0; j < nk; ++j) axis_cells[k][m++] = j;
      }
    } else {
      // More than one cell outside the grid: no soil particle within the support.
      if (!(s >= -1.0) || !(s < static_cast<double>(nk) + 1.0)) return;
      const std::int64_t c = static_cast<std::int64_t>(std::floor(s));
      for (std::int64_t j = std::max<std::int64_t>(0, c - 1); j <= std::min(nk - 1, c + 1); ++j) {
        axis_cells[k][m++] = j;
      }
    }
    if (m == 0) return;
    axis_count[k] = m;
  }
  const double support2 = support_ * support_;
  int index[D] = {};
  for (;;) {
    std::int64_t cell = 0, stride = 1;
    for (int k = 0; k < D; ++k) {
      cell += axis_cells[k][index[k]] * stride;
      stride *= grid_.cells_per_axis[k];
    }
    for (std::int32_t slot = cell_start_[cell]; slot < cell_start_[cell + 1]; ++slot) {
      sph::Vec<D> dx = x - sorted_position_[slot];
      box_.minimum_image(dx);
      const double r2 = dx.squaredNorm();
      if (r2 < support2) visit(slot, dx, std::sqrt(r2));
    }
    int k = 0;
    while (k < D && ++index[k] == axis_count[k]) index[k++] = 0;
    if (k == D) break;
  }
}

extern template class CrossNeighbours<2>;
extern template class CrossNeighbours<3>;

}  // namespace porosph::coupler
