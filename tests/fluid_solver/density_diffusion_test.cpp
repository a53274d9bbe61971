// The delta-SPH density diffusion term with the hydrostatic correction (density_diffusion.h): hand
// values on two particles, zero flux in still water where the uncorrected term is not zero, decay
// of a density bump, the diffusion coefficient delta h c0 of a sine wave, what it conserves, and
// its place in the pair loop (water pairs only, off when delta = 0).
#include "fluid_solver/density_diffusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fluid_fixtures.h"
#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/fluid_rates.h"
#include "sph/geometry.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"

namespace porosph::fluid {
namespace {

using Vec2 = sph::Vec<2>;

// The pair of terms_test.cpp: a at the origin, b at (6 mm, 0), cubic spline, h = 10 mm,
// grad_a W_ab = (450181.1247, 0), eta^2 = 0.01 h^2 = 1e-6; c0 = 20, delta = 0.1.
// By hand: x_ba . grad W = 0.006 * 450181.1247 = 2701.086748; the pair weight
// 2 x_ba . grad W / (r^2 + eta^2) = 5402.173497 / 3.7e-5 = 146004689.1067 [1/m^2 ... per volume].
TEST(DensityDiffusion, TwoParticleBumpDecaysAtTheHandComputedRate) {
  const double h = 0.01, m = 0.1;
  const TaitEos eos(1000.0, 20.0, 7.0);
  const DensityDiffusion<2> dd(0.1, h, eos, Vec2::Zero());
  const Vec2 x_ab(-0.006, 0.0), grad_w(450181.1247456468, 0.0);
  EXPECT_NEAR(dd.coefficient(), 0.1 * 0.01 * 20.0, 1e-15);  // delta h c0 [m^2/s]
  // a carries a +10 kg/m^3 bump: D_a = 0.02 * (1000 - 1010) * 146004689.1067 * 0.1 / 1000
  //   = -2920.093782 kg/m^3/s  (negative: the bump decays);
  // b gains D_b = 0.02 * (1010 - 1000) * 146004689.1067 * 0.1 / 1010 = +2891.181963.
  const double factor = x_ab.dot(grad_w) / (0.006 * 0.006 + 0.01 * h * h);  // same for b
  const double d_a = dd.coefficient() * dd.pair_term(1010.0, 1000.0, m / 1000.0, x_ab, factor);
  const double d_b =
      dd.coefficient() * dd.pair_term(1000.0, 1010.0, m / 1010.0, Vec2(-x_ab), factor);
  EXPECT_NEAR(d_a, -2920.0937821339253, 1e-8);
  EXPECT_NEAR(d_b, 2891.181962508837, 1e-8);
  // Volume-weighted: V_a D_a + V_b D_b = 0 (the pair only moves density), to round-off of the
  // O(0.3) terms.
  EXPECT_NEAR(m / 1010.0 * d_a + m / 1000.0 * d_b, 0.0, 1e-14);
  // Equal densities, no gravity: nothing to diffuse.
  EXPECT_EQ(dd.pair_term(1000.0, 1000.0, m / 1000.0, x_ab, factor), 0.0);
}

TEST(DensityDiffusion, HydrostaticDifferenceFollowsTheGravityVector) {
  // b 6 mm below a, g = (0, -9.81): still water has p_b - p_a = rho0 g . x_ba = 58.86 Pa, so
  // rho^H_ab = rho0 ((1 + 58.86 / B)^(1/7) - 1) = eos.density(58.86) - rho0 = +0.1471 kg/m^3
  // (B = 1000 * 400 / 7); b above a gives the same with the other sign to first order.
  const TaitEos eos(1000.0, 20.0, 7.0);
  const DensityDiffusion<2> down(0.1, 0.01, eos, Vec2(0.0, -9.81));
  const double below = down.hydrostatic_difference(Vec2(0.0, 0.006));  // x_ab = x_a - x_b
  EXPECT_NEAR(below, eos.density(58.86) - 1000.0, 1e-12);
  EXPECT_NEAR(below, 1000.0 * (std::pow(1.0 + 58.86 * 7.0 / 400000.0, 1.0 / 7.0) - 1.0), 1e-12);
  EXPECT_GT(below, 0.14);
  EXPECT_NEAR(down.hydrostatic_difference(Vec2(0.0, -0.006)), eos.density(-58.86) - 1000.0, 1e-12);
  // A horizontal pair has none; no axis is special: gravity along +x makes the pair along x the
  // vertical one (b at smaller x is "above").
  EXPECT_EQ(down.hydrostatic_difference(Vec2(0.006, 0.0)), 0.0);
  const DensityDiffusion<2> sideways(0.1, 0.01, eos, Vec2(9.81, 0.0));
  EXPECT_NEAR(sideways.hydrostatic_difference(Vec2(-0.006, 0.0)), below, 1e-15);
  // The binomial series to x^6 (x = rho0 g . x_ba / B) against expm1/log1p: to round-off (1e-12
  // relative) for |x| <= 0.01, within its first omitted term 0.1 x^6 (1.2e-7 at x = 0.103) beyond.
  // c0 = 2 makes x = 7 * 9.81 * dz / 4: 0.0098 at dz = 0.571 mm, 0.103 at dz = 6 mm.
  const TaitEos soft(1000.0, 2.0, 7.0);
  const DensityDiffusion<2> soft_down(0.1, 0.01, soft, Vec2(0.0, -9.81));
  for (double dz : {-0.006, -0.000571, -0.0001, 0.0001, 0.000571, 0.006}) {
    const double x = 7.0 * 9.81 * dz / 4.0;
    const double exact = 1000.0 * std::expm1(std::log1p(x) / 7.0);  // no cancellation in "- 1"
    const double tolerance = std::abs(x) <= 0.01 ? 1e-12 : 0.2 * std::pow(x, 6);
    EXPECT_NEAR(soft_down.hydrostatic_difference(Vec2(0.0, dz)), exact, tolerance * std::abs(exact))
        << dz;
  }
  const DensityDiffusion<3> down3(0.1, 0.01, eos, sph::Vec<3>(0.0, 0.0, -9.81));
  EXPECT_NEAR(down3.hydrostatic_difference(sph::Vec<3>(0.004, -0.002, 0.006)), below, 1e-15);
}

/// D_a of every particle of P (all water) from DensityDiffusion, corrected or not.
template <int D>
std::vector<double> diffusion_rates(const FluidParticles<D>& P, const sph::NeighbourList<D>& nl,
                                    const sph::CubicSpline<D>& kernel,
                                    const DensityDiffusion<D>& dd, double eta2, bool corrected) {
  std::vector<double> rate(P.n_free, 0.0);
  for (std::size_t a = 0; a < P.n_free; ++a) {
    double sum = 0.0;
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      const auto grad_w = kernel.gradient(it->x_ab, it->r);
      const double rho_a = P.density[a], rho_b = P.density[it->b];
      const double v_b = P.mass[it->b] / rho_b;
      const double factor = it->x_ab.dot(grad_w) / (it->r * it->r + eta2);
      sum += corrected ? dd.pair_term(rho_a, rho_b, v_b, it->x_ab, factor)
                       : dd.uncorrected_pair_term(rho_a, rho_b, v_b, factor);
    }
    rate[a] = dd.coefficient() * sum;
  }
  return rate;
}

/// A still water block (lattice dp = 0.01, h = 1.2 dp, c0 = 20) under `gravity`, its densities
/// from the Tait EOS of p = rho0 g . (x - x_top), x_top the highest particle (p = 0 there). Checks
/// that the corrected D_a is zero to the bound of its second-order residual everywhere (and to
/// round-off where p_a = 0), while the uncorrected term drives a flux at the top and bottom rows.
template <int D>
void expect_still_water_has_no_diffusion(const scene::Shape& block, const sph::Vec<D>& gravity) {
  const double dp = 0.01, h = 0.012, eta2 = 0.01 * h * h;
  const TaitEos eos(1000.0, 20.0, 7.0);
  const auto x = sph::fill_shape<D>(block, dp);
  auto P = testing::make_particles<D>(x, x.size(), 1000.0, 0.0);
  double top = 1e300;  // min of g . x: the highest particle
  for (const auto& xi : x) top = std::min(top, gravity.dot(xi));
  std::vector<double> p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    p[i] = 1000.0 * (gravity.dot(x[i]) - top);
    P.density[i] = eos.density(p[i]);
    P.mass[i] = P.density[i] * std::pow(dp, D);
  }
  sph::NeighbourList<D> nl;
  nl.build(P.position.data(), x.size(), x.size(), 2.0 * h, sph::DomainBox<D>{});
  const sph::CubicSpline<D> kernel(h);
  const DensityDiffusion<D> dd(0.1, h, eos, gravity);
  const auto corrected = diffusion_rates<D>(P, nl, kernel, dd, eta2, true);
  const auto uncorrected = diffusion_rates<D>(P, nl, kernel, dd, eta2, false);
  const double s = 1.0 / eos.gamma(), b = eos.b();
  double max_uncorrected = 0.0;
  int checked_surface = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    // Per pair, |rho_b - rho_a - rho^H_ab| <= ((1 + p_a / (B - p_a))^(1 - 1/gamma) - 1)
    // |rho_b - rho_a| (mean-value theorem on rho(p) = rho0 (1 + p/B)^(1/gamma), p_b >= 0), so
    // |D_a| is at most that ratio times the sum of the uncorrected |summands|.
    double abs_sum = 0.0;
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      const auto grad_w = kernel.gradient(it->x_ab, it->r);
      const double factor = it->x_ab.dot(grad_w) / (it->r * it->r + eta2);
      abs_sum += std::abs(dd.uncorrected_pair_term(P.density[a], P.density[it->b],
                                                   P.mass[it->b] / P.density[it->b], factor));
    }
    abs_sum *= dd.coefficient();
    const double ratio = std::pow(1.0 + p[a] / (b - p[a]), 1.0 - s) - 1.0;
    // Round-off: densities ~1e3 carry ~1e-13 absolute error against pair differences ~0.2 (one
    // spacing of hydrostatic head), 1e-12 relative; 1e-10 of abs_sum leaves 100x margin.
    EXPECT_LE(std::abs(corrected[a]), ratio * abs_sum + 1e-10 * abs_sum) << x[a].transpose();
    if (p[a] == 0.0) {
      EXPECT_LE(std::abs(corrected[a]), 1e-10 * abs_sum) << "surface particle " << a;
      ++checked_surface;
    }
    max_uncorrected = std::max(max_uncorrected, std::abs(uncorrected[a]));
  }
  EXPECT_GT(checked_surface, 0);
  // Without the correction the top row (only denser neighbours, below) gains density and the
  // bottom row loses it: measured 54 kg/m^3/s (2D and 3D). The corrected term's largest value is
  // at the bottom row, at most (1 + p/(B - p))^(6/7) - 1 = 3.05 % of that (p/B = 0.034; measured
  // 2.7 %). A wrong-signed correction would double the uncorrected value instead.
  double max_corrected = 0.0;
  for (double r : corrected) max_corrected = std::max(max_corrected, std::abs(r));
  EXPECT_GT(max_uncorrected, 40.0);
  EXPECT_LT(max_corrected, 0.031 * max_uncorrected);
}

