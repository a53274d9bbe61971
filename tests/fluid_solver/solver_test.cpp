// WaterSolver: a still water column stays still with hydrostatic pressure; exact integration of a
// free particle; periodic wrap; removal; interaction; non-finite detection; snapshots.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fluid_solver/water_solver.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
using testing::box;
using testing::container;
using testing::water_scene;

TEST(WaterSolver, StillWaterColumnStaysStillWithHydrostaticPressure) {
  // 0.2 m wide, d = 0.1 m deep column at dp = 5 mm (800 water particles) in a 3-layer container;
  // c = 10 sqrt(g d), alpha 0.05, mu 1e-3; 400 steps at dt = min of the limits (~0.05 s, more than
  // one acoustic period 4 d / c = 0.04 s).
  const double d = 0.1, g = 9.81;
  scene::Scene s = water_scene(0.005, {-0.1, -0.1}, {0.3, 0.3});
  s.water->sound_speed = 10.0 * std::sqrt(g * d);
  s.walls.push_back(container({0, 0}, {0.2, 0.15}, 3));
  s.water->blocks.push_back(box({0, 0}, {0.2, d}));
  scene::Observable probe;
  probe.name = "p_mid";
  probe.kind = "pressure_at";
  probe.point = {0.1, 0.5 * d};
  s.observables.push_back(probe);
  WaterSolver<2> f(s);
  ASSERT_EQ(f.free_count(), 800u);
  coupling::StepState state;
  for (int i = 0; i < 400; ++i) {
    f.compute_rates();
    const double dt = f.dt_limits().min();
    ASSERT_GT(dt, 0.0);
    f.advance(dt);
  }
  f.compute_rates();
  f.fill_state(state, {}, {});
  // Spurious speeds: with a 3 % pressure-force imbalance the water would reach 0.03 g t ~ 0.015
  // m/s in 0.05 s; this solver stays at 0.27 % of sqrt(g d) (measured; the free surface settles).
  // Bound: 1 % of sqrt(g d) = 0.0099 m/s.
  EXPECT_LT(state.diagnostics.max_speed, 0.01 * std::sqrt(g * d));
  // Mid-depth pressure: rho g d/2 = 490.5 Pa (measured +0.4 %); the weakly compressible column
  // carries acoustic oscillations of ~1 % of rho g d, plus the lattice gradient bias at h = 1.2 dp
  // (~1 %): tolerance 3 %.
  const double expected = 1000.0 * g * 0.5 * d;
  EXPECT_NEAR(state.diagnostics.observables.at("p_mid"), expected, 0.03 * expected);
  EXPECT_EQ(f.free_count(), 800u);
  EXPECT_EQ(f.removed_count(), 0u);
  // Mass m = rho(t = 0) dp^2: total mass within the compressibility (gd/c^2 = 1 %) of rho0 V.
  EXPECT_NEAR(state.diagnostics.mass, 1000.0 * 0.2 * d, 0.01 * 1000.0 * 0.2 * d);
}

TEST(WaterSolver, FreeParticleFollowsTheExactParabola) {
  // One water particle, no neighbours: x = x0 + a t^2 / 2, v = a t with a = g, for Euler and
  // Verlet steps alike (round-off only).
  scene::Scene s = water_scene(0.01, {-10, -10}, {10, 10});
  s.run.gravity = {0.3, -9.81};
  s.water->blocks.push_back(box({0, 0}, {0.01, 0.01}));
  WaterSolver<2> f(s);
  ASSERT_EQ(f.free_count(), 1u);
  const Vec2 x0(0.005, 0.005), a(0.3, -9.81);
  const double dt = 1e-3;
  for (int i = 0; i < 500; ++i) {
    f.compute_rates();
    f.advance(dt);
  }
  const double t = 500 * dt;
  EXPECT_NEAR(f.time(), t, 1e-12);
  EXPECT_EQ(f.step(), 500u);
  EXPECT_LT((f.particles().position[0] - (x0 + 0.5 * a * t * t)).norm(), 1e-11);
  EXPECT_LT((f.particles().velocity[0] - a * t).norm(), 1e-11);
}

TEST(WaterSolver, TimeStepLimits) {
  // Isolated particle at rest: dt_cfl = 0.2 h / c, dt_visc = 0.125 h^2 rho0 / mu,
  // dt_force = C_a sqrt(h / g).
  scene::Scene s = water_scene(0.01, {-1, -1}, {1, 1});
  s.water->blocks.push_back(box({0, 0}, {0.01, 0.01}));
  WaterSolver<2> f(s);
  f.compute_rates();
  const double h = 0.012;
  EXPECT_NEAR(f.dt_limits().cfl, 0.2 * h / 20.0, 1e-15);
  EXPECT_NEAR(f.dt_limits().viscous, 0.125 * h * h * 1000.0 / 1e-3, 1e-12);
  EXPECT_NEAR(f.dt_limits().force, 0.25 * std::sqrt(h / 9.81), 1e-15);
  EXPECT_EQ(f.dt_limits().min(), f.dt_limits().cfl);
  s.water->viscosity = 0.0;
  WaterSolver<2> inviscid(s);
  inviscid.compute_rates();
  EXPECT_TRUE(std::isinf(inviscid.dt_limits().viscous));
}

