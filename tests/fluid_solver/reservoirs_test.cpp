// Constant-head reservoirs (fluid_solver/reservoirs.h): geometry and bad input; a tank drained
// through an outflow zone at its far end while a reservoir at the other end holds its level (to
// half a spacing) and the mass it exchanges is booked (mass balance to round-off); bit-for-bit
// continuation after a checkpoint while the reservoir refills.
#include "fluid_solver/reservoirs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fluid_solver/water_solver.h"
#include "tests/support/solver_checkpoint_check.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
using testing::box;

scene::ReservoirZone reservoir(std::vector<double> lo, std::vector<double> hi, double level) {
  scene::ReservoirZone z;
  z.min = std::move(lo);
  z.max = std::move(hi);
  z.level = level;
  return z;
}

TEST(Reservoirs, LevelRemovalAndBadInput) {
  scene::WaterPhase w;
  w.reservoirs.push_back(reservoir({0, 0}, {0.2, 0.4}, 0.2));
  scene::ReservoirZone later = reservoir({1, 0}, {1.2, 0.4}, 0.1);
  later.start_time = 0.5;
  w.reservoirs.push_back(later);
  const TaitEos eos(1000.0, 20.0, 7.0);
  const Reservoirs<2> r(w, Vec2(0, -9.81), 0.01, 0.012, eos);
  EXPECT_EQ(r.count(), 2u);
  EXPECT_EQ(r.column_count(), 40u);  // 20 + 20 columns across gravity
  EXPECT_TRUE(r.above_level(Vec2(0.1, 0.21), 0.0));
  EXPECT_FALSE(r.above_level(Vec2(0.1, 0.19), 0.0));
  EXPECT_FALSE(r.above_level(Vec2(0.3, 0.3), 0.0));    // outside every box
  EXPECT_FALSE(r.above_level(Vec2(1.1, 0.15), 0.49));  // not active yet
  EXPECT_TRUE(r.above_level(Vec2(1.1, 0.15), 0.5));
  // Gravity along +x: "above" is towards -x.
  scene::WaterPhase sideways;
  sideways.reservoirs.push_back(reservoir({0, 0}, {0.4, 0.2}, 0.2));
  const Reservoirs<2> s(sideways, Vec2(9.81, 0), 0.01, 0.012, eos);
  EXPECT_TRUE(s.above_level(Vec2(0.19, 0.1), 0.0));
  EXPECT_FALSE(s.above_level(Vec2(0.21, 0.1), 0.0));

  EXPECT_THROW((Reservoirs<2>(w, Vec2(3, -9), 0.01, 0.012, eos)),
               std::invalid_argument);  // diagonal
  scene::WaterPhase outside;
  outside.reservoirs.push_back(reservoir({0, 0}, {0.2, 0.4}, 0.5));
  EXPECT_THROW((Reservoirs<2>(outside, Vec2(0, -9.81), 0.01, 0.012, eos)), std::invalid_argument);
  EXPECT_THROW((Reservoirs<3>(w, sph::Vec<3>(0, 0, -9.81), 0.01, 0.012, eos)),
               std::invalid_argument);
}

/// A tank [0, 0.6] x [0, 0.4] (3-layer container open at the top) with water 0.2 m deep, a
/// reservoir over its left third holding the level 0.2 m, and an outflow zone at the bottom of
/// the right end [0.56, 0.6] x [0, 0.04] through which the tank drains.
scene::Scene drained_tank() {
  scene::Scene s = testing::water_scene(0.01, {-0.05, -0.05}, {0.65, 0.5});
  s.run.dt0 = 1e-4;
  s.water->sound_speed = 25.0;
  s.water->blocks = {box({0, 0}, {0.6, 0.2})};
  s.water->reservoirs = {reservoir({0, 0}, {0.2, 0.4}, 0.2)};
  s.water->outflows = {testing::outflow({0.56, 0}, {0.6, 0.04})};
  s.walls = {testing::container({0, 0}, {0.6, 0.4}, 3)};
  return s;
}