TEST(DensityDiffusion, StillWaterColumnHasNoFluxWithTheCorrection) {
  // 0.1 wide, 0.2 deep, gravity down.
  expect_still_water_has_no_diffusion<2>(testing::box({0, 0}, {0.1, 0.2}), Vec2(0.0, -9.81));
  // The same column lying along x with gravity along -x: no hard-coded "up".
  expect_still_water_has_no_diffusion<2>(testing::box({0, 0}, {0.2, 0.1}), Vec2(-9.81, 0.0));
  // 3D, 0.05 x 0.05 x 0.2, gravity along -z.
  expect_still_water_has_no_diffusion<3>(testing::box({0, 0, 0}, {0.05, 0.05, 0.2}),
                                         sph::Vec<3>(0.0, 0.0, -9.81));
}

/// Particles on the lattice of `box` (periodic where asked), rho0 1000, m = rho dp^2.
FluidParticles<2> lattice(const sph::DomainBox<2>& box, double dp) {
  const auto x =
      sph::fill_shape<2>(testing::box({box.min[0], box.min[1]}, {box.max[0], box.max[1]}), dp);
  return testing::make_particles<2>(x, x.size(), 1000.0, 1000.0 * dp * dp);
}

TEST(DensityDiffusion, DensityBumpOnALatticeDecaysAndTheTotalStays) {
  // 11 x 11 lattice, dp 0.01, h 0.012, no gravity; the centre particle 1 kg/m^3 denser.
  const double dp = 0.01, h = 0.012;
  sph::DomainBox<2> box;
  box.min = Vec2(0, 0);
  box.max = Vec2(0.11, 0.11);
  auto P = lattice(box, dp);
  std::size_t centre = 0;
  for (std::size_t i = 0; i < P.n_free; ++i)
    if ((P.position[i] - Vec2(0.055, 0.055)).norm() < 1e-9) centre = i;
  P.density[centre] = 1001.0;
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), P.n_free, P.n_free, 2.0 * h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(h);
  const DensityDiffusion<2> dd(0.1, h, TaitEos(1000.0, 20.0, 7.0), Vec2::Zero());
  const auto rate = diffusion_rates<2>(P, nl, kernel, dd, 0.01 * h * h, true);
  // The centre loses density, its neighbours within 2h gain it, everybody else is untouched.
  EXPECT_LT(rate[centre], 0.0);
  double volume_weighted = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    const double r = (P.position[i] - P.position[centre]).norm();
    if (i != centre && r < 2.0 * h) {
      EXPECT_GT(rate[i], 0.0) << i;
    } else if (r >= 2.0 * h) {
      EXPECT_EQ(rate[i], 0.0) << i;
    }
    volume_weighted += P.mass[i] / P.density[i] * rate[i];
    scale += std::abs(P.mass[i] / P.density[i] * rate[i]);
  }
  // sum_a V_a D_a = 0: a flux between particles (round-off of ~20 terms of similar size).
  EXPECT_LT(std::abs(volume_weighted), 1e-13 * scale);
  // One explicit step of 1e-5 s (measured rate -674 kg/m^3/s at the centre): the bump shrinks and
  // no neighbour overshoots it.
  double peak = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    P.density[i] += 1e-5 * rate[i];
    peak = std::max(peak, std::abs(P.density[i] - 1000.0));
  }
  EXPECT_LT(P.density[centre] - 1000.0, 1.0);
  EXPECT_NEAR(peak, P.density[centre] - 1000.0, 1e-15);
}

