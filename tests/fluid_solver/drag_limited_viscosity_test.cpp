// The artificial viscosity inside soil (fluid_solver/artificial_viscosity.h,
// water.artificial_viscosity_in_soil): the share s = min(1, lambda / r_av) that the seepage drag
// replaces, the pair weight 1 - (s_a + s_b) / 2 in the rates loop, and the solver taking the
// coupler's drag rates.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "fluid_solver/artificial_viscosity.h"
#include "fluid_solver/water_rates.h"
#include "fluid_solver/water_solver.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
constexpr double kPi = 3.14159265358979323846;

TEST(DragLimitedViscosity, KernelDampingRateAndTheShareTheDragReplaces) {
  // r_av = alpha c0 pi^2 / (2 (D + 2) h): alpha 0.05, c0 20 m/s, h 12 mm -> 102.8 1/s in 2D,
  // 82.2 1/s in 3D (by hand).
  const double r2 = ArtificialViscosity::kernel_damping_rate(0.05, 20.0, 0.012, 2);
  EXPECT_NEAR(r2, 0.05 * 20.0 * kPi * kPi / (8.0 * 0.012), 1e-12);
  EXPECT_NEAR(r2, 102.808, 1e-3);
  EXPECT_NEAR(ArtificialViscosity::kernel_damping_rate(0.05, 20.0, 0.012, 3), 82.247, 1e-3);
  const ArtificialViscosity av{0.05, 0.0, 0.012, r2};
  EXPECT_EQ(av.cut(0.0), 0.0);
  EXPECT_NEAR(av.cut(0.5 * r2), 0.5, 1e-15);
  EXPECT_EQ(av.cut(r2), 1.0);
  EXPECT_EQ(av.cut(196.2), 1.0);  // the seepage weir's sand: g / K = 9.81 / 0.05
  EXPECT_EQ(av.cut(-1.0), 0.0);
  EXPECT_EQ(av.cut(std::numeric_limits<double>::quiet_NaN()), 0.0);
  const ArtificialViscosity full{0.05, 0.0, 0.012, 0.0};  // artificial_viscosity_in_soil = "full"
  EXPECT_EQ(full.cut(1e6), 0.0);
  // The stability argument: the kernel-scale noise is damped at r_av (1 - s) + lambda >= r_av,
  // whatever the drag rate.
  for (double lambda = 0.0; lambda < 10.0 * r2; lambda += 0.37) {
    EXPECT_GE(r2 * (1.0 - av.cut(lambda)) + lambda, r2 * (1.0 - 1e-15)) << lambda;
  }
}

/// A random cloud of 300 water particles with random velocities, densities, sound speeds and
/// masses, and the list of its pairs at h = 6 mm.
struct Cloud {
  WaterParticles<2> P;
  WaterParams<2> params;
  sph::NeighbourList<2> list;
  explicit Cloud(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec2> x(300);
    for (auto& p : x) p = Vec2(0.1 * u(rng), 0.1 * u(rng));
    P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
    for (std::size_t i = 0; i < x.size(); ++i) {
      P.mass[i] = 0.02 + 0.01 * u(rng);
      P.density[i] = 990.0 + 20.0 * u(rng);
      P.sound_speed[i] = 20.0 + u(rng);
      P.velocity[i] = Vec2(u(rng) - 0.5, u(rng) - 0.5);
    }
    params.h = 0.006;
    params.eta2 = 0.01 * params.h * params.h;
    list.build(P.position.data(), x.size(), x.size(), 2.0 * params.h, sph::DomainBox<2>{});
  }
  void rates(double alpha) {
    // The drag limit on (a positive r_av): the loop applies the shares set in viscosity_cut.
    params.artificial = ArtificialViscosity{alpha, 0.0, params.h, 1.0};
    compute_water_rates(list, sph::CubicSpline<2>(params.h), params, P);
  }
};