TEST(WaterSolver, PeriodicAxisWrapsAParticleAcrossTheFace) {
  // Domain x in [0, 0.1), periodic; a = +5 m/s^2 along x from x0 = 0.095: at t = 0.1 s the
  // unwrapped x = 0.095 + 2.5 * 0.01 = 0.12, i.e. 0.02 after re-entering at x = 0.
  scene::Scene s = water_scene(0.01, {0, -1}, {0.1, 1});
  s.run.periodic = {true, false};
  s.run.gravity = {5.0, 0.0};
  s.water->blocks.push_back(box({0.09, 0}, {0.1, 0.01}));
  WaterSolver<2> f(s);
  for (int i = 0; i < 100; ++i) {
    f.compute_rates();
    f.advance(1e-3);
  }
  EXPECT_NEAR(f.particles().position[0][0], 0.02, 1e-12);
  EXPECT_EQ(f.free_count(), 1u);
  EXPECT_EQ(f.removed_count(), 0u);
  s.domain.max = {0.03, 1};  // shorter than 2 x support (0.048 m): rejected
  EXPECT_THROW(WaterSolver<2>{s}, std::invalid_argument);
}

TEST(WaterSolver, ParticleLeavingTheDomainIsRemovedAndIdsStayStable) {
  // Two isolated particles falling from y = 0.005 (id 0) and y = 0.505 (id 1); the floor of the
  // domain is y = 0: after 0.05 s the first has left (t_exit = sqrt(2 * 0.005 / g) = 0.032 s).
  scene::Scene s = water_scene(0.01, {0, 0}, {1, 1});
  s.water->blocks.push_back(box({0.5, 0.0}, {0.51, 0.01}));
  s.water->blocks.push_back(box({0.5, 0.5}, {0.51, 0.51}));
  WaterSolver<2> f(s);
  ASSERT_EQ(f.free_count(), 2u);
  for (int i = 0; i < 50; ++i) {
    f.compute_rates();
    f.advance(1e-3);
  }
  EXPECT_EQ(f.free_count(), 1u);
  EXPECT_EQ(f.particle_count(), 1u);
  EXPECT_EQ(f.removed_count(), 1u);
  EXPECT_EQ(f.particles().id[0], 1);
  coupling::StepState state;
  f.fill_state(state, {}, {});
  EXPECT_EQ(state.diagnostics.removed_count, 1u);
  EXPECT_EQ(state.diagnostics.free_count, 1u);
}

TEST(WaterSolver, InteractionAcceleratesTheOverlapParticles) {
  // Two isolated particles; only the one inside the overlap box gets the interaction (2, 0) m/s^2.
  // First step is an Euler step: v = (g + a_int) dt.
  scene::Scene s = water_scene(0.01, {-1, -1}, {1, 1});
  s.water->blocks.push_back(box({0.0, 0.0}, {0.01, 0.01}));
  s.water->blocks.push_back(box({0.5, 0.0}, {0.51, 0.01}));
  WaterSolver<2> f(s);
  coupling::StepState state;
  f.compute_rates();
  f.fill_state(state, {0.4, -0.1}, {0.6, 0.1});
  ASSERT_EQ(state.overlap_id.size(), 1u);
  EXPECT_EQ(state.overlap_position.size(), 2u);
  EXPECT_NEAR(state.overlap_position[0], 0.505, 1e-12);
  EXPECT_EQ(state.overlap_mass.size(), 1u);
  EXPECT_THROW(f.add_interaction({1.0}), std::invalid_argument);
  f.add_interaction({2.0, 0.0});
  f.advance(1e-3);
  const auto& P = f.particles();
  for (std::size_t i = 0; i < 2; ++i) {
    const bool in_overlap = P.id[i] == state.overlap_id[0];
    EXPECT_NEAR(P.velocity[i][0], in_overlap ? 2e-3 : 0.0, 1e-15);
    EXPECT_NEAR(P.velocity[i][1], -9.81e-3, 1e-15);
  }
  // eq. 21 of the next step sees the total acceleration |g + a_int| = sqrt(4 + 9.81^2).
  f.compute_rates();
  EXPECT_NEAR(f.dt_limits().force, 0.25 * std::sqrt(0.012 / std::hypot(2.0, 9.81)), 1e-12);
  // Without a new interaction the step after uses (and remembers) none.
  f.advance(1e-3);
  f.compute_rates();
  EXPECT_NEAR(f.dt_limits().force, 0.25 * std::sqrt(0.012 / 9.81), 1e-12);
  EXPECT_TRUE(state.region_min.size() == 2 && state.region_max.size() == 2);
}