TEST(DensityDiffusion, SineWaveDiffusesWithCoefficientDeltaHC0) {
  // The pair sum is Brookshaw's (1985) SPH Laplacian: D_a ~ delta h c0 lap(rho). On a periodic
  // lattice (dp 0.01, h 0.012) rho = rho0 + A sin(k x) with k = 2 pi / 0.4 (k h = 0.19) must give
  // D = -delta h c0 k^2 A sin(k x). Tolerance 3%: the lattice sum of the cubic spline at
  // h = 1.2 dp, the eta^2 = 0.01 h^2 regularisation (1.4% on the nearest ring) and the O((k h)^2)
  // truncation; measured 2.3 % (printed on failure).
  const double dp = 0.01, h = 0.012, k = 2.0 * M_PI / 0.4, amplitude = 1.0;
  sph::DomainBox<2> box;
  box.min = Vec2(0, 0);
  box.max = Vec2(0.4, 0.06);
  box.periodic = {true, true};
  auto P = lattice(box, dp);
  for (std::size_t i = 0; i < P.n_free; ++i)
    P.density[i] = 1000.0 + amplitude * std::sin(k * P.position[i][0]);
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), P.n_free, P.n_free, 2.0 * h, box);
  const DensityDiffusion<2> dd(0.1, h, TaitEos(1000.0, 20.0, 7.0), Vec2::Zero());
  const auto rate = diffusion_rates<2>(P, nl, sph::CubicSpline<2>(h), dd, 0.01 * h * h, true);
  double worst = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    const double expected = -dd.coefficient() * k * k * amplitude * std::sin(k * P.position[i][0]);
    worst = std::max(worst, std::abs(rate[i] - expected));
  }
  const double peak = dd.coefficient() * k * k * amplitude;
  EXPECT_LT(worst, 0.03 * peak) << "worst deviation / peak = " << worst / peak;
}

