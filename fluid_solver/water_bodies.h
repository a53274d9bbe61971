// Connected water bodies of the initial lattice (hydrostatic_initial.h) and a hash grid of points
// for local queries at set-up.
//
// Two water particles are linked when they are at most 1.5 dp apart: the lattice's nearest and
// diagonal neighbours, the closest ring of the kernel support. A wall at least one spacing thick
// takes at least one lattice row out of the water (sph::fill_block_outside_walls), so the water
// on its two sides is at least 2 dp apart and never linked through it; a gap under a wall's tip
// that holds water links the two sides. A body is a maximal set of particles linked by chains.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "sph/vector.h"

namespace porosph::water {

/// Largest distance between two linked water particles, in particle spacings.
inline constexpr double kBodyLinkSpacings = 1.5;

/// Points hashed into cubic cells of side `cell` (set-up only: it allocates).
template <int D>
class PointGrid {
 public:
  PointGrid(const sph::Vec<D>* x, std::size_t n, double cell);
  /// Calls fn(j) for every point j in the cells within one cell of x's cell (all points closer
  /// than `cell` to x, and some farther).
  template <class Fn>
  void for_each_near(const sph::Vec<D>& x, Fn&& fn) const;

 private:
  using Key = std::array<std::int64_t, D>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 0;
      for (std::int64_t c : k) h = h * 1000003u ^ static_cast<std::size_t>(c + (1 << 20));
      return h;
    }
  };
  Key key_of(const sph::Vec<D>& x) const;
  double cell_;
  std::unordered_map<Key, std::vector<std::size_t>, KeyHash> cells_;
};

/// Body index (0, 1, ...) of each of the n particles at x, linked as described above; returns
/// the number of bodies in *count.
template <int D>
std::vector<std::int32_t> water_bodies(const sph::Vec<D>* x, std::size_t n, double dp,
                                       std::size_t* count);

template <int D>
template <class Fn>
void PointGrid<D>::for_each_near(const sph::Vec<D>& x, Fn&& fn) const {
  const Key centre = key_of(x);
  std::array<int, D> offset;
  offset.fill(-1);
  while (true) {
    Key k = centre;
    for (int d = 0; d < D; ++d) k[d] += offset[d];
    const auto it = cells_.find(k);
    if (it != cells_.end())
      for (std::size_t j : it->second) fn(j);
    int d = 0;
    while (d < D && offset[d] == 1) offset[d++] = -1;
    if (d == D) return;
    ++offset[d];
  }
}

}  // namespace porosph::water
