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

}  // namespace
}  // namespace porosph::sph