TEST(DragLimitedViscosity, WholeCutIsNoArtificialViscosityAndNoCutIsTheFullTerm) {
  // Gravity and pressure are zero: the accelerations are the artificial viscosity alone.
  Cloud c(11);
  c.rates(0.1);
  const std::vector<Vec2> full = c.P.acceleration;
  double largest = 0.0;
  for (const Vec2& a : full) largest = std::max(largest, a.norm());
  ASSERT_GT(largest, 1.0);  // the term is there
  std::fill(c.P.viscosity_cut.begin(), c.P.viscosity_cut.end(), 1.0);
  c.rates(0.1);
  for (const Vec2& a : c.P.acceleration) EXPECT_EQ(a.norm(), 0.0);
  std::fill(c.P.viscosity_cut.begin(), c.P.viscosity_cut.end(), 0.25);
  c.rates(0.1);
  for (std::size_t i = 0; i < full.size(); ++i)
    EXPECT_NEAR((c.P.acceleration[i] - 0.75 * full[i]).norm(), 0.0, 1e-12 * largest) << i;
}

TEST(DragLimitedViscosity, PairWeightKeepsMomentumWithUnequalShares) {
  // Random shares per particle: the pair keeps 1 - (s_a + s_b) / 2 on both sides, so
  // sum_a m_a a_a still vanishes to round-off (1e-12 of sum |m a|).
  Cloud c(5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double& s : c.P.viscosity_cut) s = u(rng);
  c.rates(0.1);
  Vec2 total = Vec2::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < c.P.size(); ++i) {
    total += c.P.mass[i] * c.P.acceleration[i];
    scale += c.P.mass[i] * c.P.acceleration[i].norm();
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(total.norm(), 1e-12 * scale);
}

TEST(DragLimitedViscosity, SolverTakesTheCouplersDragRates) {
  // Two isolated particles, one inside the overlap box: its share follows the rate sent, the
  // other's stays 0; an empty rate list (no drag) clears it; "full" never cuts.
  for (const char* mode : {"drag_limited", "full"}) {
    scene::Scene s = testing::water_scene(0.01, {-1, -1}, {1, 1});
    s.water->artificial_viscosity_in_soil = mode;
    s.water->blocks.push_back(testing::box({0.0, 0.0}, {0.01, 0.01}));
    s.water->blocks.push_back(testing::box({0.5, 0.0}, {0.51, 0.01}));
    WaterSolver<2> f(s);
    const double r_av = ArtificialViscosity::kernel_damping_rate(
        s.water->alpha, s.water->sound_speed, f.params().h, 2);
    const bool limited = std::string(mode) == "drag_limited";
    EXPECT_EQ(f.params().artificial.damping_rate, limited ? r_av : 0.0);
    coupling::StepState state;
    f.compute_rates();
    f.fill_state(state, {0.4, -0.1}, {0.6, 0.1});
    ASSERT_EQ(state.overlap_id.size(), 1u);
    EXPECT_THROW(f.set_drag_rate({1.0, 2.0}), std::invalid_argument);
    f.set_drag_rate({0.5 * r_av});
    const auto& P = f.particles();
    for (std::size_t i = 0; i < 2; ++i) {
      const bool in_overlap = P.id[i] == state.overlap_id[0];
      EXPECT_NEAR(P.viscosity_cut[i], in_overlap && limited ? 0.5 : 0.0, 1e-15) << mode;
    }
    f.set_drag_rate({});
    for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(P.viscosity_cut[i], 0.0);
  }
}

TEST(DragLimitedViscosity, SceneRejectsAnUnknownMode) {
  scene::Scene s = testing::water_scene(0.01, {-1, -1}, {1, 1});
  s.water->artificial_viscosity_in_soil = "sometimes";
  s.water->blocks.push_back(testing::box({0.0, 0.0}, {0.01, 0.01}));
  EXPECT_THROW(WaterSolver<2>{s}, std::invalid_argument);
}

}  // namespace
}  // namespace porosph::water