double free_mass(const WaterParticles<2>& P) {
  double m = 0.0;
  for (std::size_t a = 0; a < P.n_free; ++a) m += P.mass[a];
  return m;
}

TEST(Reservoirs, HoldLevelWhileTheTankDrainsAndBookTheMass) {
  // Over 0.6 s, every 200 steps: the mean surface of the reservoir's 20 columns within dp/2 of
  // the level (measured: 2.9 mm at worst, dp = 10 mm), each column's within [level - 4 dp,
  // level + dp/2 + 1 mm] (the column at the box's face towards the drain, whose particles drift
  // out of the box sideways, dips to 3.15 dp below at 0.22 s, a middle one to 2.6 dp late in the
  // run: the surface's waves; with the walls' artificial viscosity on the whole velocity, "full",
  // the floor's friction slowed the drain to 49.8 kg/m and the dip was 1.55 dp); the water's mass
  // equals initial + inflow - outflow to 1e-12 relative (measured 2.2e-14); the reservoir fed the
  // drain (23 of 53 kg/m).
  const scene::Scene s = drained_tank();
  WaterSolver<2> f(s);
  const double initial = free_mass(f.particles());
  coupling::StepState state;
  const std::vector<double> none;
  const double level = 0.2, dp = 0.01;
  double worst_mean = 0.0, worst_imbalance = 0.0;
  int checks = 0;
  while (f.time() < 0.6) {
    porosph::testing::step_alone(f, state, s.run.dt0);
    if (f.step() % 200 != 0) continue;
    const std::vector<double> surface = f.reservoirs().column_surfaces(0, f.particles());
    double mean = 0.0;
    for (std::size_t k = 0; k < surface.size(); ++k) {
      const double top = surface[k];
      ASSERT_TRUE(std::isfinite(top));
      EXPECT_LT(top, level + 0.5 * dp + 1e-3) << "t = " << f.time();
      EXPECT_GT(top, level - 4.0 * dp) << "t = " << f.time() << " column " << k;
      mean += top / static_cast<double>(surface.size());
    }
    worst_mean = std::max(worst_mean, std::abs(mean - level));
    f.fill_state(state, none, none);
    const auto& d = state.diagnostics;
    const double expected = initial + d.inflow_mass - d.outflow_mass;
    worst_imbalance = std::max(worst_imbalance, std::abs(d.mass - expected) / expected);
    ++checks;
  }
  f.fill_state(state, none, none);
  const auto& d = state.diagnostics;
  std::printf(
      "reservoir: worst |mean surface - level| %.3g m, worst mass imbalance %.3g, inflow "
      "%.4g kg/m, outflow %.4g kg/m, born %llu, removed %llu\n",
      worst_mean, worst_imbalance, d.inflow_mass, d.outflow_mass,
      static_cast<unsigned long long>(f.born_count()),
      static_cast<unsigned long long>(f.removed_count()));
  EXPECT_GT(checks, 20);
  EXPECT_LT(worst_mean, 0.5 * dp);
  EXPECT_LT(worst_imbalance, 1e-12);
  EXPECT_GT(d.inflow_mass, 0.05 * initial);  // the reservoir fed the drain
  EXPECT_GT(d.outflow_mass, d.inflow_mass);
}

TEST(Reservoirs, RefillContinuesBitForBitAfterACheckpoint) {
  // The first refills come at t = 0.149 s (step ~1650): checkpoint after 1900 steps, 300 more.
  const scene::Scene s = drained_tank();
  WaterSolver<2> first(s), second(s);
  porosph::testing::expect_checkpoint_continues_exactly(first, second, 1900, 300, s.run.dt0);
  EXPECT_GT(first.born_count(), 0u);
  EXPECT_EQ(second.born_count(), first.born_count());
  EXPECT_EQ(second.removed_count(), first.removed_count());
}

}  // namespace
}  // namespace porosph::water
