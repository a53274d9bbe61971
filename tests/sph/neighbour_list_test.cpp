// Cell-list neighbour search against brute force: identical neighbour sets, displacements and
// distances, with and without periodic axes, with free and fixed particles.
#include "sph/neighbour_list.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace porosph::sph {
namespace {

template <int D>
std::vector<Vec<D>> random_points(std::size_t n, const DomainBox<D>& box, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Vec<D>> x(n);
  for (auto& p : x)
    for (int k = 0; k < D; ++k)
      p[k] = std::uniform_real_distribution<double>(box.min[k], box.max[k])(rng);
  return x;
}

/// Checks list against brute force: every pair (a, b != a) with r < support, except fixed-fixed,
/// appears once, water neighbours before fixed ones, with the minimum-image displacement.
template <int D>
void expect_matches_brute_force(const std::vector<Vec<D>>& x, std::size_t n_free, double support,
                                const DomainBox<D>& box) {
  NeighbourList<D> list;
  list.build(x.data(), x.size(), n_free, support, box);
  ASSERT_EQ(list.size(), x.size());
  std::size_t brute_pairs = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    std::set<std::int32_t> expected;
    for (std::size_t b = 0; b < x.size(); ++b) {
      if (b == a || (a >= n_free && b >= n_free)) continue;
      Vec<D> dx = x[a] - x[b];
      box.minimum_image(dx);
      if (dx.norm() < support) expected.insert(static_cast<std::int32_t>(b));
    }
    brute_pairs += expected.size();
    std::set<std::int32_t> found;
    for (auto it = list.begin(a); it != list.end(a); ++it) {
      const bool is_free = static_cast<std::size_t>(it->b) < n_free;
      EXPECT_EQ(is_free, it < list.mid(a)) << "water neighbours first, then fixed";
      EXPECT_TRUE(found.insert(it->b).second) << "duplicate neighbour " << it->b << " of " << a;
      Vec<D> dx = x[a] - x[it->b];
      box.minimum_image(dx);
      EXPECT_LT((it->x_ab - dx).norm(), 1e-12);
      EXPECT_NEAR(it->r, dx.norm(), 1e-12);
    }
    EXPECT_EQ(found, expected) << "particle " << a;
  }
  EXPECT_EQ(list.pair_count(), brute_pairs);
  // cell_order is a permutation of all particles.
  std::vector<std::int32_t> order = list.cell_order();
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], static_cast<std::int32_t>(i));
}

TEST(SphNeighbourList, MatchesBruteForce2D) {
  DomainBox<2> box;
  box.min = Vec<2>(-0.3, 0.1);
  box.max = Vec<2>(0.7, 0.6);
  const auto x = random_points<2>(1500, box, 1);
  expect_matches_brute_force<2>(x, 1200, 0.05, box);
}

TEST(SphNeighbourList, MatchesBruteForce3D) {
  DomainBox<3> box;
  box.min = Vec<3>(0.0, 0.0, 0.0);
  box.max = Vec<3>(0.4, 0.3, 0.2);
  const auto x = random_points<3>(1500, box, 2);
  expect_matches_brute_force<3>(x, 1000, 0.06, box);
}

TEST(SphNeighbourList, MatchesBruteForcePeriodic2D) {
  DomainBox<2> box;
  box.min = Vec<2>(0.0, 0.0);
  box.max = Vec<2>(0.53, 0.41);
  box.periodic = {true, false};
  const auto x = random_points<2>(1200, box, 3);
  expect_matches_brute_force<2>(x, 1200, 0.05, box);
}

TEST(SphNeighbourList, MatchesBruteForcePeriodic3DAllAxes) {
  DomainBox<3> box;
  box.min = Vec<3>(-0.1, -0.1, -0.1);
  box.max = Vec<3>(0.2, 0.25, 0.3);
  box.periodic = {true, true, true};
  const auto x = random_points<3>(1000, box, 4);
  expect_matches_brute_force<3>(x, 800, 0.07, box);
}

TEST(SphNeighbourList, PeriodicAxisOfTwoAndThreeCells) {
  // Lengths of exactly 2 and ~2.9 supports: 2 cells (left and right neighbour cell coincide) and
  // 2 cells again; no pair may be counted twice.
  DomainBox<2> box;
  box.min = Vec<2>(0.0, 0.0);
  box.max = Vec<2>(0.1, 0.145);
  box.periodic = {true, true};
  const auto x = random_points<2>(400, box, 5);
  expect_matches_brute_force<2>(x, 400, 0.05, box);
}

TEST(SphNeighbourList, SparseParticlesInHugeBoxAndEmptyInput) {
  // Far-apart clusters make the grid coarsen (bounded cell count); lists stay exact.
  DomainBox<2> box;
  std::vector<Vec<2>> x =
      random_points<2>(200, DomainBox<2>{Vec<2>(0, 0), Vec<2>(0.1, 0.1), {}}, 6);
  for (int i = 0; i < 50; ++i) x.push_back(Vec<2>(1000.0 + 0.01 * i, -500.0));
  expect_matches_brute_force<2>(x, 180, 0.02, box);
  NeighbourList<2> list;
  list.build(nullptr, 0, 0, 0.02, box);
  EXPECT_EQ(list.pair_count(), 0u);
}

TEST(SphNeighbourList, ReusedAcrossBuildsWithChangingSizes) {
  DomainBox<2> box;
  box.min = Vec<2>(0, 0);
  box.max = Vec<2>(0.2, 0.2);
  NeighbourList<2> list;
  for (unsigned seed : {10u, 11u, 12u}) {
    const auto x = random_points<2>(300 + 100 * seed % 7, box, seed);
    list.build(x.data(), x.size(), x.size() / 2, 0.03, box);
    std::size_t pairs = 0;
    for (std::size_t a = 0; a < x.size(); ++a) pairs += list.end(a) - list.begin(a);
    EXPECT_EQ(pairs, list.pair_count());
  }
}

