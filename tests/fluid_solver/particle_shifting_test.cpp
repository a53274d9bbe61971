// Particle shifting (fluid_solver/particle_shifting.h): the shift moves the particles and their
// mass, so the continuity equation sees it and the density follows each particle's neighbourhood.
#include "fluid_solver/particle_shifting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

/// sum_b m_b W_ab of particle a (b = a included): the summation density.
double summation_density(const WaterParticles<2>& P, const sph::CubicSpline<2>& kernel,
                         std::size_t a) {
  double rho = 0.0;
  for (std::size_t b = 0; b < P.size(); ++b)
    rho += P.mass[b] * kernel.w((P.position[a] - P.position[b]).norm());
  return rho;
}

TEST(ParticleShifting, TheDensityFollowsTheShiftAsTheSummationDensityDoes) {
  // A lattice (dp 5 mm, 24 x 24) disordered by up to 0.2 dp, uniform density rho0 and mass
  // rho0 dp^2. Then V_b = m_b / rho0 and the shift's continuity share rho_a sum_b V_b u_ab .
  // grad W_ab is sum_b m_b u_ab . grad W_ab: the time derivative of the summation density under
  // the motion u. Checked against a finite difference of sum_b m_b W_ab over a shift of dt, at the
  // particles whose support lies inside the cloud. Without the share the rate would be 0 and the
  // density would not see the shift at all (the mean drift of docs/verification.md).
  const double dp = 0.005, h = 1.2 * dp, rho0 = 1000.0, dt = 1e-5, coefficient = 2.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2 * dp, 0.2 * dp);
  std::vector<Vec2> x;
  for (int j = 0; j < 24; ++j)
    for (int i = 0; i < 24; ++i) x.emplace_back(i * dp + jitter(rng), j * dp + jitter(rng));
  auto P = testing::make_particles<2>(x, x.size(), rho0, rho0 * dp * dp);
  P.volume.assign(P.size(), dp * dp);
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.size(), 2.0 * h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(h);
  ParticleShiftingGradients<2> shifting;
  shifting.compute(list, kernel, dp, /*max_speed=*/1.0, P);
  shifting.add_to_continuity(list, kernel, coefficient, h, P);

  // A central difference over shifts of +dt and -dt.
  auto forward = P, backward = P;
  for (std::size_t a = 0; a < P.size(); ++a) {
    shifting.shift(coefficient, h, dt, a, forward);
    shifting.shift(coefficient, h, -dt, a, backward);
  }
  double largest = 0.0, worst = 0.0;
  for (std::size_t a = 0; a < P.size(); ++a) {
    const Vec2& p = P.position[a];
    const double margin = 2.0 * h + 0.2 * dp;
    if (p.x() < margin || p.y() < margin || p.x() > 23 * dp - margin || p.y() > 23 * dp - margin)
      continue;
    const double finite_difference =
        (summation_density(forward, kernel, a) - summation_density(backward, kernel, a)) /
        (2.0 * dt);
    largest = std::max(largest, std::abs(P.density_rate[a]));
    worst = std::max(worst, std::abs(P.density_rate[a] - finite_difference));
  }
  // The shift over dt is ~1e-3 dp: the central difference's own error is ~1e-6 relative.
  EXPECT_GT(largest, 100.0);  // kg/m^3/s: the disorder gives a real rate
  EXPECT_LT(worst, 1e-4 * largest) << "largest rate " << largest;
}

TEST(ParticleShifting, ZoneParticlesAreNotShiftedAndAUniformShiftChangesNoDensity) {
  const double dp = 0.005, h = 1.2 * dp;
  std::vector<Vec2> x;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) x.emplace_back(i * dp + 0.1 * dp * ((i * 7 + j * 3) % 5), j * dp);
  auto P = testing::make_particles<2>(x, x.size(), 1000.0, 1000.0 * dp * dp);
  P.volume.assign(P.size(), dp * dp);
  P.zone[5] = 0;  // an inflow zone's particle moves as prescribed
  sph::NeighbourList<2> list;
  list.build(P.position.data(), P.size(), P.size(), 2.0 * h, sph::DomainBox<2>{});
  const sph::CubicSpline<2> kernel(h);
  ParticleShiftingGradients<2> shifting;
  shifting.compute(list, kernel, dp, 1.0, P);
  EXPECT_EQ(shifting.velocity(2.0, h, 5, P), Vec2::Zero());
  EXPECT_GT(shifting.velocity(2.0, h, 6, P).norm(), 0.0);
  // The same gradient everywhere is a rigid translation: no relative motion, no density change.
  for (auto& g : shifting.concentration) g = Vec2(0.3, -0.1);
  P.zone[5] = -1;
  shifting.add_to_continuity(list, kernel, 2.0, h, P);
  for (std::size_t a = 0; a < P.size(); ++a) EXPECT_NEAR(P.density_rate[a], 0.0, 1e-9) << a;
}

}  // namespace
}  // namespace porosph::water
