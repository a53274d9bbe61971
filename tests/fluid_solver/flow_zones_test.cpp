// Inflow and outflow zones (fluid_solver/flow_zones.h): zone geometry and speeds, the prescribed
// motion and speed ramp of zone particles, renewal of the zone lattice with fresh ids, and exact
// removal of the particles that enter an outflow zone.
#include "fluid_solver/flow_zones.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "fluid_solver/water_solver.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
const Vec2 kGravity(0.0, -9.81);
using testing::box;
using testing::inflow;
using testing::outflow;
using testing::water_scene;

TEST(FlowZones, GeometrySpeedsAndBadInput) {
  scene::WaterPhase w;
  w.inflows.push_back(inflow({0, 0}, {0.1, 0.05}, {-1, 0}, 2.0, 0.1, 0.2));
  w.outflows.push_back(outflow({1, 0}, {1.2, 0.1}));
  scene::OutflowZone later = outflow({2, 0}, {2.2, 0.1});
  later.start_time = 0.3;  // a zone that opens at 0.3 s
  w.outflows.push_back(later);
  const FlowZones<2> zones(w, 0.01, 0.012, kGravity, 0.15);  // damping stage until 0.15 s
  ASSERT_EQ(zones.inflow_count(), 1u);
  EXPECT_EQ(zones.inflow_at(Vec2(0.05, 0.02)), 0);
  EXPECT_EQ(zones.inflow_at(Vec2(0.15, 0.02)), -1);
  EXPECT_TRUE(zones.in_outflow(Vec2(1.0, 0.1), 0, 0.0));  // closed box
  EXPECT_FALSE(zones.in_outflow(Vec2(0.99, 0.05), 0, 0.0));
  EXPECT_FALSE(zones.in_outflow(Vec2(2.1, 0.05), 0, 0.29));  // not open yet
  EXPECT_TRUE(zones.in_outflow(Vec2(2.1, 0.05), 0, 0.3));
  // The ramp starts at 0.1 s but the damping stage holds it at 0 until 0.15 s; then 2 (t - 0.1) /
  // 0.2 (exact in binary up to round-off).
  EXPECT_EQ(zones.speed(0, 0.12), 0.0);
  EXPECT_NEAR(zones.speed(0, 0.2), 1.0, 1e-14);
  EXPECT_NEAR(zones.velocity(0, 0.4)[0], -2.0, 1e-14);
  EXPECT_EQ(zones.velocity(0, 0.4)[1], 0.0);

  // Downstream face of a -x zone is x = 0: a particle moved past it reports 1, one inside 0.
  FlowZones<2> moving(w, 0.01, 0.012, kGravity, 0.0);
  moving.begin_step(1.0, 0.01);  // full speed 2: the step moves by 0.02
  Vec2 x(0.025, 0.02), v, v_previous;
  EXPECT_EQ(moving.move(0, x, v, v_previous, 0.01), 0);
  EXPECT_EQ(moving.move(0, x, v, v_previous, 0.01), 1);
  EXPECT_NEAR(x[0], -0.015, 1e-15);
  EXPECT_EQ(v, Vec2(-2.0, 0.0));

  scene::WaterPhase diagonal;
  diagonal.inflows.push_back(inflow({0, 0}, {0.1, 0.1}, {0.6, 0.8}, 1.0));
  EXPECT_THROW((FlowZones<2>(diagonal, 0.01, 0.012, kGravity, 0.0)), std::invalid_argument);
  scene::WaterPhase empty_box;
  empty_box.outflows.push_back(outflow({0, 0}, {0.1, 0.0}));
  EXPECT_THROW((FlowZones<2>(empty_box, 0.01, 0.012, kGravity, 0.0)), std::invalid_argument);
  EXPECT_THROW((FlowZones<3>(w, 0.01, 0.012, sph::Vec<3>(0, 0, -9.81), 0.0)),
               std::invalid_argument);  // 2-component vectors
  // An inflow zone shorter along its direction than the kernel support 2h = 0.024 m.
  scene::WaterPhase shallow;
  shallow.inflows.push_back(inflow({0, 0}, {0.1, 0.02}, {0, 1}, 1.0));
  EXPECT_THROW((FlowZones<2>(shallow, 0.01, 0.012, kGravity, 0.0)), std::invalid_argument);
  shallow.inflows[0].max[1] = 0.024;
  EXPECT_NO_THROW((FlowZones<2>(shallow, 0.01, 0.012, kGravity, 0.0)));
}

