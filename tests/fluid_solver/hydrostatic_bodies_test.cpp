// Hydrostatic initial state per connected water body (fluid_solver/hydrostatic_initial.h,
// water_bodies.h): two pools that a wall separates, a pool stacked on a shelf above another, and
// the water under a wall's tip in a pool the wall does not reach the bottom of.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "fluid_solver/hydrostatic_initial.h"
#include "fluid_solver/water_bodies.h"
#include "fluid_solver/water_solver.h"
#include "sph/geometry.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using testing::box;

constexpr double kRho = 1000.0, kG = 9.81, kDp = 0.01;

/// Still weakly compressible water d below its surface (c0 = 20 m/s, the pools' EOS):
/// rho0 g d (1 + g d / (2 c0^2) + ...), TaitEos::still_water_pressure.
double still(double depth) { return TaitEos(kRho, 20.0, 7.0).still_water_pressure(depth, kG); }

/// Water of `blocks` (lattice points inside a wall skipped) and the particles of `walls`.
template <int D>
struct Pools {
  std::vector<sph::Vec<D>> water, walls;
  std::vector<double> p, rho;
  std::size_t bodies = 0;
  std::vector<std::int32_t> body;

  Pools(const std::vector<scene::Shape>& blocks, const std::vector<scene::Shape>& wall_shapes) {
    for (const auto& b : blocks)
      for (const auto& x : sph::fill_block_outside_walls<D>(b, wall_shapes, kDp))
        water.push_back(x);
    for (const auto& w : wall_shapes)
      for (const auto& x : sph::fill_shape<D>(w, kDp)) walls.push_back(x);
    p.resize(water.size());
    rho.resize(water.size());
    sph::Vec<D> g = sph::Vec<D>::Zero();
    g[D - 1] = -kG;
    const TaitEos eos(kRho, 20.0, 7.0);
    hydrostatic_state<D>(water.data(), water.size(), walls.data(), walls.size(), g, kDp, eos,
                         p.data(), rho.data());
    body = water_bodies<D>(water.data(), water.size(), kDp, &bodies);
  }
};

TEST(WaterBodies, AWallSeparatesAndAGapUnderItJoins) {
  // Two pools either side of a wall down to the floor: two bodies; the same wall ending 0.1 m
  // above the floor: one body (linked through the gap).
  const auto wall_to_floor = box({0.3, 0.0}, {0.33, 0.5});
  const Pools<2> separate({box({0, 0}, {0.6, 0.3})}, {wall_to_floor});
  EXPECT_EQ(separate.bodies, 2u);
  const Pools<2> gap({box({0, 0}, {0.6, 0.3})}, {box({0.3, 0.1}, {0.33, 0.5})});
  EXPECT_EQ(gap.bodies, 1u);
  const Pools<3> gap3({box({0, 0, 0}, {0.2, 0.05, 0.2})}, {box({0.1, 0, 0.05}, {0.13, 0.05, 0.4})});
  EXPECT_EQ(gap3.bodies, 1u);
}

TEST(HydrostaticBodies, TwoPoolsOfDifferentLevelsEachFromItsOwnSurface) {
  // Left pool 0.3 m deep, right pool 0.15 m deep, a wall between them: p = rho g (own level - y)
  // exactly (round-off), in particular at the bottom row.
  const Pools<2> pools({box({0, 0}, {0.3, 0.3}), box({0.33, 0}, {0.6, 0.15})},
                       {box({0.3, 0.0}, {0.33, 0.5})});
  ASSERT_EQ(pools.bodies, 2u);
  for (std::size_t i = 0; i < pools.water.size(); ++i) {
    const double level = pools.water[i][0] < 0.3 ? 0.3 : 0.15;
    EXPECT_NEAR(pools.p[i], still(level - pools.water[i][1]), 1e-9);
  }
}

