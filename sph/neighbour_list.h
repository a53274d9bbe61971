// Cell-list neighbour search, O(N), with CSR-style neighbour lists built once per step and reused
// by every particle loop of that step.
//
// Particles [0, n_free) are free, [n_free, n) fixed (walls). The list of a free particle holds its
// free neighbours first, then its fixed ones ([begin, mid) and [mid, end)); the list of a fixed
// particle holds only its free neighbours (fixed-fixed pairs are never needed). A particle is not
// its own neighbour. Every pair (a, b) with r_ab < support appears in the list of a (and of b),
// with the displacement x_ab = x_a - x_b (minimum image on periodic axes) and r_ab = |x_ab|.
//
// Build: the grid covers the particles' bounding box on non-periodic axes and the domain box on
// periodic ones; cell size >= support so a 3^D stencil suffices; particles are counting-sorted by
// cell (free before fixed within a cell); OpenMP threads take chunks of particles dynamically and
// append their lists to their own buffer (one distance pass, no atomics, no copy). All buffers are
// reused: no allocation in steady state.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/cell_grid.h"
#include "sph/domain_box.h"
#include "sph/vector.h"

namespace porosph::sph {

template <int D>
struct NeighbourPair {
  Vec<D> x_ab;     ///< x_a - x_b [m] (minimum image)
  double r;        ///< |x_ab| [m]
  std::int32_t b;  ///< neighbour index
};

template <int D>
class NeighbourList {
 public:
  using Pair = NeighbourPair<D>;

  /// Builds the lists of the n particles at x (first n_free free). Positions must lie inside the
  /// box along periodic axes (wrapped). Non-finite positions are tolerated (they get no neighbours
  /// beyond chance) so that the caller can report them.
  void build(const Vec<D>* x, std::size_t n, std::size_t n_free, double support,
             const DomainBox<D>& box);

  std::size_t size() const { return n_; }
  std::size_t free_size() const { return n_free_; }
  std::size_t pair_count() const { return pair_count_; }
  /// Mean number of neighbours (free and fixed) of a free particle: the figure SPH throughput is
  /// compared by. O(n_free).
  double neighbours_per_free_particle() const {
    if (n_free_ == 0) return 0.0;
    std::size_t entries = 0;
    for (std::size_t a = 0; a < n_free_; ++a)
      entries += static_cast<std::size_t>(end_[a] - begin_[a]);
    return static_cast<double>(entries) / static_cast<double>(n_free_);
  }
  double support() const { return support_; }

  /// All neighbours of a: [begin(a), end(a)); free ones [begin(a), mid(a)), fixed [mid(a), end(a)).
  const Pair* begin(std::size_t a) const { return begin_[a]; }
  const Pair* mid(std::size_t a) const { return mid_[a]; }
  const Pair* end(std::size_t a) const { return end_[a]; }

  /// Every particle index ordered by cell (axis 0 fastest), free before fixed within a cell.
  const std::vector<std::int32_t>& cell_order() const { return sorted_index_; }

 private:
  void setup_grid(const Vec<D>* x);
  void sort_into_cells(const Vec<D>* x);
  template <bool kPeriodic>
  void fill_lists(const Vec<D>* x);
  int stencil_of(std::int64_t cell, std::int64_t* out) const;

  std::size_t n_ = 0, n_free_ = 0, pair_count_ = 0;
  double support_ = 0;
  DomainBox<D> box_;
  // grid
  CellGrid<D> grid_;
  // counting sort
  std::vector<std::int64_t> cell_of_;                     ///< per particle
  std::vector<std::int32_t> cell_start_;                  ///< per cell + 1, into sorted arrays
  std::vector<std::int32_t> cell_free_end_;               ///< per cell: end of its free particles
  std::vector<std::vector<std::int32_t>> thread_counts_;  ///< per thread: counts, then cursors
  std::vector<std::int32_t> sorted_index_;
  std::vector<Vec<D>> sorted_position_;
  // lists
  std::vector<std::vector<Pair>> buffers_;  ///< one per thread
  std::vector<std::uint32_t> offsets_;      ///< scratch: 3 per particle, offsets in its buffer
  std::vector<int> chunk_owner_;            ///< thread whose buffer holds a chunk's lists
  std::vector<const Pair*> begin_, mid_, end_;
};

extern template class NeighbourList<2>;
extern template class NeighbourList<3>;

}  // namespace porosph::sph