// water.outflow[].stagger: a row rising through the lower face of the box leaves one particle at
// a time. With stagger 1 and dp 0.01, particle id k leaves once it is frac(k / golden) dp above the
// face: of 60 ids at half a spacing above it about half (the sequence's discrepancy is below 2 in
// 60), all at a spacing, none below the face; ids 0 and 1 on their exact thresholds.
TEST(FlowZones, StaggeredOutflowReleasesARowOneParticleAtATime) {
  scene::WaterPhase w;
  w.outflows.push_back(outflow({0, 0.1}, {0.6, 0.2}));
  w.outflows[0].stagger = 1.0;
  const FlowZones<2> zones(w, 0.01, 0.012, kGravity, 0.0);
  int half = 0, full = 0, below = 0;
  for (std::int64_t id = 0; id < 60; ++id) {
    const double x = 0.005 + 0.01 * static_cast<double>(id);
    half += zones.in_outflow(Vec2(x, 0.105), id, 0.0);
    full += zones.in_outflow(Vec2(x, 0.11), id, 0.0);
    below += zones.in_outflow(Vec2(x, 0.0999), id, 0.0);
  }
  EXPECT_NEAR(half, 30, 2);
  EXPECT_EQ(full, 60);
  EXPECT_EQ(below, 0);
  EXPECT_TRUE(zones.in_outflow(Vec2(0.1, 0.1), 0, 0.0));      // s(0) = 0: at the face
  EXPECT_FALSE(zones.in_outflow(Vec2(0.1, 0.1061), 1, 0.0));  // s(1) = 0.618
  EXPECT_TRUE(zones.in_outflow(Vec2(0.1, 0.1062), 1, 0.0));
  // Gravity along +y: the lower face is the box's max.
  const FlowZones<2> upside_down(w, 0.01, 0.012, Vec2(0.0, 9.81), 0.0);
  EXPECT_FALSE(upside_down.in_outflow(Vec2(0.1, 0.1939), 1, 0.0));
  EXPECT_TRUE(upside_down.in_outflow(Vec2(0.1, 0.1938), 1, 0.0));
  // Without gravity the face is undefined.
  EXPECT_THROW((FlowZones<2>(w, 0.01, 0.012, Vec2(0.0, 0.0), 0.0)), std::invalid_argument);
}

