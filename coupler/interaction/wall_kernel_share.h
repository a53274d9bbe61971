// The share of a water particle's kernel support that lies inside walls, where neither water nor
// soil can be,
//   S_a = sum_w V_w W(x_a - x_w)     (w: the particles of the walls acting on water, less those
//                                      of a wall the soil passes through inside a soil block),
// and the factor 1 / (1 - S_a) by which the soil-water pair sums of that particle are
// renormalised (coupling.drag_at_walls = "renormalised", docs/coupling.md).
//
// Why. The drag and the porosity a water particle sees are kernel sums over the soil particles
// (soil_water_sums.h), and there is no soil in a wall. Next to a wall the sum misses the
// part of the support inside the wall: in the seepage weir's sand (dp 5 mm) the first water row
// beside a wall saw a porosity of 0.51-0.53 instead of 0.40, a drag about 35 % weaker, and the
// water there ran 25-45 % faster than one row further in (the floor, the cut-off wall's face).
// That thin fast layer along every wall (the weir's base, the cut-off wall, the floor) adds
// discharge in proportion to dp and lifts the exit gradient beside the cut-off wall
// (docs/verification.md). The water and soil lattices fill the space up to the wall faces alike,
// so deep in soil S_soil + S_wall = 1 (the kernel carries the lattice factor), and dividing the
// soil sums by 1 - S_wall restores them where the wall, not the soil's edge, cuts them short. At
// the soil's free surface away from walls S_wall = 0 and nothing changes (there the water goes
// on where the soil ends); in free water beside a wall the soil sum is 0 and stays 0. A wall that
// acts on soil only is not counted: water fills it. S is capped at kMaxShare (a water particle
// in a concave corner of two walls sees about 0.6).
//
// Walls that move (moves_with) are left out: their particles' places change during the run.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "coupler/interaction/cross_neighbours.h"
#include "proto/coupling_client.h"
#include "sph/domain_box.h"
#include "sph/vector.h"
#include "sph/wall_occluders.h"

namespace porosph::coupler {

template <int D, class Kernel>
class WallKernelShare {
 public:
  /// The largest share of the support taken as inside walls.
  static constexpr double kMaxShare = 0.75;

  /// `wall_points`: the fixed wall particles (n x D, flattened), each of volume `volume`; no
  /// points: the share is 0 everywhere (renormalisation off).
  /// `tags`: the points' thin-wall side tags (empty: all 0), `occluders` the thin walls
  /// (sph/wall_occluders.h; empty: none): a wall point that a thin wall hides from a water
  /// particle is not in its share.
  WallKernelShare(std::vector<double> wall_points, double volume, const Kernel& kernel,
                  const sph::DomainBox<D>& box, double skin, std::vector<std::int32_t> tags = {},
                  sph::WallOccluders<D> occluders = {})
      : points_(std::move(wall_points)),
        tags_(std::move(tags)),
        volume_(volume),
        kernel_(kernel),
        box_(box),
        occluders_(std::move(occluders)) {
    tags_.resize(points_.size() / D, 0);
    ids_.resize(points_.size() / D);
    std::iota(ids_.begin(), ids_.end(), std::int64_t{0});
    grid_.set_skin(skin);
  }

  bool empty() const { return ids_.empty(); }

  /// scale[a] = 1 / (1 - min(S_a, kMaxShare)) of every water overlap particle a.
  void compute(const coupling::StepState& water, std::vector<double>& scale) {
    const std::size_t n = water.overlap_id.size();
    scale.assign(n, 1.0);
    if (empty() || n == 0) return;
    grid_.update(OverlapPoints{ids_.data(), points_.data(), ids_.size()},
                 OverlapPoints{water.overlap_id.data(), water.overlap_position.data(), n},
                 kernel_.support(), box_);
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (count >= 2048)
    for (std::int64_t a = 0; a < count; ++a) {
      const std::size_t m = grid_.candidate_count(a);
      if (m == 0) continue;
      const std::int32_t* wall = grid_.candidates(a);
      const sph::Vec<D> x_a = Eigen::Map<const sph::Vec<D>>(water.overlap_position.data() + a * D);
      double share = 0.0;
      for (std::size_t c = 0; c < m; ++c) {
        sph::Vec<D> dx = x_a - Eigen::Map<const sph::Vec<D>>(points_.data() + wall[c] * D);
        box_.minimum_image(dx);
        if (!occluders_.empty() && occluders_.hides(x_a, 0, x_a - dx, tags_[wall[c]])) continue;
        share += volume_ * kernel_.w(dx.norm());
      }
      scale[a] = 1.0 / (1.0 - std::min(share, kMaxShare));
    }
  }

 private:
  std::vector<double> points_;
  std::vector<std::int32_t> tags_;  ///< per point (sph::wall_side_tag)
  std::vector<std::int64_t> ids_;
  double volume_;
  Kernel kernel_;
  sph::DomainBox<D> box_;
  sph::WallOccluders<D> occluders_;
  CrossNeighbours<D> grid_;
};

}  // namespace porosph::coupler
