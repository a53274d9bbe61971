// Cell-list neighbour search, O(N), with CSR-style neighbour lists built once per step and reused
// by every particle loop of that step.
//
// Verlet skin (set_skin, Verlet 1967; the "neighbour list with skin" of molecular dynamics): the
// cell search runs only when some particle has moved more than skin/2 since the last search, and
// then collects every index pair closer than support + skin (candidates, 4 bytes each). In
// between, build() only refreshes the pair lists from the candidates at the current positions
// (x_ab, r, kept when r < support): the same pairs a full search would find, since no pair can
// close more than skin. A search also runs when the particle count, the support or the box
// changed, and after invalidate(). Each list is in index order, free then fixed neighbours: the
// lists, and every sum over them, do not depend on the step of the last search (a resumed run
// sums in the same order as an uninterrupted one).
//
// Particles [0, n_free) are free, [n_free, n) fixed (walls). The list of a free particle holds its
// free neighbours first, then its fixed ones ([begin, mid) and [mid, end)); the list of a fixed
// particle holds only its free neighbours (fixed-fixed pairs are never needed). A particle is not
// its own neighbour. Every pair (a, b) with r_ab < support appears in the list of a (and of b),
// with the displacement x_ab = x_a - x_b (minimum image on periodic axes) and r_ab = |x_ab|.
//
// Search: the grid covers the particles' bounding box on non-periodic axes and the domain box on
// periodic ones; cell size >= support + skin so a 3^D stencil suffices; particles are
// counting-sorted by cell (free before fixed within a cell); OpenMP threads take chunks of
// particles dynamically and append their candidates, then (refresh) their lists, to their own
// buffer (no atomics, no copy). All buffers are reused: no allocation in steady state.
//
// Occluders (set_occluders, sph/wall_occluders.h): the pairs that a thin wall hides are left out
// of the lists at every build, from the current positions and the particles' wall side tags.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "sph/cell_grid.h"
#include "sph/domain_box.h"
#include "sph/vector.h"
#include "sph/wall_occluders.h"

namespace porosph::sph {

/// The solvers' skin as a fraction of the support: measured on the dam break (docs/performance.md),
/// the list is searched every few steps at the fastest flow while each refresh handles ~1.2x the
/// pairs (the candidates within 1.1 support).
inline constexpr double kSolverSkinFraction = 0.1;

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
  /// `wall_tag` (n entries, wall_side_tag; null: all 0) is read only with occluders set.
  void build(const Vec<D>* x, std::size_t n, std::size_t n_free, double support,
             const DomainBox<D>& box, const std::int32_t* wall_tag = nullptr);

  /// The thin walls whose hidden pairs build() leaves out (empty: none; a copy is kept).
  void set_occluders(WallOccluders<D> occluders) {
    occluders_ = std::move(occluders);
    invalidate();
  }
  const WallOccluders<D>& occluders() const { return occluders_; }

  /// Verlet skin [m] (>= 0; 0: a cell search on every build() that sees a moved particle).
  void set_skin(double skin) {
    skin_ = skin > 0.0 ? skin : 0.0;
    invalidate();
  }
  double skin() const { return skin_; }
  /// The next build() runs the cell search.
  void invalidate() { searched_ = false; }
  /// Cell searches so far (the rest of the build() calls only refreshed the lists).
  std::uint64_t search_count() const { return search_count_; }

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

  /// Every particle index ordered by cell (axis 0 fastest), free before fixed within a cell, as
  /// of the last cell search (invalidate() then build() for a current one).
  const std::vector<std::int32_t>& cell_order() const { return sorted_index_; }
  /// The permutation that stores the particles in the order of the last cell search, for memory
  /// locality: the free particles in cell order, then the fixed ones - in cell order as well when
  /// sort_fixed (walls never move: sorting them once is enough), else in their current order, so
  /// that what was stored about them by index stays valid. Reuses out's storage.
  void cell_sorted_permutation(bool sort_fixed, std::vector<std::int32_t>& out) const;

 private:
  void setup_grid(const Vec<D>* x);
  void sort_into_cells(const Vec<D>* x);
  bool needs_search(const Vec<D>* x, std::size_t n, std::size_t n_free, double support,
                    const DomainBox<D>& box) const;
  template <bool kPeriodic>
  void search_candidates(const Vec<D>* x);
  template <bool kPeriodic>
  void refresh_pairs(const Vec<D>* x, const std::int32_t* wall_tag);
  int stencil_of(std::int64_t cell, std::int64_t* out) const;

  std::size_t n_ = 0, n_free_ = 0, pair_count_ = 0;
  double support_ = 0, skin_ = 0;
  DomainBox<D> box_;
  bool searched_ = false;
  WallOccluders<D> occluders_;
  std::uint64_t search_count_ = 0;
  std::vector<Vec<D>> searched_position_;  ///< positions at the last cell search
  // grid
  CellGrid<D> grid_;
  // counting sort
  std::vector<std::int64_t> cell_of_;                     ///< per particle
  std::vector<std::int32_t> cell_start_;                  ///< per cell + 1, into sorted arrays
  std::vector<std::int32_t> cell_free_end_;               ///< per cell: end of its free particles
  std::vector<std::vector<std::int32_t>> thread_counts_;  ///< per thread: counts, then cursors
  std::vector<std::int32_t> sorted_index_;
  std::vector<Vec<D>> sorted_position_;
  // candidates (index pairs closer than support + skin at the last search)
  std::vector<std::vector<std::int32_t>> candidate_buffers_;  ///< one per thread
  std::vector<std::uint32_t> candidate_offsets_;              ///< 3 per particle: begin, mid, end
  std::vector<int> candidate_owner_;  ///< per chunk: thread whose buffer holds it
  // lists
  std::vector<std::vector<Pair>> buffers_;  ///< one per thread; sizes only grow
  std::vector<std::uint32_t> offsets_;      ///< scratch: 3 per particle, offsets in its buffer
  std::vector<int> chunk_owner_;            ///< thread whose buffer holds a chunk's lists
  std::vector<const Pair*> begin_, mid_, end_;
};

extern template class NeighbourList<2>;
extern template class NeighbourList<3>;

}  // namespace porosph::sph