/// Zone particles of a lone inflow zone [0, 0.4] x [0, 0.02]^(D-1) along +x (dp 0.01: 40 rows of
/// 2^(D-1) columns), speed 2 m/s ramped from t = 0.1 s over 0.2 s, no gravity, dt = 1e-4 s.
/// Checks, at t = 0.05 (before the ramp), 0.2 (mid-ramp), 0.3 (end) and 0.35 s (full speed):
/// every zone particle moves with v = speed_at(t) e, an initial particle has moved by the exact
/// integral of the ramp (the midpoint rule is exact for it: round-off only), the zone keeps its
/// particle count and lattice, and each column has emitted one particle per row crossed, with
/// fresh unique ids and m = rho dp^D.
template <int D>
void check_ramp_and_renewal() {
  const double dp = 0.01, speed = 2.0, start = 0.1, ramp = 0.2, dt = 1e-4;
  // Domain: the emitted particles stay below x = 0.4 + 0.3 (the zone's displacement); a tight box
  // keeps the cell grid small.
  std::vector<double> lo(D, -0.05), hi(D, 0.07), zone_hi(D, 0.02);
  hi[0] = 1.0;
  zone_hi[0] = 0.4;
  scene::Scene s = water_scene(dp, lo, hi);
  s.run.gravity.assign(D, 0.0);
  std::vector<double> e(D, 0.0);
  e[0] = 1.0;
  s.water->inflows.push_back(inflow(std::vector<double>(D, 0.0), zone_hi, e, speed, start, ramp));
  WaterSolver<D> f(s);
  const std::size_t columns = D == 2 ? 2 : 4, zone_size = 40 * columns;
  ASSERT_EQ(f.free_count(), zone_size);
  const std::int64_t first_new_id = static_cast<std::int64_t>(zone_size);
  std::map<std::int64_t, sph::Vec<D>> x0;
  for (std::size_t a = 0; a < f.free_count(); ++a)
    x0[f.particles().id[a]] = f.particles().position[a];

  const double checks[] = {0.05, 0.2, 0.3, 0.35};
  // Displacement: integral of speed_at from 0 to t.
  const double displacement[] = {0.0, 0.5 * speed * 0.1 * 0.1 / ramp, 0.5 * speed * ramp,
                                 0.5 * speed * ramp + speed * 0.05};
  int step = 0;
  for (int c = 0; c < 4; ++c) {
    const int steps = static_cast<int>(std::lround(checks[c] / dt));
    for (; step < steps; ++step) {
      f.compute_rates();
      const std::int64_t born_before = first_new_id + static_cast<std::int64_t>(f.born_count());
      f.advance(dt);
      // Particles born in this step: m = rho dp^D at the density they were born with (which no
      // integration has changed yet), round-off only.
      const WaterParticles<D>& P = f.particles();
      for (std::size_t a = 0; a < P.n_free; ++a) {
        if (P.id[a] < born_before) continue;
        EXPECT_NEAR(P.mass[a], P.density[a] * std::pow(dp, D), 1e-15 * P.mass[a]);
        EXPECT_EQ(P.zone[a], 0);
      }
    }
    const double t = f.time();
    const double u = s.water->inflows[0].speed_at(t);
    const WaterParticles<D>& P = f.particles();
    std::size_t in_zone = 0;
    std::set<std::int64_t> ids;
    for (std::size_t a = 0; a < P.n_free; ++a) {
      EXPECT_TRUE(ids.insert(P.id[a]).second) << "duplicate id " << P.id[a];
      // Masses follow the densities at birth: rho0 up to the compression of the zone front by the
      // accelerating zone behind it, which catches up with the slower particles it emitted
      // earlier (measured < 0.12 %; bound 1 %).
      EXPECT_NEAR(P.mass[a], 1000.0 * std::pow(dp, D), 1e-2 * P.mass[a]);
      if (P.zone[a] < 0) continue;
      ++in_zone;
      EXPECT_NEAR(P.velocity[a][0], u, 1e-12) << "t = " << t;
      for (int k = 1; k < D; ++k) EXPECT_EQ(P.velocity[a][k], 0.0);
      // On the lattice: x - dp/2 is a multiple of dp along x after removing the displacement.
      const double rows = (P.position[a][0] - displacement[c] - 0.5 * dp) / dp;
      EXPECT_NEAR(rows, std::round(rows), 1e-6) << "t = " << t;
      const auto it = x0.find(P.id[a]);
      if (it == x0.end()) continue;  // born later
      EXPECT_NEAR(P.position[a][0] - it->second[0], displacement[c], 1e-10) << "t = " << t;
      for (int k = 1; k < D; ++k) EXPECT_EQ(P.position[a][k], it->second[k]);
    }
    EXPECT_EQ(in_zone, zone_size) << "t = " << t;
    // Row i (centre 0.005 + 0.01 i) has crossed x = 0.4 once the displacement exceeds its distance
    // to the face; none of the newborn rows has travelled 0.4 m yet.
    std::size_t crossed_rows = 0;
    for (int i = 0; i < 40; ++i) crossed_rows += displacement[c] > 0.4 - (0.005 + 0.01 * i);
    EXPECT_EQ(f.born_count(), crossed_rows * columns) << "t = " << t;
    EXPECT_EQ(P.n_free, zone_size + f.born_count());
    EXPECT_EQ(*ids.rbegin(), first_new_id + static_cast<std::int64_t>(f.born_count()) - 1);
  }
  EXPECT_EQ(f.born_count(), 30 * columns);  // displacement 0.3 m at t = 0.35 s: 30 rows crossed
}

TEST(InflowZone, SpeedRampPrescribedMotionAndLatticeRenewal2D) { check_ramp_and_renewal<2>(); }
TEST(InflowZone, SpeedRampPrescribedMotionAndLatticeRenewal3D) { check_ramp_and_renewal<3>(); }

