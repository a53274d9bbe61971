// The Monaghan term at a no-slip wall on the wall-normal approach only
// (fluid_solver/wall_normal_damping.h): the normal of a straight floor and of a corner's bisector
// from the walls' kernel sum, and the velocity the term then acts on.
#include "fluid_solver/wall_normal_damping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sph/kernels.h"
#include "sph/neighbour_list.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
constexpr double kDp = 0.01;

/// One water particle at `at` (index 0) over wall particles at spacing dp: three floor rows
/// (y = -0.5, -1.5, -2.5 dp) for x in [-10, 10] dp; with `corner` the floor starts at x = -2 dp
/// and its mirror image about the diagonal x = y is added, a left wall symmetric with the floor.
struct WallLattice {
  std::vector<Vec2> x;
  std::vector<double> volume;
  sph::NeighbourList<2> list;
  WallLattice(const Vec2& at, bool corner) {
    x.push_back(at);
    for (int i = corner ? -2 : -10; i <= 10; ++i)
      for (int j = 0; j < 3; ++j) {
        x.emplace_back(i * kDp, -(j + 0.5) * kDp);
        if (corner) x.emplace_back(-(j + 0.5) * kDp, i * kDp);
      }
    volume.assign(x.size(), kDp * kDp);
    list.build(x.data(), x.size(), 1, 2.4 * kDp, sph::DomainBox<2>{});
  }
};

TEST(WallNormalDamping, TheNormalOfAFloorIsVerticalAndACornersIsItsBisector) {
  const sph::CubicSpline<2> kernel(1.2 * kDp);
  const WallLattice floor(Vec2(0.0, 0.6 * kDp), false);
  const Vec2 n = wall_normal_of<2>(floor.list, kernel, floor.volume.data(), 0);
  EXPECT_NEAR(std::abs(n.y()), 1.0, 1e-12);  // the lattice is symmetric about x = 0
  EXPECT_NEAR(n.x(), 0.0, 1e-12);
  // In a corner on its diagonal: the bisector (either sign; only the line enters the term).
  const WallLattice corner(Vec2(0.7 * kDp, 0.7 * kDp), true);
  const Vec2 b = wall_normal_of<2>(corner.list, kernel, corner.volume.data(), 0);
  EXPECT_NEAR(std::abs(b.x()), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(b.x(), b.y(), 1e-12);
  // Without wall neighbours: no normal, and so no artificial viscosity at walls.
  const WallLattice far(Vec2(0.0, 1.0), false);
  EXPECT_EQ(wall_normal_of<2>(far.list, kernel, far.volume.data(), 0), Vec2::Zero());
}

TEST(WallNormalDamping, OnlyTheNormalApproachIsDamped) {
  const Vec2 n(0.0, 1.0), v_aw(2.0, -0.5);  // sliding at 2 m/s, approaching at 0.5 m/s
  EXPECT_EQ(wall_damped_velocity<2>(WallArtificialViscosity::normal, n, v_aw), Vec2(0.0, -0.5));
  EXPECT_EQ(wall_damped_velocity<2>(WallArtificialViscosity::full, n, v_aw), v_aw);
  // Sliding only: nothing left for the term to act on.
  EXPECT_EQ(wall_damped_velocity<2>(WallArtificialViscosity::normal, n, Vec2(2.0, 0.0)),
            Vec2::Zero());
}

}  // namespace
}  // namespace porosph::water