/// Lists of `a` and `b` are the same pairs in the same order with the same x_ab and r (bitwise:
/// both come from the same positions by the same arithmetic).
template <int D>
void expect_identical_lists(const NeighbourList<D>& a, const NeighbourList<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.pair_count(), b.pair_count());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.end(i) - a.begin(i), b.end(i) - b.begin(i)) << "particle " << i;
    ASSERT_EQ(a.mid(i) - a.begin(i), b.mid(i) - b.begin(i)) << "particle " << i;
    for (auto p = a.begin(i), q = b.begin(i); p != a.end(i); ++p, ++q) {
      EXPECT_EQ(p->b, q->b);
      EXPECT_EQ(p->r, q->r);
      EXPECT_EQ(p->x_ab, q->x_ab);
    }
  }
}

template <int D>
void expect_skin_reuse_matches_fresh_search(const DomainBox<D>& box, std::size_t n_free) {
  const double support = 0.03, skin = 0.1 * support;
  auto x = random_points<D>(600, box, 21);
  NeighbourList<D> reused;
  reused.set_skin(skin);
  reused.build(x.data(), x.size(), n_free, support, box);
  ASSERT_EQ(reused.search_count(), 1u);
  // Three moves of every free particle by 0.16 skin each: at most 0.48 skin from where they were
  // searched, under the skin/2 that forces a search, so the lists are only refreshed - and must
  // equal a fresh search's at the new positions, pair for pair and bit for bit.
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (int move = 0; move < 3; ++move) {
    for (std::size_t i = 0; i < n_free; ++i) {
      Vec<D> d;
      for (int k = 0; k < D; ++k) d[k] = normal(rng);
      const Vec<D> step = (0.16 * skin / d.norm()) * d;
      bool leaves = false;  // a wrap across a periodic face is a jump by the box: move back
      for (int k = 0; k < D; ++k)
        leaves = leaves || (box.periodic[k] &&
                            !(x[i][k] + step[k] >= box.min[k] && x[i][k] + step[k] < box.max[k]));
      x[i] += leaves ? Vec<D>(-step) : step;
    }
    reused.build(x.data(), x.size(), n_free, support, box);
    NeighbourList<D> fresh;
    fresh.build(x.data(), x.size(), n_free, support, box);
    expect_identical_lists(reused, fresh);
  }
  EXPECT_EQ(reused.search_count(), 1u) << "no particle moved skin/2: no new search";
  // One particle jumps by 0.6 skin: a search, and the lists still match the brute force.
  x[0][0] += 0.6 * skin;
  reused.build(x.data(), x.size(), n_free, support, box);
  EXPECT_EQ(reused.search_count(), 2u);
  NeighbourList<D> fresh;
  fresh.build(x.data(), x.size(), n_free, support, box);
  expect_identical_lists(reused, fresh);
  expect_matches_brute_force(x, n_free, support, box);
  // invalidate() forces the next search even without motion.
  reused.invalidate();
  reused.build(x.data(), x.size(), n_free, support, box);
  EXPECT_EQ(reused.search_count(), 3u);
}

TEST(SphNeighbourList, SkinReusesTheSearchAndMatchesAFreshOne2D) {
  DomainBox<2> box;
  box.min = Vec<2>(0, 0);
  box.max = Vec<2>(0.2, 0.2);
  expect_skin_reuse_matches_fresh_search(box, 450);
}

TEST(SphNeighbourList, SkinReusesTheSearchAndMatchesAFreshOnePeriodic3D) {
  DomainBox<3> box;
  box.min = Vec<3>(0, 0, 0);
  box.max = Vec<3>(0.12, 0.12, 0.12);
  box.periodic = {true, false, true};
  expect_skin_reuse_matches_fresh_search(box, 600);
}

TEST(SphNeighbourList, CellSortedPermutationPutsFreeParticlesFirst) {
  DomainBox<2> box;
  box.min = Vec<2>(0.0, 0.0);
  box.max = Vec<2>(1.0, 0.5);
  const auto x = random_points<2>(400, box, 5);
  const std::size_t n_free = 300;
  NeighbourList<2> list;
  list.build(x.data(), x.size(), n_free, 0.1, box);
  std::vector<std::int32_t> free_in_cells, fixed_in_cells;
  for (std::int32_t i : list.cell_order())
    (static_cast<std::size_t>(i) < n_free ? free_in_cells : fixed_in_cells).push_back(i);
  std::vector<std::int32_t> order{42};  // stale content is replaced
  list.cell_sorted_permutation(true, order);
  ASSERT_EQ(order.size(), x.size());
  EXPECT_TRUE(std::equal(free_in_cells.begin(), free_in_cells.end(), order.begin()));
  EXPECT_TRUE(std::equal(fixed_in_cells.begin(), fixed_in_cells.end(), order.begin() + n_free));
  list.cell_sorted_permutation(false, order);
  ASSERT_EQ(order.size(), x.size());
  EXPECT_TRUE(std::equal(free_in_cells.begin(), free_in_cells.end(), order.begin()));
  for (std::size_t i = n_free; i < x.size(); ++i) EXPECT_EQ(order[i], static_cast<std::int32_t>(i));
  // The cell order differs from the index order (random points), so the test can tell them apart.
  EXPECT_FALSE(std::is_sorted(fixed_in_cells.begin(), fixed_in_cells.end()));
}

}  // namespace
}  // namespace porosph::sph
