// Each water-phase term on two hand-made particles against values computed by hand, the EOS, and
// momentum conservation of the pair loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "fluid_solver/artificial_viscosity.h"
#include "fluid_solver/continuity.h"
#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/pressure_force.h"
#include "fluid_solver/viscosity_morris.h"
#include "fluid_solver/water_rates.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

// Two particles: a at the origin, b at (6 mm, 0); cubic spline, h = 10 mm (q = 0.6).
// By hand: sigma = 10 / (7 pi h^2) = 4547.284088, dW/dr = sigma/h (-3q + 9/4 q^2) = -450181.1247,
// grad_a W_ab = dW/dr x_ab / r = (+450181.1247, 0) (pointing from a towards b).
struct TwoParticles {
  const double h = 0.01, r = 0.006, m_b = 0.1;
  const Vec2 x_ab{-0.006, 0.0};
  const Vec2 grad_w{450181.1247456467, 0.0};
  const double eta2 = 0.01 * h * h;
};

TEST(WaterTerms, KernelGradientOfTheFixture) {
  const TwoParticles t;
  const sph::CubicSpline<2> kernel(t.h);
  EXPECT_NEAR(kernel.gradient(t.x_ab, t.r)[0], t.grad_w[0], 1e-6);
}

TEST(WaterTerms, ContinuityOfApproachingPairIsPositive) {
  // v_ab = (1, 0): (m_b / rho_b) v_ab . grad W = 1e-4 * 450181.12 = 45.018112; drho_a/dt = rho_a x.
  const TwoParticles t;
  const double term = continuity_term<2>(t.m_b / 1000.0, Vec2(1.0, 0.0), t.grad_w);
  EXPECT_NEAR(term, 45.018112474564674, 1e-9);
  EXPECT_NEAR(continuity_term<2>(t.m_b / 1000.0, Vec2(-1.0, 0.0), t.grad_w), -term, 1e-12);
}

TEST(WaterTerms, PressureIsRepulsive) {
  // -m_b (p_a + p_b) / (rho_a rho_b) grad W = -0.1 * 400 / 1e6 * 450181.12 = -18.007245 (away
  // from b).
  const TwoParticles t;
  const Vec2 acc = pressure_acceleration<2>(t.m_b, 100.0, 300.0, 1e-3, 1e-3, t.grad_w);
  EXPECT_NEAR(acc[0], -18.00724498982587, 1e-9);
  EXPECT_EQ(acc[1], 0.0);
}

TEST(WaterTerms, MorrisViscosityOpposesRelativeVelocity) {
  // factor = x_ab . grad W / (r^2 + 0.01 h^2) = -2701.0867 / 3.7e-5 = -73002.34;
  // a = m_b (mu_a + mu_b) / (rho_a rho_b) factor v_ab = 0.1 * 2e-3 / 1e6 * factor = -0.0146005.
  const TwoParticles t;
  const double factor =
      regularised_gradient_factor(t.x_ab.dot(t.grad_w), 1.0 / (t.r * t.r + t.eta2));
  const Vec2 acc =
      morris_viscous_acceleration<2>(t.m_b, 1e-3, 1e-3, 1e-3, 1e-3, factor, Vec2(1.0, 0.0));
  EXPECT_NEAR(acc[0], -0.014600468910669625, 1e-12);
  EXPECT_EQ(acc[1], 0.0);
  // A transverse relative velocity is damped too (shear).
  const Vec2 shear =
      morris_viscous_acceleration<2>(t.m_b, 1e-3, 1e-3, 1e-3, 1e-3, factor, Vec2(0.0, 1.0));
  EXPECT_LT(shear[1], 0.0);
}

TEST(WaterTerms, ArtificialViscosityRepelsApproachingAndIgnoresReceding) {
  // alpha 0.1, beta 0, c = 20: mu_ab = h v.x / (r^2 + eta^2) = -1.621622,
  // Pi = -alpha c mu / rho = 0.00324324, a = -m_b Pi grad W = -146.0047 (decelerates a).
  const TwoParticles t;
  const ArtificialViscosity av{0.1, 0.0, t.h};
  const double inv_r2_eta2 = 1.0 / (t.r * t.r + t.eta2);
  const Vec2 approaching = av.acceleration<2>(t.m_b, Vec2(1.0, 0.0), t.x_ab, inv_r2_eta2, 20.0,
                                              20.0, 1000.0, 1000.0, t.grad_w);
  EXPECT_NEAR(approaching[0], -146.00468910669625, 1e-9);
  const Vec2 receding = av.acceleration<2>(t.m_b, Vec2(-1.0, 0.0), t.x_ab, inv_r2_eta2, 20.0, 20.0,
                                           1000.0, 1000.0, t.grad_w);
  EXPECT_EQ(receding.norm(), 0.0);
  // beta adds the quadratic part: Pi = (0 + beta mu^2) / rho with alpha = 0.
  const ArtificialViscosity quadratic{0.0, 1.0, t.h};
  EXPECT_NEAR(quadratic.pi(-0.006, inv_r2_eta2, 20.0, 1000.0),
              1.6216216216216217 * 1.6216216216216217 / 1000, 1e-15);
}

