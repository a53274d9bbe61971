// The damping stage seen from the water (sph/damping_stage.h): with soil.damping_duration
// set the water is frozen until then, inflow speeds are 0, and the first step after it starts from
// zero velocities with an Euler step.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fluid_solver/water_solver.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
using testing::box;
using testing::container;
using testing::inflow;
using testing::water_scene;

struct State {
  Vec2 x, v;
  double rho;
};

std::map<std::int64_t, State> water_state(const WaterSolver<2>& f) {
  std::map<std::int64_t, State> out;
  const WaterParticles<2>& P = f.particles();
  for (std::size_t a = 0; a < P.n_free; ++a)
    out[P.id[a]] = State{P.position[a], P.velocity[a], P.density[a]};
  return out;
}

/// A 0.2 x 0.05 m water layer (dp 0.01) in a container under gravity, with an inflow zone above it
/// (x in [0, 0.05], y in [0.05, 0.08], along +x at 0.5 m/s from t = 0) that the damping stage
/// must hold still; c = 20 m/s.
scene::Scene tank_with_inflow() {
  scene::Scene s = water_scene(0.01, {-0.1, -0.1}, {0.4, 0.3});
  s.walls.push_back(container({0, 0}, {0.2, 0.15}, 3));
  s.water->blocks.push_back(box({0, 0}, {0.2, 0.05}));
  s.water->inflows.push_back(inflow({0, 0.05}, {0.05, 0.08}, {1, 0}, 0.5));
  return s;
}

TEST(DampingStage, WaterIsFrozenUntilItsEndThenStartsFromRestWithAnEulerStep) {
  const double dt = 1.0 / 8192.0, duration = 100 * dt;  // binary fractions: t sums exactly
  scene::Scene s = tank_with_inflow();
  s.soil = scene::SoilPhase{};
  s.soil->damping_duration = duration;
  WaterSolver<2> f(s);
  ASSERT_EQ(f.free_count(), 100u + 15u);  // 20 x 5 layer + 5 x 3 zone
  EXPECT_EQ(f.damping_stage().duration(), duration);
  const auto initial = water_state(f);
  // Before the end of the stage nothing moves: positions, velocities and densities are the
  // initial ones bit for bit (a step that would integrate moves the water by g dt^2 / 2 = 7e-8 m
  // and the zone by 6e-5 m), and the inflow speed is 0 although its ramp starts at t = 0.
  int steps = 0;
  while (f.time() < duration) {
    f.compute_rates();
    f.advance(dt);
    ++steps;
    ASSERT_EQ(water_state(f).size(), initial.size());
    for (const auto& [id, st] : water_state(f)) {
      const State& s0 = initial.at(id);
      ASSERT_EQ(st.x, s0.x) << "id " << id << " at step " << steps;
      ASSERT_EQ(st.v, s0.v) << "id " << id << " at step " << steps;
      ASSERT_EQ(st.rho, s0.rho) << "id " << id << " at step " << steps;
    }
  }
  EXPECT_EQ(steps, 100);
  EXPECT_EQ(f.flow_zones().speed(0, 0.5 * duration), 0.0);
  EXPECT_EQ(f.flow_zones().speed(0, duration), 0.5);
  coupling::StepState state;
  f.compute_rates();
  f.fill_state(state, {}, {});
  EXPECT_EQ(state.diagnostics.max_speed, 0.0);  // at rest when the stage ends

  // First step after it: velocities start from 0 with an Euler step, v = dt a (a Verlet step
  // from v^{n-1} = 0 would give 2 dt a); positions x0 + dt^2 a / 2. Zone particles take the
  // inflow velocity (0.5, 0) and move by 0.5 dt.
  std::map<std::int64_t, Vec2> acceleration;
  for (std::size_t a = 0; a < f.free_count(); ++a)
    acceleration[f.particles().id[a]] = f.particles().acceleration[a];
  f.advance(dt);
  const WaterParticles<2>& P = f.particles();
  int zone = 0;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    const State& s0 = initial.at(P.id[a]);
    if (P.zone[a] >= 0) {
      ++zone;
      EXPECT_EQ(P.velocity[a], Vec2(0.5, 0.0));
      EXPECT_NEAR((P.position[a] - s0.x - Vec2(0.5 * dt, 0.0)).norm(), 0.0, 1e-15);
      continue;
    }
    const Vec2 a_i = acceleration.at(P.id[a]);
    EXPECT_NEAR((P.velocity[a] - dt * a_i).norm(), 0.0, 1e-12 * (1.0 + dt * a_i.norm()));
    EXPECT_NEAR((P.position[a] - s0.x - 0.5 * dt * dt * a_i).norm(), 0.0, 1e-15);
  }
  EXPECT_EQ(zone, 15);
}

TEST(DampingStage, WithoutSoilTheSameWaterMovesAtOnce) {
  // Control: no soil phase (or a zero duration), no stage: the first step moves the zone by
  // 0.5 dt and the layer under gravity.
  for (int with_soil = 0; with_soil < 2; ++with_soil) {
    scene::Scene s = tank_with_inflow();
    if (with_soil) s.soil = scene::SoilPhase{};  // damping_duration 0: no stage
    WaterSolver<2> f(s);
    const auto initial = water_state(f);
    f.compute_rates();
    f.advance(1e-4);
    int moved = 0;
    for (const auto& [id, st] : water_state(f)) moved += st.x != initial.at(id).x;
    EXPECT_EQ(moved, static_cast<int>(initial.size())) << "with soil " << with_soil;
  }
}

}  // namespace
}  // namespace porosph::water
