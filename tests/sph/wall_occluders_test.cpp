// Thin walls that part the water on their two sides (sph/wall_occluders.h): the occluder's
// visibility rules, the two-sided fill, and the neighbour list leaving out exactly the hidden
// pairs (against a brute-force search).
#include "sph/wall_occluders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "sph/neighbour_list.h"
#include "sph/occluder_crossing.h"

namespace porosph::sph {
namespace {

scene::Shape box(std::vector<double> lo, std::vector<double> hi) {
  scene::Shape s;
  s.kind = scene::Shape::Kind::Box;
  s.min = std::move(lo), s.max = std::move(hi);
  return s;
}

using V = Vec<2>;

TEST(WallOccluders, SeparatingLayersFollowTheKernelSupport) {
  // m = ceil(2h / dp) - 1 whole spacings shorter than 2h; the table of docs/water-in-soil.md.
  EXPECT_EQ(scene::separating_wall_layers(1.0 * 0.01, 0.01), 2);
  EXPECT_EQ(scene::separating_wall_layers(1.2 * 0.01, 0.01), 4);
  EXPECT_EQ(scene::separating_wall_layers(1.5 * 0.01, 0.01), 4);
  EXPECT_EQ(scene::separating_wall_layers(2.0 * 0.01, 0.01), 6);
}

TEST(WallOccluders, APairIsHiddenOnlyWhereItsSegmentCrossesThePatch) {
  // A wall x in [-0.005, 0.005], y in [0.03, 0.32]: the mid-plane x = 0 over that span.
  WallOccluders<2> o;
  o.add(occluder_of<2>(box({-0.005, 0.03}, {0.005, 0.32}), 0));
  EXPECT_TRUE(o.hides(V(-0.01, 0.1), 0, V(0.01, 0.1), 0));       // straight through
  EXPECT_TRUE(o.hides(V(-0.01, 0.035), 0, V(0.01, 0.025), 0));   // crosses at y = 0.03: the tip
  EXPECT_FALSE(o.hides(V(-0.01, 0.025), 0, V(0.01, 0.015), 0));  // under the tip: the gap
  EXPECT_FALSE(o.hides(V(-0.02, 0.1), 0, V(-0.01, 0.2), 0));     // same side
  EXPECT_TRUE(o.hides(V(-0.01, 0.1), 0, V(0.0, 0.1), 0));        // a point on the plane is +1
  // Tagged wall particles: seen from their own side only, wherever the other particle is.
  const std::int32_t left = wall_side_tag(0, -1), right = wall_side_tag(0, 1);
  EXPECT_FALSE(o.hides(V(0.01, 0.1), left, V(-0.01, 0.1), 0));
  EXPECT_TRUE(o.hides(V(0.01, 0.1), left, V(0.02, 0.1), 0));
  EXPECT_TRUE(o.hides(V(-0.01, 0.01), 0, V(0.0, 0.035), right));  // a left particle under the tip
  EXPECT_FALSE(o.hides(V(0.01, 0.01), 0, V(0.0, 0.035), right));
}

TEST(OccluderCrossing, AMoveThroughThePatchIsCaughtAndTheLowestIndexKept) {
  WallOccluders<2> o;
  o.add(occluder_of<2>(box({-0.005, 0.03}, {0.005, 0.32}), 0));
  EXPECT_EQ(crossed_occluder<2>(o, V(-0.001, 0.1), V(0.001, 0.1)), 0);     // through the wall
  EXPECT_EQ(crossed_occluder<2>(o, V(-0.001, 0.02), V(0.001, 0.02)), -1);  // under its tip
  EXPECT_EQ(crossed_occluder<2>(o, V(-0.003, 0.1), V(-0.001, 0.2)), -1);   // along it
  FirstCrossing<2> first;
  EXPECT_EQ(first.index, -1);
  first.offer(7, 0, V(-0.001, 0.1), V(0.001, 0.1));
  first.offer(3, 0, V(-0.001, 0.2), V(0.001, 0.2));
  first.offer(5, 0, V(-0.001, 0.3), V(0.001, 0.3));
  EXPECT_EQ(first.index, 3);
  EXPECT_EQ(first.before, V(-0.001, 0.2));
  const std::string message =
      occluder_crossing_message<2>("water", 42, o[0], first.before, first.after, 9, 0.5);
  EXPECT_NE(message.find("water particle 42 crossed the thin wall at x0 = 0"), std::string::npos);
  EXPECT_NE(message.find("step 9, t = 0.5 s"), std::string::npos);
}

TEST(WallOccluders, EachSideIsFilledWithAFullSupportOfItsOwn) {
  // dp 10 mm, h 12 mm: m = 2. A 1-layer wall gets 2 layers per side, a 3-layer one 3 per side.
  std::vector<V> x;
  std::vector<std::int32_t> tag;
  two_sided_wall_fill<2>(box({-0.005, 0.0}, {0.005, 0.1}), 0, 0, 0.012, 0.01, x, tag);
  ASSERT_EQ(x.size(), 40u);                // 2 sides x 2 layers x 10 rows
  std::set<std::pair<long, int>> columns;  // (x in 0.1 mm, tag)
  for (std::size_t i = 0; i < x.size(); ++i) columns.insert({std::lround(x[i][0] * 1e4), tag[i]});
  const std::set<std::pair<long, int>> expected = {{0, -1}, {100, -1}, {0, 1}, {-100, 1}};
  EXPECT_EQ(columns, expected);
  x.clear(), tag.clear();
  two_sided_wall_fill<2>(box({0.2, 0.0}, {0.23, 0.1}), 0, 1, 0.012, 0.01, x, tag);
  EXPECT_EQ(x.size(), 60u);  // both sides the wall's own 3 layers
  EXPECT_EQ(std::count(tag.begin(), tag.end(), 2), 30);
  EXPECT_EQ(std::count(tag.begin(), tag.end(), -2), 30);
}

TEST(WallOccluders, TheNeighbourListLeavesOutExactlyTheHiddenPairs) {
  // Free particles on a jittered lattice around a one-layer wall with a gap under its tip, and the
  // wall's two-sided particles: the lists equal a brute-force search less the hidden pairs.
  const double dp = 0.01, h = 0.012, support = 2 * h;
  const scene::Shape wall = box({-0.005, 0.03}, {0.005, 0.2});
  WallOccluders<2> occ;  // with its reach, so that the list's near() filter is exercised
  occ.add(thin_wall_occluder<2>(wall, 0, {wall}, h, dp));
  std::vector<V> x;
  for (int i = -8; i <= 8; ++i)
    for (int j = 0; j < 20; ++j) {
      const V p(i * dp + 0.002 * std::sin(7.0 * i + j), (j + 0.5) * dp + 0.002 * std::cos(3.0 * j));
      if (std::abs(p[0]) < 0.005 + 0.3 * dp && p[1] > 0.03 - 0.3 * dp) continue;  // not in the wall
      x.push_back(p);
    }
  const std::size_t n_free = x.size();
  std::vector<std::int32_t> tag(n_free, 0);
  two_sided_wall_fill<2>(wall, 0, 0, h, dp, x, tag);
  DomainBox<2> domain;
  NeighbourList<2> list;
  list.set_skin(0.1 * support);
  list.set_occluders(occ);
  list.build(x.data(), x.size(), n_free, support, domain, tag.data());
  std::size_t hidden = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    std::set<std::int32_t> expected, got;
    for (std::size_t b = 0; b < x.size(); ++b) {
      if (b == a || (a >= n_free && b >= n_free) || (x[a] - x[b]).norm() >= support) continue;
      if (occ.hides(x[a], tag[a], x[b], tag[b])) {
        ++hidden;
        continue;
      }
      expected.insert(static_cast<std::int32_t>(b));
    }
    for (auto it = list.begin(a); it != list.end(a); ++it) got.insert(it->b);
    EXPECT_EQ(got, expected) << "particle " << a;
  }
  EXPECT_GT(hidden, 500u);  // the test sees pairs across the wall
  // The filter is needed: far from the wall a free particle is not near(), next to it it is.
  EXPECT_FALSE(occ.near(V(-0.06, 0.1), support));
  EXPECT_TRUE(occ.near(V(-0.03, 0.1), support));  // within 2h of the +1 side's layer at -0.01
}

}  // namespace
}  // namespace porosph::sph
