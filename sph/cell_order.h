// One phase's particles kept in cell order (issue 24, the shared phase core): the neighbour
// search every particle solver runs before its rates, a re-sort of the particles by cell every
// kReorderEvery steps (neighbours close in memory), and the overlap indices that must follow a
// re-sort (sph/overlap_scatter.h).
#pragma once

#include <cstdint>
#include <vector>

#include "sph/domain_box.h"
#include "sph/neighbour_list.h"
#include "sph/overlap_scatter.h"

namespace porosph::sph {

template <int D>
class CellOrder {
 public:
  /// Steps between two re-sorts.
  static constexpr std::uint64_t kReorderEvery = 100;

  /// The search reaches 2h; `list` gets the solvers' skin (kSolverSkinFraction of 2h).
  CellOrder(NeighbourList<D>& list, double h) : reach_(2.0 * h) {
    list.set_skin(kSolverSkinFraction * reach_);
  }

  /// The neighbours of P's particles (the first P.n_free free) within 2h in `box`.
  template <class Particles>
  void search(NeighbourList<D>& list, const Particles& P, const DomainBox<D>& box) const {
    list.build(P.position.data(), P.size(), P.n_free, reach_, box, wall_tags(P, 0));
  }

  /// Re-sorts P by cell (the fixed particles too with `sort_fixed`), moves `overlap_index` with
  /// them, and searches again in the new order.
  template <class Particles>
  void reorder(NeighbourList<D>& list, Particles& P, const DomainBox<D>& box, bool sort_fixed,
               std::vector<std::int32_t>& overlap_index) {
    list.invalidate();  // a search now: the current cell order, whatever the last search
    search(list, P, box);
    list.cell_sorted_permutation(sort_fixed, order_);
    P.permute(order_);
    remap_overlap_index(overlap_index, order_, inverse_);
    list.invalidate();
    search(list, P, box);
  }

  /// The search of step `step`: a re-sort (free particles only) every kReorderEvery steps after
  /// the first, a search otherwise.
  template <class Particles>
  void refresh(NeighbourList<D>& list, Particles& P, const DomainBox<D>& box, std::uint64_t step,
               std::vector<std::int32_t>& overlap_index) {
    if (step > 0 && step % kReorderEvery == 0) {
      reorder(list, P, box, /*sort_fixed=*/false, overlap_index);
    } else {
      search(list, P, box);
    }
  }

 private:
  /// The particles' thin-wall side tags (sph/wall_occluders.h), where the container has them.
  template <class Particles>
  static auto wall_tags(const Particles& P, int) -> decltype(P.wall_side.data()) {
    return P.wall_side.data();
  }
  template <class Particles>
  static const std::int32_t* wall_tags(const Particles&, long) {
    return nullptr;
  }

  double reach_;
  std::vector<std::int32_t> order_, inverse_;  ///< scratch of a re-sort
};

}  // namespace porosph::sph
