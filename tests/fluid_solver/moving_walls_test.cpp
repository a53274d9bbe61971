// Moving walls (fluid_solver/moving_walls.h): a wall that follows an observable moves by dt times
// the speed the coupler sends, and measures the force the water's pressure puts on it.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid_solver/water_solver.h"
#include "tests/fluid_solver/water_fixtures.h"

namespace porosph::water {
namespace {

scene::Shape wall_box(std::vector<double> lo, std::vector<double> hi) {
  scene::Shape s = testing::box(std::move(lo), std::move(hi));
  s.phases = {"water"};
  return s;
}

/// Still water 0.2 m wide and deep between two fixed side walls, on a floor that moves with the
/// (here unused) observable `floor_speed` and reports its force as `floor_force`.
scene::Scene column_on_a_moving_floor() {
  scene::Scene s = testing::water_scene(0.01, {-0.05, -0.05}, {0.25, 0.35});
  s.water->blocks = {testing::box({0.0, 0.0}, {0.2, 0.2})};
  scene::Shape floor = wall_box({-0.03, -0.03}, {0.23, 0.0});
  floor.label = "floor";
  floor.moves_with = "floor_speed";
  floor.move_direction = {0.0, 1.0};
  s.walls = {wall_box({-0.03, 0.0}, {0.0, 0.3}), floor, wall_box({0.2, 0.0}, {0.23, 0.3})};
  scene::Observable force;
  force.name = "floor_force";
  force.kind = "wall_force";
  force.phase = "water";
  force.wall = "floor";
  force.direction = {0.0, 1.0};
  s.observables = {force};
  return s;
}

TEST(MovingWalls, TheFloorCarriesTheWeightOfStillWater) {
  WaterSolver<2> solver(column_on_a_moving_floor());
  solver.compute_rates();
  coupling::StepState state;
  solver.fill_state(state, {}, {});
  const double weight = 1000.0 * 9.81 * 0.2 * 0.2;  // rho g H W [N/m]
  // Pushed down by the weight: measured 393.35 N/m, +0.24 % (the walls' extrapolated pressure and
  // the oblique pairs at the bottom corners share the weight a little differently from the exact
  // hydrostatic split). Tolerance 1.5 %; a force of the wrong sign, or none, fails at once.
  EXPECT_NEAR(state.diagnostics.observables.at("floor_force"), -weight, 0.015 * weight);
}

TEST(MovingWalls, AMovingWallMovesByDtTimesItsSpeedAndTheOthersStay) {
  WaterSolver<2> solver(column_on_a_moving_floor());
  const WaterParticles<2>& P = solver.particles();
  std::vector<sph::Vec<2>> before(P.position.begin(), P.position.end());
  std::vector<std::int32_t> motion(P.wall_motion.begin(), P.wall_motion.end());
  solver.compute_rates();
  solver.set_wall_speeds({0.0, -0.01, 0.0});  // one speed per scene wall: the floor's -1 cm/s
  solver.advance(1e-3);
  int moved = 0, still = 0;
  for (std::size_t w = P.n_free; w < P.size(); ++w) {
    ASSERT_EQ(P.wall_motion[w], motion[w]);  // walls keep their order here (no reorder yet)
    if (P.wall_motion[w] == 0) {
      EXPECT_NEAR(P.position[w][1], before[w][1] - 1e-5, 1e-15);
      EXPECT_EQ(P.position[w][0], before[w][0]);
      EXPECT_EQ(P.velocity[w][1], -0.01);
      ++moved;
    } else {
      EXPECT_EQ(P.position[w], before[w]);
      ++still;
    }
  }
  EXPECT_EQ(moved, 26 * 3);  // the floor box: 26 columns x 3 rows
  EXPECT_GT(still, 0);
  EXPECT_THROW(solver.set_wall_speeds({0.0}), std::invalid_argument);  // one per scene wall
}

}  // namespace
}  // namespace porosph::water
