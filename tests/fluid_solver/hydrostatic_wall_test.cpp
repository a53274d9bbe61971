// Hydrostatic initial state, Adami wall interpolation of a hydrostatic field, Shepard filter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fluid_solver/density_filter.h"
#include "fluid_solver/hydrostatic_initial.h"
#include "fluid_solver/wall_boundary.h"
#include "sph/geometry.h"
#include "sph/kernels.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

TEST(WaterHydrostatic, DensityIsInverseEosOfRhoGDepth) {
  // Block 0.1 m wide, 0.2 m deep at dp = 0.01: p = p(0.2 - y) of still weakly compressible water
  // (the free surface half a spacing above the top centres), rho = inverse EOS(p), to round-off;
  // p(d) = B ((1 + (6/7) rho0 g d / B)^(7/6) - 1) = rho0 g d (1 + g d / (2 c0^2) + ...).
  const TaitEos eos(1000.0, 14.0, 7.0);
  const auto x = sph::fill_shape<2>(testing::box({0, 0}, {0.1, 0.2}), 0.01);
  std::vector<double> p(x.size()), rho(x.size());
  hydrostatic_state<2>(x.data(), x.size(), Vec2(0, -9.81), 0.01, eos, p.data(), rho.data());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = 0.2 - x[i][1], b = 1000.0 * 14.0 * 14.0 / 7.0;
    const double expected =
        b * (std::pow(1.0 + 6.0 / 7.0 * 1000.0 * 9.81 * d / b, 7.0 / 6.0) - 1.0);
    EXPECT_NEAR(expected, 1000.0 * 9.81 * d * (1.0 + 9.81 * d / (2.0 * 14.0 * 14.0)),
                1e-3 * 1000.0 * 9.81 * d);  // the second-order term is ~1e-4 relative here
    EXPECT_NEAR(p[i], expected, 1e-9);
    EXPECT_NEAR(rho[i], eos.density(expected), 1e-12);
  }
}

TEST(WaterHydrostatic, FollowsGravityNotAnAxisAndColumnTops) {
  // Gravity along -x: "up" is +x. An L-shaped body (two blocks) has two column heights.
  const TaitEos eos(1000.0, 14.0, 7.0);
  auto x = sph::fill_shape<2>(testing::box({0, 0}, {0.2, 0.05}), 0.01);  // short columns: x < 0.2
  const auto tall = sph::fill_shape<2>(testing::box({0, 0.05}, {0.3, 0.1}), 0.01);  // x < 0.3
  x.insert(x.end(), tall.begin(), tall.end());
  std::vector<double> p(x.size()), rho(x.size());
  hydrostatic_state<2>(x.data(), x.size(), Vec2(-9.81, 0), 0.01, eos, p.data(), rho.data());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double top = x[i][1] < 0.05 ? 0.2 : 0.3;
    EXPECT_NEAR(p[i], eos.still_water_pressure(top - x[i][0], 9.81), 1e-9) << x[i].transpose();
  }
  // 3D, gravity along -z; zero gravity gives rho0 everywhere.
  const auto x3 = sph::fill_shape<3>(testing::box({0, 0, 0}, {0.05, 0.05, 0.1}), 0.01);
  std::vector<double> p3(x3.size()), rho3(x3.size());
  hydrostatic_state<3>(x3.data(), x3.size(), sph::Vec<3>(0, 0, -9.81), 0.01, eos, p3.data(),
                       rho3.data());
  for (std::size_t i = 0; i < x3.size(); ++i)
    EXPECT_NEAR(p3[i], eos.still_water_pressure(0.1 - x3[i][2], 9.81), 1e-9);
  hydrostatic_state<3>(x3.data(), x3.size(), sph::Vec<3>::Zero(), 0.01, eos, p3.data(),
                       rho3.data());
  for (double r : rho3) EXPECT_EQ(r, 1000.0);
}

/// Water block [0, 0.1] x [0, 0.1] at dp = 5 mm in hydrostatic state above a 3-layer floor and
/// beside a 3-layer left wall; plus one isolated wall particle far away.
struct HydrostaticTank {
  const double dp = 0.005, h = 0.006, depth = 0.1;
  const TaitEos eos{1000.0, 10.0 * std::sqrt(9.81 * 0.1), 7.0};
  WaterParams<2> params;
  WaterParticles<2> P;
  sph::NeighbourList<2> list;

  HydrostaticTank() {
    auto x = sph::fill_shape<2>(testing::box({0, 0}, {0.1, depth}), dp);
    const std::size_t n_water = x.size();
    const auto walls =
        sph::fill_shape<2>(testing::container({0, 0}, {0.1, 0.2}, 3, {"y+", "x+"}), dp);
    x.insert(x.end(), walls.begin(), walls.end());
    x.push_back(Vec2(5.0, 5.0));
    params.h = h;
    params.eos = eos;
    params.volume = dp * dp;
    params.gravity = Vec2(0, -9.81);
    P = testing::make_particles<2>(x, n_water, 1000.0, 1000.0 * dp * dp);
    hydrostatic_state<2>(P.position.data(), n_water, params.gravity, dp, eos, P.pressure.data(),
                         P.density.data());
    for (std::size_t i = 0; i < n_water; ++i) P.velocity[i] = Vec2(0.3, -0.1);
    list.build(P.position.data(), P.size(), n_water, 2 * h, sph::DomainBox<2>{});
  }
};