TEST(WaterTerms, TaitEquationOfStateAndInverse) {
  // B = rho0 c^2 / gamma = 1000 * 400 / 7; p(1010) = B (1.01^7 - 1) = 3874.92 Pa.
  const TaitEos eos(1000.0, 20.0, 7.0);
  EXPECT_NEAR(eos.b(), 400000.0 / 7.0, 1e-9);
  EXPECT_NEAR(eos.pressure(1010.0), 400000.0 / 7.0 * (std::pow(1.01, 7) - 1.0), 1e-9);
  EXPECT_EQ(eos.pressure(1000.0), 0.0);
  for (double p : {-5000.0, 0.0, 981.0, 1e5}) EXPECT_NEAR(eos.pressure(eos.density(p)), p, 1e-8);
  // Sound speed c0 (rho/rho0)^3 for gamma 7; the generic path (gamma 7.5) agrees with pow().
  EXPECT_NEAR(eos.sound_speed(1010.0), 20.0 * std::pow(1.01, 3), 1e-12);
  const TaitEos generic(1000.0, 20.0, 7.5);
  EXPECT_NEAR(generic.pressure(1010.0), 1000.0 * 400 / 7.5 * (std::pow(1.01, 7.5) - 1.0), 1e-9);
  EXPECT_NEAR(generic.density(generic.pressure(990.0)), 990.0, 1e-9);
  // Tension beyond -B is clamped to rho0 / 2 instead of a zero or NaN density.
  EXPECT_NEAR(eos.density(-2.0 * eos.b()), 500.0, 1e-9);
}

TEST(WaterTerms, RatesLoopSumsTheTermsPlusGravity) {
  // The two-particle fixture through compute_water_rates (mu 1e-3, alpha 0.1, c 20, g = -9.81 y):
  // a_a = pressure + Morris + artificial + g, drho_a = rho_a * continuity.
  const TwoParticles t;
  auto P = testing::make_particles<2>({Vec2(0, 0), Vec2(0.006, 0)}, 2, 1000.0, t.m_b);
  P.velocity[0] = Vec2(1.0, 0.0);
  P.pressure[0] = 100.0;
  P.pressure[1] = 300.0;
  WaterParams<2> params;
  params.h = t.h;
  params.mu = 1e-3;
  params.eta2 = t.eta2;
  params.artificial = ArtificialViscosity{0.1, 0.0, t.h};
  params.gravity = Vec2(0.0, -9.81);
  sph::NeighbourList<2> list;
  list.build(P.position.data(), 2, 2, 2.0 * t.h, sph::DomainBox<2>{});
  const RateSummary s = compute_water_rates(list, sph::CubicSpline<2>(t.h), params, P);
  const double expected_x = -18.00724498982587 - 0.014600468910669625 - 146.00468910669625;
  EXPECT_NEAR(P.acceleration[0][0], expected_x, 1e-8);
  EXPECT_NEAR(P.acceleration[0][1], -9.81, 1e-12);
  EXPECT_NEAR(P.density_rate[0], 45018.112474564674, 1e-6);
  EXPECT_NEAR(P.acceleration[1][0], -expected_x, 1e-8);  // equal masses: action = -reaction
  EXPECT_NEAR(s.max_speed, 1.0, 1e-15);
}

TEST(WaterTerms, PairLoopConservesMomentum) {
  // Random cloud, random pressures, densities and velocities, no gravity: every term is
  // antisymmetric in (a, b), so sum_a m_a dv_a/dt vanishes to round-off (1e-12 of sum |m a|).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(300);
  for (auto& p : x) p = Vec2(0.1 * u(rng), 0.1 * u(rng));
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    P.mass[i] = 0.02 + 0.01 * u(rng);
    P.density[i] = 990.0 + 20.0 * u(rng);
    P.pressure[i] = 2000.0 * u(rng) - 500.0;
    P.sound_speed[i] = 20.0 + u(rng);
    P.velocity[i] = Vec2(u(rng) - 0.5, u(rng) - 0.5);
  }
  WaterParams<2> params;
  params.h = 0.006;
  params.mu = 1e-3;
  params.eta2 = 0.01 * params.h * params.h;
  params.artificial = ArtificialViscosity{0.1, 0.2, params.h};
  sph::NeighbourList<2> list;
  list.build(P.position.data(), x.size(), x.size(), 2.0 * params.h, sph::DomainBox<2>{});
  compute_water_rates(list, sph::CubicSpline<2>(params.h), params, P);
  Vec2 total = Vec2::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    total += P.mass[i] * P.acceleration[i];
    scale += P.mass[i] * P.acceleration[i].norm();
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(total.norm(), 1e-12 * scale);
}

