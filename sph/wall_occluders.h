// Walls that separate the particles of one phase on their two sides at any thickness
// (docs/water-in-soil.md, section 2). A wall of L particle layers keeps two bodies of water (or
// soil) apart by itself only for L >= 2m, m = ceil(2h / dp) - 1 (4 layers at h = 1.2 dp): a
// thinner wall's particles are neighbours of both sides and carry the pressure of one side to the
// other, and under a head difference water passes through it (the hydraulic heave's 1 cm sheet
// pile at dp 10 mm).
//
// Such a thin box wall (scene::thin_wall_axis, scene/thin_walls.h) becomes an occluder: the patch
// of its mid-plane across its span. Two particles see each other only if the segment between them
// does not cross a patch (hides), and the wall is filled once per side (two_sided_wall_fill): each
// side gets max(L, m) layers from its own face inwards, tagged with the side (wall_side_tag), and
// a tagged wall particle is seen only from its side of the mid-plane. Each side so meets a wall
// that fills its kernel support, as beside a thick wall, and never the other side's pressure or
// stress; the water under a wall's tip still flows round it. Near the tip a side's lattice
// reaches up to (max(L, m) - L) dp past the wall's far face: the tip is that much wider, seen
// from one side. Used by the water and soil solvers (water.thin_walls, soil.thin_walls) and the
// coupler's soil-water sums.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/thin_walls.h"
#include "sph/vector.h"

namespace porosph::sph {

/// The mid-plane patch of a thin wall: x[axis] = plane over lo <= x <= hi on the other axes.
template <int D>
struct WallOccluder {
  int axis = 0;
  double plane = 0.0;
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();
  /// How far from the plane its tagged wall particles lie at most (max(L, m) dp): a particle
  /// farther than the support from the box [plane - reach, plane + reach] x [lo, hi] has no pair
  /// this occluder hides (its segments cannot reach the patch, nor its tagged particles).
  double reach = 0.0;

  /// True if x lies within `support` of that box.
  bool near(const Vec<D>& x, double support) const {
    double d2 = 0.0;
    for (int k = 0; k < D; ++k) {
      const double low = k == axis ? plane - reach : lo[k];
      const double high = k == axis ? plane + reach : hi[k];
      const double d = std::max({0.0, low - x[k], x[k] - high});
      d2 += d * d;
    }
    return d2 < support * support;
  }

  /// +1 on the side x[axis] >= plane, -1 on the other.
  int side(const Vec<D>& x) const { return x[axis] >= plane ? 1 : -1; }

  /// True if the segment from a to b crosses the patch (a and b on different sides, the crossing
  /// point within the span; a point on the plane counts as on the +1 side).
  bool crossed_by(const Vec<D>& a, const Vec<D>& b) const {
    if (side(a) == side(b)) return false;
    const double t = (plane - a[axis]) / (b[axis] - a[axis]);
    for (int k = 0; k < D; ++k) {
      if (k == axis) continue;
      const double p = a[k] + t * (b[k] - a[k]);
      if (p < lo[k] || p > hi[k]) return false;
    }
    return true;
  }
};

/// The tag of a wall particle filled for side `side` (+1/-1) of occluder `k`: +-(k + 1); 0 is an
/// untagged particle (water, and walls that are not occluders).
inline std::int32_t wall_side_tag(int k, int side) { return side > 0 ? k + 1 : -(k + 1); }

/// The occluders of one solver's walls.
template <int D>
class WallOccluders {
 public:
  bool empty() const { return walls_.empty(); }
  std::size_t size() const { return walls_.size(); }
  const WallOccluder<D>& operator[](std::size_t k) const { return walls_[k]; }
  /// Adds one; returns its index k (the k of wall_side_tag).
  int add(const WallOccluder<D>& occluder) {
    walls_.push_back(occluder);
    return static_cast<int>(walls_.size()) - 1;
  }

  /// True if x is near() some occluder: only such a particle can have a hidden pair.
  bool near(const Vec<D>& x, double support) const {
    for (const WallOccluder<D>& o : walls_)
      if (o.near(x, support)) return true;
    return false;
  }

  /// True if particles a and b (tags as wall_side_tag; xb = xa - x_ab with the minimum image, so
  /// that the segment is the pair's) must not see each other: a tagged particle is hidden from
  /// the other side of its own occluder's plane, any pair by another occluder it crosses.
  bool hides(const Vec<D>& xa, std::int32_t tag_a, const Vec<D>& xb, std::int32_t tag_b) const {
    for (std::size_t k = 0; k < walls_.size(); ++k) {
      const std::int32_t own = static_cast<std::int32_t>(k) + 1;
      const WallOccluder<D>& o = walls_[k];
      if (tag_a == own || tag_a == -own) {
        if (o.side(xb) != (tag_a > 0 ? 1 : -1)) return true;
      } else if (tag_b == own || tag_b == -own) {
        if (o.side(xa) != (tag_b > 0 ? 1 : -1)) return true;
      } else if (o.crossed_by(xa, xb)) {
        return true;
      }
    }
    return false;
  }

 private:
  std::vector<WallOccluder<D>> walls_;
};

/// The occluder of box wall `wall`, thin along `axis`: its mid-plane over its span.
template <int D>
WallOccluder<D> occluder_of(const scene::Shape& wall, int axis);

/// occluder_of(), each end of the span that meets another of `walls` (a floor the wall stands on,
/// a base it hangs from) carried on by 2h into that wall: the other wall's particles under the
/// thin wall's foot are then seen from their own side only, instead of from both (the water on
/// the two sides would share them, as through a thin wall). A free end (a sheet pile's tip over
/// the gap the water flows through) keeps the wall's span.
template <int D>
WallOccluder<D> thin_wall_occluder(const scene::Shape& wall, int axis,
                                   const std::vector<scene::Shape>& walls, double h, double dp);

/// The thin walls among `walls` (the scene's walls acting on `phase`, in order) that are filled on
/// both sides: occluder k of `occluders`, `occluder_of_wall[j]` the occluder of wall j (-1: an
/// ordinary wall), `axis_of_wall[j]` its thin axis. None unless `separating` (water.thin_walls,
/// soil.thin_walls); a wall that moves (moves_with) is never one (its mid-plane would move).
template <int D>
struct ThinWallSet {
  WallOccluders<D> occluders;
  std::vector<int> occluder_of_wall, axis_of_wall;

  /// The particles of wall j (`wall`, h, dp as the set's): two_sided_wall_fill() for a thin one,
  /// else fill_shape() with tags 0. Replaces the contents of points and tags.
  void fill(std::size_t j, const scene::Shape& wall, double h, double dp,
            std::vector<Vec<D>>& points, std::vector<std::int32_t>& tags) const;
};
template <int D>
ThinWallSet<D> thin_walls_of(const scene::Scene& scene, const std::vector<scene::Shape>& walls,
                             const std::string& phase, bool separating);

/// The two-sided fill of thin box wall `wall` (occluder index k, thin along `axis`): for each side
/// max(L, m) layers from that side's face inwards (m = separating_wall_layers / 2), the wall's
/// lattice across the axis; `tags` gets each point's wall_side_tag. Appends to points and tags.
template <int D>
void two_sided_wall_fill(const scene::Shape& wall, int axis, int k, double h, double dp,
                         std::vector<Vec<D>>& points, std::vector<std::int32_t>& tags);

}  // namespace porosph::sph
