// Soil-water neighbour search of the coupler (docs/design.md section 1, step 3): for each water
// overlap particle, the soil overlap particles within the kernel support. O(N): a cell list over
// the soil (cells of size >= support + skin, so a query scans at most 3^D cells), queried with each
// water particle. The grid covers the soil's bounding box on non-periodic axes and the domain box
// on periodic ones, where displacements follow the minimum image (sph::DomainBox) and every pair is
// found exactly once, also when the periodic axis holds fewer than 3 cells.
//
// Verlet skin (as sph/neighbour_list.h): the cell search collects, per water particle, the soil
// particles within support + skin (candidates); later steps reuse them while both overlap sets
// hold the same particles in the same order (ids) and none moved more than skin/2 since; the
// caller evaluates the candidates' current distances. Candidates are in soil index order, so the
// sums over them do not depend on the step of the last search (a resumed run sums like an
// uninterrupted one). Buffers are reused: no allocation in steady state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/cell_grid.h"
#include "sph/domain_box.h"
#include "sph/vector.h"

namespace porosph::coupler {

/// One overlap set as the coupler received it: ids and flattened positions (n x D).
struct OverlapPoints {
  const std::int64_t* id = nullptr;
  const double* position = nullptr;
  std::size_t size = 0;
};

template <int D>
class CrossNeighbours {
 public:
  /// Skin [m] (>= 0; 0: a cell search every step).
  void set_skin(double skin) {
    skin_ = skin > 0.0 ? skin : 0.0;
    searched_ = false;
  }

  /// Makes the candidates current for these soil and water sets (a cell search when needed).
  /// Non-finite coordinates are tolerated (such a particle has no neighbours).
  void update(const OverlapPoints& soil, const OverlapPoints& water, double support,
              const sph::DomainBox<D>& box);

  std::size_t soil_size() const { return soil_count_; }
  double support() const { return support_; }
  /// Cell searches so far (the other update() calls reused the candidates).
  std::uint64_t search_count() const { return search_count_; }

  /// The candidate soil particles of water particle `a`: indices into the soil set, ascending.
  /// Every soil particle within r < support is one; so are a few up to support + skin (kernels
  /// vanish there, and the caller counts pairs with r < support()).
  const std::int32_t* candidates(std::size_t a) const {
    return candidate_.data() + candidate_start_[a];
  }
  std::size_t candidate_count(std::size_t a) const {
    return static_cast<std::size_t>(candidate_start_[a + 1] - candidate_start_[a]);
  }
  /// The largest candidate_count() of the last search.
  std::size_t max_candidate_count() const { return max_candidate_count_; }

 private:
  bool needs_search(const OverlapPoints& soil, const OverlapPoints& water, double support,
                    const sph::DomainBox<D>& box) const;
  void search(const OverlapPoints& soil, const OverlapPoints& water);
  void setup_grid(const double* positions, std::size_t n);
  template <class Collect>
  void scan_cells(sph::Vec<D> x, Collect&& collect) const;

  double support_ = 0.0, skin_ = 0.0;
  sph::DomainBox<D> box_;
  bool searched_ = false;
  std::uint64_t search_count_ = 0;
  std::size_t soil_count_ = 0;
  std::size_t max_candidate_count_ = 0;
  // the last search
  std::vector<std::int64_t> searched_soil_id_, searched_water_id_;
  std::vector<double> searched_soil_position_, searched_water_position_;
  sph::CellGrid<D> grid_;
  std::vector<std::int64_t> cell_of_particle_;
  std::vector<std::int32_t> cell_start_;  ///< per cell + 1: first slot of the cell
  std::vector<std::int32_t> order_;       ///< slot -> soil index
  std::vector<sph::Vec<D>> sorted_position_;
  std::vector<std::int32_t> candidate_start_;  ///< per water particle + 1
  std::vector<std::int32_t> candidate_;        ///< soil indices, ascending per water particle
};

template <int D>
template <class Collect>
void CrossNeighbours<D>::scan_cells(sph::Vec<D> x, Collect&& collect) const {
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
      // More than one cell outside the grid: no soil particle within reach.
      if (!(s >= -1.0) || !(s < static_cast<double>(nk) + 1.0)) return;
      const std::int64_t c = static_cast<std::int64_t>(std::floor(s));
      for (std::int64_t j = std::max<std::int64_t>(0, c - 1); j <= std::min(nk - 1, c + 1); ++j) {
        axis_cells[k][m++] = j;
      }
    }
    if (m == 0) return;
    axis_count[k] = m;
  }
  const double reach = support_ + skin_, reach2 = reach * reach;
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
      if (dx.squaredNorm() < reach2) collect(order_[slot]);
    }
    int k = 0;
    while (k < D && ++index[k] == axis_count[k]) index[k++] = 0;
    if (k == D) break;
  }
}

extern template class CrossNeighbours<2>;
extern template class CrossNeighbours<3>;

}  // namespace porosph::coupler