TEST(DensityDiffusion, ConservesVolumeWeightedDensityUpToTheSecondOrderHydrostaticLeak) {
  // Random cloud, random densities and masses. Without gravity the summand is antisymmetric
  // (symmetric weight K_ab times rho_b - rho_a): sum_a V_a D_a = 0 to round-off. With gravity
  // the correction adds -delta h c0 sum_{a<b} K_ab V_a V_b (rho^H_ab + rho^H_ba), and
  // rho^H_ab + rho^H_ba = rho0 ((1 + x)^s + (1 - x)^s - 2) = rho0 s (s - 1) x^2 (1 + O(x^2)) with
  // x = rho0 g . x_ba / B ~ 2e-3 here: the sum must equal that second-order expression to 1e-4.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(300);
  for (auto& p : x) p = Vec2(0.1 * u(rng), 0.1 * u(rng));
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    P.mass[i] = 0.02 + 0.01 * u(rng);
    P.density[i] = 990.0 + 20.0 * u(rng);
  }
  const double h = 0.006, eta2 = 0.01 * h * h;
  const TaitEos eos(1000.0, 20.0, 7.0);
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), x.size(), x.size(), 2.0 * h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(h);
  auto volume_weighted_sum = [&](const DensityDiffusion<2>& dd, double* scale) {
    const auto rate = diffusion_rates<2>(P, nl, kernel, dd, 0.01 * h * h, true);
    double sum = 0.0;
    *scale = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a) {
      sum += P.mass[a] / P.density[a] * rate[a];
      *scale += std::abs(P.mass[a] / P.density[a] * rate[a]);
    }
    return sum;
  };
  double scale = 0.0;
  const double no_gravity =
      volume_weighted_sum(DensityDiffusion<2>(0.1, h, eos, Vec2::Zero()), &scale);
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(std::abs(no_gravity), 1e-13 * scale);

  const Vec2 g(0.0, -9.81);
  const double with_gravity = volume_weighted_sum(DensityDiffusion<2>(0.1, h, eos, g), &scale);
  const double s = 1.0 / 7.0, coefficient = 0.1 * h * 20.0;
  double leak = 0.0;  // -delta h c0 sum_{a<b} K_ab V_a V_b rho0 s (s - 1) x_ab^2
  for (std::size_t a = 0; a < x.size(); ++a) {
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      if (static_cast<std::size_t>(it->b) < a) continue;
      const double k_ab = -2.0 * kernel.grad_factor(it->r) * it->r * it->r / (it->r * it->r + eta2);
      const double xi = 1000.0 * g.dot(-it->x_ab) / eos.b();
      leak -= coefficient * k_ab * P.mass[a] / P.density[a] * P.mass[it->b] / P.density[it->b] *
              1000.0 * s * (s - 1.0) * xi * xi;
    }
  }
  ASSERT_GT(std::abs(leak), 1e6 * 1e-13 * scale);  // well above the round-off of the sum
  EXPECT_NEAR(with_gravity, leak, 1e-4 * std::abs(leak) + 1e-13 * scale);
}