TEST(HydrostaticBodies, APoolOnAShelfDoesNotLoadThePoolBelowIt) {
  // Lower pool [0, 0.6] x [0, 0.1] under a 3-layer shelf [0, 0.6] x [0.1, 0.13] that carries an
  // upper pool [0, 0.3] x [0.13, 0.3]: the same columns hold two bodies. The upper pool starts
  // from its own surface 0.3; the lower one, covered by the shelf everywhere, from its own top
  // 0.1 (before: the columns under the upper pool took 0.3, 1.96 kPa too much).
  const Pools<2> pools({box({0, 0}, {0.6, 0.1}), box({0, 0.13}, {0.3, 0.3})},
                       {box({0, 0.1}, {0.6, 0.13})});
  ASSERT_EQ(pools.bodies, 2u);
  for (std::size_t i = 0; i < pools.water.size(); ++i) {
    const double level = pools.water[i][1] > 0.1 ? 0.3 : 0.1;
    EXPECT_NEAR(pools.p[i], still(level - pools.water[i][1]), 1e-9) << pools.water[i].transpose();
  }
}

/// A pool [0, 0.6] x [0, 0.3] (3D: 0.05 deep along y) with a 3-layer wall x in [0.3, 0.33] from
/// 0.1 m above the floor upwards: the water under the wall's tip is one body with the rest and
/// starts at rho g (0.3 - y) like its neighbours (before: rho g (0.1 - y), its own column's top
/// under the wall; at the bottom row 932 Pa against 2.9 kPa).
template <int D>
void check_water_under_a_wall_tip() {
  std::vector<double> lo(D, 0.0), hi(D, 0.05), wall_lo(D, 0.0), wall_hi(D, 0.05);
  hi[0] = 0.6;
  hi[D - 1] = 0.3;
  wall_lo[0] = 0.3;
  wall_hi[0] = 0.33;
  wall_lo[D - 1] = 0.1;
  wall_hi[D - 1] = 0.5;
  const Pools<D> pools({box(lo, hi)}, {box(wall_lo, wall_hi)});
  ASSERT_EQ(pools.bodies, 1u);
  std::size_t under_tip = 0;
  for (std::size_t i = 0; i < pools.water.size(); ++i) {
    const auto& x = pools.water[i];
    EXPECT_NEAR(pools.p[i], still(0.3 - x[D - 1]), 1e-9) << x.transpose();
    under_tip += x[0] > 0.3 && x[0] < 0.33;
  }
  EXPECT_GE(under_tip, D == 2 ? 30u : 150u);  // 3 columns x 10 rows (x 5 in 3D)
}

TEST(HydrostaticBodies, WaterUnderAWallTipTakesItsBodysSurface2D) {
  check_water_under_a_wall_tip<2>();
}
TEST(HydrostaticBodies, WaterUnderAWallTipTakesItsBodysSurface3D) {
  check_water_under_a_wall_tip<3>();
}

TEST(HydrostaticBodies, SolverStartsEachBodyFromItsOwnSurface) {
  // Through WaterSolver (initial_particles passes the walls): a pool 0.3 m deep joined under a
  // sheet-pile wall (tip 0.1 m above the floor) to a pool on the right, and a separate pool
  // 0.15 m deep behind a wall to the floor. Bottom-row pressures within 1 % of rho g (own depth).
  scene::Scene s = testing::water_scene(kDp, {-0.05, -0.05}, {1.0, 0.6});
  s.water->blocks = {box({0, 0}, {0.6, 0.3}), box({0.63, 0}, {0.9, 0.15})};
  s.walls = {box({0.3, 0.1}, {0.33, 0.5}), box({0.6, 0.0}, {0.63, 0.5}),
             testing::container({0, 0}, {0.9, 0.5}, 3)};
  WaterSolver<2> f(s);
  const auto& P = f.particles();
  int bottom = 0;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    const auto& x = P.position[a];
    if (x[1] > kDp) continue;
    const double depth = (x[0] < 0.6 ? 0.3 : 0.15) - x[1];
    EXPECT_NEAR(P.pressure[a], still(depth), 0.01 * kRho * kG * depth) << x.transpose();
    ++bottom;
  }
  EXPECT_EQ(bottom, 87);  // 60 + 27 columns
}

}  // namespace
}  // namespace porosph::water