TEST(WaterWallBoundary, InterpolatedWallPressureReproducesHydrostaticField) {
  // p_w = (sum p_f W + g . sum rho_f x_wf W) / sum W is exact for p = rho g (H - y) when rho_f =
  // rho0; with rho_f = rho0 (1 + eps), eps <= 1 % here, the error is rho0 eps g |y_f - y_w| <~
  // 1.2 Pa out of ~1000 Pa: tolerance 0.3 % of rho0 g H.
  HydrostaticTank t;
  update_wall_state(t.list, sph::CubicSpline<2>(t.h), t.params, t.P);
  const double scale = 1000.0 * 9.81 * t.depth;
  int checked = 0;
  for (std::size_t w = t.P.n_free; w + 1 < t.P.size(); ++w) {
    if (t.list.mid(w) == t.list.begin(w)) continue;  // no water neighbour
    const double y = t.P.position[w][1];
    EXPECT_NEAR(t.P.pressure[w], t.eos.still_water_pressure(0.1 - y, 9.81), 3e-3 * scale)
        << t.P.position[w].transpose();
    EXPECT_NEAR(t.P.density[w], t.eos.density(t.P.pressure[w]), 1e-12);
    EXPECT_NEAR(t.P.mass[w], t.P.density[w] * t.dp * t.dp, 1e-15);  // fixed volume dp^2
    // No-slip: mirrored velocity 2 v_w - <v_f> = -(0.3, -0.1) for a uniform water velocity.
    EXPECT_LT((t.P.wall_velocity[w] - Vec2(-0.3, 0.1)).norm(), 1e-12);
    ++checked;
  }
  EXPECT_GE(checked, 80);  // two layers within 2h of the water: 2 x (20 floor + 20 side) + corner
  const std::size_t lonely = t.P.size() - 1;  // no water neighbour: p = 0, rho0, own velocity
  EXPECT_EQ(t.P.pressure[lonely], 0.0);
  EXPECT_EQ(t.P.density[lonely], 1000.0);
  EXPECT_EQ(t.P.wall_velocity[lonely].norm(), 0.0);
}

TEST(WaterDensityFilter, KeepsTheHydrostaticGradientNextToWalls) {
  // The hydrostatic density grows by rho0 g / c^2 = 100 kg/m^4 with depth here; a filter that
  // ignored the floor would average one-sidedly and lower the bottom rows (by 0.13 kg/m^3,
  // measured). With the walls' extrapolated densities in the sums the field must stay within
  // 0.05 kg/m^3 everywhere below the top three rows (the free surface is one-sided).
  HydrostaticTank t;
  const sph::CubicSpline<2> kernel(t.h);
  update_wall_state(t.list, kernel, t.params, t.P);
  const std::vector<double> before(t.P.density.begin(), t.P.density.begin() + t.P.n_free);
  std::vector<double> scratch;
  shepard_density_filter(t.list, kernel, t.P, scratch);
  double worst = 0.0;
  for (std::size_t i = 0; i < t.P.n_free; ++i) {
    if (t.P.position[i][1] > t.depth - 3 * t.dp) continue;
    worst = std::max(worst, std::abs(t.P.density[i] - before[i]));
  }
  EXPECT_LT(worst, 0.05);
}

TEST(WaterDensityFilter, KeepsUniformInteriorAndSmoothsNoise) {
  // Shepard filter on a lattice of equal masses: rho0 in the interior stays rho0 (to 1e-9
  // relative: the Shepard ratio of a constant is exact); random +-1 % noise shrinks (the filtered
  // value is a weighted mean of the neighbours', so the spread must drop by well over half).
  const double dp = 0.01, h = 0.012;
  const auto x = sph::fill_shape<2>(testing::box({0, 0}, {0.3, 0.3}), dp);
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 1000.0 * dp * dp);
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.n_free, 2 * h, sph::DomainBox<2>{});
  std::vector<double> scratch;
  const sph::CubicSpline<2> kernel(h);
  shepard_density_filter(list, kernel, P, scratch);
  for (double rho : P.density) EXPECT_NEAR(rho, 1000.0, 1e-9 * 1000.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-10.0, 10.0);
  double before = 0.0, after = 0.0;
  for (auto& rho : P.density) rho = 1000.0 + noise(rng);
  for (double rho : P.density) before += (rho - 1000.0) * (rho - 1000.0);
  shepard_density_filter(list, kernel, P, scratch);
  for (double rho : P.density) after += (rho - 1000.0) * (rho - 1000.0);
  EXPECT_LT(after, 0.25 * before);
}

}  // namespace
}  // namespace porosph::water