TEST(DensityDiffusion, InThePairLoopBetweenWaterParticlesOnly) {
  // compute_fluid_rates on the two-particle bump at rest (continuity term 0): drho_a/dt is the
  // hand value -2920.0938 with delta 0.1, exactly 0 with delta 0, and 0 when b is a wall particle.
  FluidParams<2> params;
  params.h = 0.01;
  params.eta2 = 1e-6;
  params.eos = TaitEos(1000.0, 20.0, 7.0);
  params.artificial = ArtificialViscosity{0.0, 0.0, params.h};
  params.gravity = Vec2(0.0, -9.81);  // horizontal pair: no hydrostatic difference
  params.density_diffusion = 0.1;
  auto rate_of_a = [&](std::size_t n_free) {
    auto P = testing::make_particles<2>({Vec2(0, 0), Vec2(0.006, 0)}, n_free, 1000.0, 0.1);
    P.density[0] = 1010.0;
    sph::NeighbourList<2> list;
    list.build(P.position.data(), 2, n_free, 2.0 * params.h, sph::DomainBox<2>{});
    compute_fluid_rates(list, sph::CubicSpline<2>(params.h), params, P);
    return P.density_rate[0];
  };
  EXPECT_NEAR(rate_of_a(2), -2920.0937821339253, 1e-8);
  EXPECT_EQ(rate_of_a(1), 0.0);  // b is a wall: no diffusion with walls
  params.density_diffusion = 0.0;
  EXPECT_EQ(rate_of_a(2), 0.0);
}

}  // namespace
}  // namespace porosph::fluid