// A zone whose rows reach past its box along the flow (0.036 m at dp 0.01 holds four rows, 0.04
// m) and which starts at the domain's face: each particle is handed over at the lattice's end,
// so the one born 0.04 m upstream lands inside the box. Handed over at the box's face (before),
// the newborn landed 4 mm outside the domain and was removed: the zone emptied after its first
// rows (the rockfill sheet at dp 0.0283, a 0.1 m box, injected four particles and stopped).
TEST(InflowZone, RowsReachingPastTheBoxKeepTheZoneFull) {
  const double dp = 0.01, dt = 1e-4;
  scene::Scene s = water_scene(dp, {0.0, -0.05}, {1.0, 0.07});
  s.run.gravity.assign(2, 0.0);
  s.water->inflows.push_back(inflow({0.0, 0.0}, {0.036, 0.02}, {1.0, 0.0}, 1.0));
  WaterSolver<2> f(s);
  const std::size_t zone_size = 4 * 2;  // four rows along x, two across
  ASSERT_EQ(f.free_count(), zone_size);
  for (int step = 0; step < 1500; ++step) {  // 0.15 m at 1 m/s
    f.compute_rates();
    f.advance(dt);
  }
  const WaterParticles<2>& P = f.particles();
  std::size_t in_zone = 0;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    if (P.zone[a] < 0) continue;
    ++in_zone;
    EXPECT_GE(P.position[a][0], 0.0);
    EXPECT_LE(P.position[a][0], 0.04);
  }
  EXPECT_EQ(in_zone, zone_size);
  // A row crosses x = 0.04 at every 0.01 m of travel from 0.005 m on: 15 rows by 0.15 m.
  EXPECT_EQ(f.born_count(), 15 * 2u);
  EXPECT_EQ(P.n_free, zone_size + f.born_count());
}

TEST(OutflowZone, RemovesExactlyTheParticlesThatEnterIt) {
  // Eight isolated particles (0.1 m apart: no neighbours within 2h = 0.024 m) fall from
  // centres y0 = 0.0123 + 0.0457 i under g; their positions are exact parabolas (round-off only,
  // see FreeParticleFollowsTheExactParabola). Outflow box x in [0.05, 0.75], y in [-1, 0]: particle
  // 0 (x = 0.005) falls beside it and stays; the others are removed at the first step that ends
  // with y <= 0 - no earlier, no later. The y0 are such that no step ends within 1e-6 m of y = 0.
  scene::Scene s = water_scene(0.01, {-1, -2}, {1, 1});
  for (int i = 0; i < 8; ++i) {
    const double x = 0.1 * i, y = 0.0073 + 0.0457 * i;  // lattice centre: + 0.005
    s.water->blocks.push_back(box({x, y}, {x + 0.01, y + 0.01}));
  }
  s.water->outflows.push_back(outflow({0.05, -1.0}, {0.75, 0.0}));
  WaterSolver<2> f(s);
  ASSERT_EQ(f.free_count(), 8u);
  std::map<std::int64_t, Vec2> x0;
  for (std::size_t a = 0; a < 8; ++a) x0[f.particles().id[a]] = f.particles().position[a];
  const double dt = 1e-3, g = 9.81;
  std::size_t expected_removed = 0;
  for (int n = 1; n <= 300; ++n) {
    f.compute_rates();
    f.advance(dt);
    const double drop = 0.5 * g * (n * dt) * (n * dt);
    std::set<std::int64_t> expected;
    for (const auto& [id, x] : x0) {
      const double y = x[1] - drop;
      ASSERT_GT(std::abs(y), 1e-6) << "test set-up: a particle ends a step on the face";
      if (x[0] < 0.05 || y > 0.0) expected.insert(id);
    }
    std::set<std::int64_t> present;
    for (std::size_t a = 0; a < f.free_count(); ++a) present.insert(f.particles().id[a]);
    ASSERT_EQ(present, expected) << "step " << n;
    expected_removed = x0.size() - expected.size();
    ASSERT_EQ(f.removed_count(), expected_removed) << "step " << n;
  }
  EXPECT_EQ(expected_removed, 7u);  // all but the one beside the box by t = 0.3 s (drop 0.44 m)
  coupling::StepState state;
  f.compute_rates();
  f.fill_state(state, {}, {});
  EXPECT_EQ(state.diagnostics.removed_count, 7u);
  EXPECT_NEAR(state.diagnostics.mass, f.particles().mass[0], 1e-15);
}

}  // namespace
}  // namespace porosph::water