TEST(WaterSolver, FindsAnInjectedNaNWithItsId) {
  scene::Scene s = water_scene(0.01, {-1, -1}, {1, 1});
  s.water->blocks.push_back(box({0.0, 0.0}, {0.01, 0.01}));
  s.water->blocks.push_back(box({0.5, 0.0}, {0.51, 0.01}));
  WaterSolver<2> f(s);
  std::int64_t id = -1;
  f.compute_rates();
  EXPECT_FALSE(f.find_non_finite(&id).has_value());
  coupling::StepState state;
  f.fill_state(state, {0.4, -0.1}, {0.6, 0.1});
  ASSERT_EQ(state.overlap_id.size(), 1u);
  f.add_interaction({std::numeric_limits<double>::quiet_NaN(), 0.0});
  f.advance(1e-3);
  const auto message = f.find_non_finite(&id);
  ASSERT_TRUE(message.has_value());
  EXPECT_EQ(id, state.overlap_id[0]);
  EXPECT_NE(message->find("particle " + std::to_string(id)), std::string::npos) << *message;
  EXPECT_EQ(f.free_count(), 2u);  // a NaN particle is reported, not silently removed
}

TEST(WaterSolver, WallsDisappearAtTheirRemovalTimeAndSnapshotsListEveryParticle) {
  // A gate (box wall) removed at t = 2 ms next to a permanent wall; 10 water particles.
  scene::Scene s = water_scene(0.01, {-1, -1}, {1, 1});
  s.water->blocks.push_back(box({0.0, 0.0}, {0.1, 0.01}));
  s.walls.push_back(box({0.2, 0.0}, {0.23, 0.1}, 0.002));  // 3 x 10 = 30 particles
  s.walls.push_back(box({0.0, -0.03}, {0.1, 0.0}));        // 10 x 3 = 30 particles
  WaterSolver<2> f(s);
  EXPECT_EQ(f.particle_count(), 70u);
  auto fields = f.snapshot_fields();
  ASSERT_EQ(fields.size(), 7u);
  const char* names[] = {"position", "velocity", "density", "pressure", "mass", "id", "fixed"};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(fields[i].name, names[i]);
    EXPECT_EQ(fields[i].rows, 70u);
  }
  EXPECT_EQ(fields[0].cols, 2u);
  int fixed = 0;
  for (std::size_t i = 0; i < 70; ++i) fixed += fields[6].u8[i];
  EXPECT_EQ(fixed, 60);
  for (int i = 0; i < 3; ++i) {
    f.compute_rates();
    f.advance(1e-3);
  }
  EXPECT_EQ(f.particle_count(), 40u);
  EXPECT_EQ(f.free_count(), 10u);
  EXPECT_EQ(f.snapshot_fields()[5].rows, 40u);
}

TEST(WaterSolver, RejectsBadScenes) {
  scene::Scene s = water_scene(0.01, {-1, -1}, {1, 1});
  s.run.kernel = "gaussian";
  EXPECT_THROW(WaterSolver<2>{s}, std::invalid_argument);
  s.run.kernel = "wendland_c2";
  EXPECT_NO_THROW(WaterSolver<2>{s});
  EXPECT_THROW(WaterSolver<3>{s}, std::invalid_argument);  // run.dimension = 2
  s.water.reset();
  EXPECT_THROW(WaterSolver<2>{s}, std::invalid_argument);
}

}  // namespace
}  // namespace porosph::water

namespace porosph::water {
namespace {

TEST(WaterSolver3D, StillWaterCubeWithWendlandKernel) {
  // 3D, Wendland C2: a 5 cm water cube at dp = 5 mm (1000 particles) in a 3-layer container,
  // 150 steps (~0.02 s, half an acoustic period 4 d / c = 0.03 s). Same bounds as the 2D column:
  // speeds below 1 % of sqrt(g d), no particle lost, walls below the water under pressure.
  const double d = 0.05, g = 9.81;
  scene::Scene s = testing::water_scene(0.005, {-0.1, -0.1, -0.1}, {0.2, 0.2, 0.2});
  s.run.kernel = "wendland_c2";
  s.water->sound_speed = 10.0 * std::sqrt(g * d);
  s.walls.push_back(testing::container({0, 0, 0}, {0.05, 0.05, 0.08}, 3));
  s.walls.back().open_faces = {"z+"};
  s.run.gravity = {0.0, 0.0, -g};
  s.water->blocks.push_back(testing::box({0, 0, 0}, {0.05, 0.05, d}));
  WaterSolver<3> f(s);
  ASSERT_EQ(f.free_count(), 1000u);
  for (int i = 0; i < 150; ++i) {
    f.compute_rates();
    f.advance(f.dt_limits().min());
  }
  coupling::StepState state;
  f.compute_rates();
  f.fill_state(state, {}, {});
  EXPECT_LT(state.diagnostics.max_speed, 0.01 * std::sqrt(g * d));
  EXPECT_EQ(f.free_count(), 1000u);
  std::int64_t id = -1;
  EXPECT_FALSE(f.find_non_finite(&id).has_value());
  ASSERT_EQ(state.region_min.size(), 3u);
  EXPECT_NEAR(state.region_min[2], 0.0025, 1e-3);
}

}  // namespace
}  // namespace porosph::water
