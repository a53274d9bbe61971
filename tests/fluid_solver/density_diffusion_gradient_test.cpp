// The density diffusion's linear correction (density_diffusion_gradient.h): in a steady seepage
// state, whose departure potential psi = Phi - g . x is linear but not constant, the corrected
// term vanishes at every particle - the truncated top and bottom rows included - while the
// hydrostatic-only bracket drives a flux there (what slowed the water in a fluidised bed).
#include "fluid_solver/density_diffusion_gradient.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/water_rates.h"
#include "sph/geometry.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

/// D_a / (delta h c0) of every water particle, with the gradients G (zero: hydrostatic only).
std::vector<double> rates(const WaterParticles<2>& P, const sph::NeighbourList<2>& nl,
                          const sph::CubicSpline<2>& kernel, const DensityDiffusion<2>& dd,
                          double eta2, const std::vector<Vec2>& gradient) {
  std::vector<double> out(P.n_free, 0.0);
  for (std::size_t a = 0; a < P.n_free; ++a) {
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      const double factor = it->x_ab.dot(kernel.gradient(it->x_ab, it->r)) / (it->r * it->r + eta2);
      out[a] += dd.pair_term(P.diffusion_state[a], P.diffusion_state[it->b], P.volume[it->b],
                             it->x_ab, factor, gradient[a], gradient[it->b]);
    }
  }
  return out;
}

TEST(DensityDiffusionGradient, SteadySeepageStateHasNoFluxWithTheLinearCorrection) {
  // A water block 0.1 x 0.2 m (dp 0.01, h 0.012, c0 = 20), gravity (0, -9.81), in an upward
  // seepage flow of gradient i = 0.8: Phi = g (1 + i) (top - y), so psi = Phi - g . x = g (1 + i)
  // top - g i y, linear in y with slope -g i (a fluidised bed's drag carries that).
  const double dp = 0.01, h = 0.012, eta2 = 0.01 * h * h, c0 = 20.0, i = 0.8, top = 0.195;
  const TaitEos eos(1000.0, c0, 7.0);
  const auto x = sph::fill_shape<2>(testing::box({0, 0}, {0.1, 0.2}), dp);
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double phi = 9.81 * (1.0 + i) * (top - x[k][1]);  // Phi(rho) = c0^2 (s^6 - 1) / 6
    P.density[k] = 1000.0 * std::pow(1.0 + 6.0 * phi / (c0 * c0), 1.0 / 6.0);
    P.mass[k] = P.density[k] * dp * dp;
  }
  update_inverse_density_and_volume(P);
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), x.size(), x.size(), 2.0 * h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(h);
  const DensityDiffusion<2> dd(0.1, h, eos, Vec2(0.0, -9.81));
  fill_diffusion_states(dd, P);
  std::vector<Vec2> gradient;
  departure_gradients(nl, kernel, dd, P, gradient);
  // G = grad psi / c0^2 = (0, -g i / c0^2) at every particle, edges and corners included (the
  // renormalised gradient is exact for a linear field; round-off ~1e-12 of the 0.0196 1/m).
  for (std::size_t k = 0; k < x.size(); ++k) {
    EXPECT_NEAR(gradient[k][0], 0.0, 1e-10) << k;
    EXPECT_NEAR(gradient[k][1], -9.81 * i / (c0 * c0), 1e-10) << k;
  }
  const auto corrected = rates(P, nl, kernel, dd, eta2, gradient);
  const auto hydrostatic_only =
      rates(P, nl, kernel, dd, eta2, std::vector<Vec2>(x.size(), Vec2::Zero()));
  double max_corrected = 0.0, max_plain = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    max_corrected = std::max(max_corrected, std::abs(corrected[k]));
    max_plain = std::max(max_plain, std::abs(hydrostatic_only[k]));
  }
  // Without the linear correction the top and bottom rows see a one-sided gradient: measured
  // 1810 (per delta h c0, kg/m^3/m^2). With it: round-off of the brackets' sums, 1e-9 of that.
  EXPECT_GT(max_plain, 1000.0);
  EXPECT_LT(max_corrected, 1e-9 * max_plain);
}

TEST(DensityDiffusionGradient, IsolatedParticleFallsBackToTheHydrostaticBracket) {
  // Two particles side by side: the moment matrix has rank 1 (det 0), so G = 0, not a NaN.
  auto P = testing::make_particles<2>({Vec2(0, 0), Vec2(0.006, 0)}, 2, 1000.0, 0.1);
  P.density[0] = 1001.0;
  update_inverse_density_and_volume(P);
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), 2, 2, 0.024, sph::DomainBox<2>{});
  const DensityDiffusion<2> dd(0.1, 0.012, TaitEos(1000.0, 20.0, 7.0), Vec2(0.0, -9.81));
  fill_diffusion_states(dd, P);
  std::vector<Vec2> gradient;
  departure_gradients(nl, sph::CubicSpline<2>(0.012), dd, P, gradient);
  ASSERT_EQ(gradient.size(), 2u);
  EXPECT_EQ(gradient[0], Vec2::Zero());
  EXPECT_EQ(gradient[1], Vec2::Zero());
}

}  // namespace
}  // namespace porosph::water