/// A random cloud of water particles with random velocities at two levels, densities near rho0,
/// a uniform pressure (for the difference-form test) and mu, alpha > 0.
WaterParticles<2> random_cloud(std::size_t count, double pressure, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(count);
  for (auto& p : x) p = Vec2(0.1 * u(rng), 0.1 * u(rng));
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    P.mass[i] = 0.036;
    P.density[i] = 995.0 + 10.0 * u(rng);
    P.pressure[i] = pressure;
    P.sound_speed[i] = 20.0;
    P.velocity[i] = Vec2(u(rng) - 0.5, u(rng) - 0.5);
    P.velocity_previous[i] = Vec2(u(rng) - 0.5, u(rng) - 0.5);
  }
  return P;
}

TEST(WaterTerms, ViscousTermsOfAVerletStepActOnThePreviousLevel) {
  // viscous_level.h: at ViscousLevel::Previous the Morris and artificial viscosities take v^{n-1}
  // (velocity_previous); the continuity equation and the reported speed keep v^n. Same rates as
  // evaluating everything at the current level with the two velocity levels swapped, except
  // the continuity term.
  std::mt19937 rng(11);
  auto P = random_cloud(200, 0.0, rng);
  WaterParams<2> params;
  params.h = 0.006;
  params.mu = 1e-3;
  params.eta2 = 0.01 * params.h * params.h;
  params.artificial = ArtificialViscosity{0.1, 0.2, params.h};
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.size(), 2.0 * params.h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(params.h);
  auto lagged = P;
  const RateSummary s = compute_water_rates(list, kernel, params, lagged, ViscousLevel::Previous);
  auto swapped = P;
  std::swap(swapped.velocity, swapped.velocity_previous);
  compute_water_rates(list, kernel, params, swapped, ViscousLevel::Current);
  auto current = P;
  compute_water_rates(list, kernel, params, current, ViscousLevel::Current);
  double largest = 0.0, change = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_NEAR((lagged.acceleration[i] - swapped.acceleration[i]).norm(), 0.0,
                1e-12 * (1.0 + swapped.acceleration[i].norm()));
    EXPECT_EQ(lagged.density_rate[i], current.density_rate[i]);  // continuity at v^n
    largest = std::max(largest, swapped.acceleration[i].norm());
    change = std::max(change, (lagged.acceleration[i] - current.acceleration[i]).norm());
  }
  EXPECT_GT(change, 1e-3 * largest);  // the levels differ, so the test tests something
  double max_speed = 0.0;
  for (const auto& v : P.velocity) max_speed = std::max(max_speed, v.norm());
  EXPECT_EQ(s.max_speed, max_speed);
}

TEST(WaterTerms, DensityDiffusionOfAVerletStepActsOnThePreviousLevel) {
  // viscous_level.h, fill_diffusion_states: at ViscousLevel::Previous the density diffusion takes
  // rho^{n-1} (density_previous). A random density field with a uniform previous level (no
  // gravity): the lagged diffusion is exactly zero, so the density rate is the continuity term
  // alone, the one of delta = 0; at the current level the diffusion acts.
  std::mt19937 rng(13);
  auto P = random_cloud(200, 0.0, rng);
  std::fill(P.density_previous.begin(), P.density_previous.end(), 1001.0);
  WaterParams<2> params;
  params.h = 0.006;
  params.eta2 = 0.01 * params.h * params.h;
  params.gravity = Vec2::Zero();
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.size(), 2.0 * params.h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(params.h);
  auto without = P;
  compute_water_rates(list, kernel, params, without, ViscousLevel::Previous);
  params.density_diffusion = 0.1;
  auto lagged = P, current = P;
  compute_water_rates(list, kernel, params, lagged, ViscousLevel::Previous);
  compute_water_rates(list, kernel, params, current, ViscousLevel::Current);
  double change = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_NEAR(lagged.density_rate[i], without.density_rate[i],
                1e-12 * (1.0 + std::abs(without.density_rate[i])));
    change = std::max(change, std::abs(current.density_rate[i] - without.density_rate[i]));
    largest = std::max(largest, std::abs(without.density_rate[i]));
  }
  EXPECT_GT(change, 1e-2 * largest);  // the current level's diffusion is real
}

TEST(WaterTerms, PressureDifferenceFormWithShiftingIsZerothOrderConsistent) {
  // pressure_force.h: with particle shifting on, a uniform pressure exerts no force on a
  // disordered cloud (difference form); the symmetric form pushes every particle by
  // 2 p / rho grad C, the residue the shifting does not need.
  std::mt19937 rng(5);
  auto P = random_cloud(300, 5000.0, rng);
  for (auto& v : P.velocity) v = Vec2::Zero();
  P.velocity_previous = P.velocity;
  WaterParams<2> params;
  params.h = 0.006;
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.size(), 2.0 * params.h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(params.h);
  auto symmetric = P;
  compute_water_rates(list, kernel, params, symmetric);
  params.particle_shifting = 2.0;
  compute_water_rates(list, kernel, params, P);
  double residue = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_EQ(P.acceleration[i].norm(), 0.0);
    residue = std::max(residue, symmetric.acceleration[i].norm());
  }
  EXPECT_GT(residue, 1.0);  // 5 kPa over a 6 mm kernel: a large spurious push without it
}

}  // namespace
}  // namespace porosph::water
