// The per-particle gradient renormalisation (fluid_solver/particle_gradient.h,
// run.kernel_gradient = "particle"): the blend s(t), s = 1 on the initial square lattice, and on a
// hexagonal packing of the same particle area the renormalised gradient of a linear field exact
// where the plain lattice factor leaves it ~3 % too strong.
#include "fluid_solver/particle_gradient.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sph/kernels.h"
#include "sph/lattice_gradient.h"
#include "sph/neighbour_list.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

TEST(ParticleGradient, BlendFromTheFreeSurfaceToTheInterior) {
  EXPECT_EQ(ParticleGradient::scale(0.5), 1.0);  // a free surface: left alone
  EXPECT_EQ(ParticleGradient::scale(0.9), 1.0);
  EXPECT_NEAR(ParticleGradient::scale(0.935), 1.0 + 0.5 * (1.0 / 0.935 - 1.0), 1e-12);
  EXPECT_NEAR(ParticleGradient::scale(0.97), 1.0 / 0.97, 1e-12);
  EXPECT_NEAR(ParticleGradient::scale(1.03), 1.0 / 1.03, 1e-12);
  EXPECT_EQ(ParticleGradient::scale(1.2), 1.0);  // a clump: left to the lattice factor
  EXPECT_EQ(ParticleGradient::scale(std::numeric_limits<double>::quiet_NaN()), 1.0);
}

/// Particles on a lattice over [0, 0.3]^2 with area dp^2 each: square, or hexagonal (rows
/// sqrt(3)/2 a apart, every other row shifted by a/2, a^2 sqrt(3)/2 = dp^2).
std::vector<Vec2> lattice(double dp, bool hexagonal) {
  std::vector<Vec2> x;
  const double a = hexagonal ? dp * std::sqrt(2.0 / std::sqrt(3.0)) : dp;
  const double row = hexagonal ? a * std::sqrt(3.0) / 2.0 : dp;
  int j = 0;
  for (double y = 0.5 * row; y < 0.3; y += row, ++j) {
    const double shift = hexagonal && j % 2 ? 0.5 * a : 0.0;
    for (double xx = 0.5 * a + shift; xx < 0.3; xx += a) x.emplace_back(xx, y);
  }
  return x;
}

/// s of every particle and the gradient of f = 3 x + 2 y at the particle nearest the centre:
/// sum_b V_b (f_b - f_a) grad_a W_ab, with and without s_a.
struct Measured {
  double centre_scale = 0.0;
  Vec2 plain = Vec2::Zero(), renormalised = Vec2::Zero();
  double interior_min = 1e9, interior_max = -1e9;
};

Measured measure(bool hexagonal) {
  const double dp = 0.01, h = 1.2 * dp;
  const auto kernel = sph::make_kernel<sph::CubicSpline<2>>(h, dp, true);
  const std::vector<Vec2> x = lattice(dp, hexagonal);
  sph::NeighbourList<2> list;
  list.build(x.data(), x.size(), x.size(), 2.0 * h, sph::DomainBox<2>{});
  const std::vector<double> volume(x.size(), dp * dp);
  std::vector<double> s;
  ParticleGradient::compute(list, kernel, x.size(), volume, s);
  Measured m;
  std::size_t centre = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    if ((x[a] - Vec2(0.15, 0.15)).norm() < (x[centre] - Vec2(0.15, 0.15)).norm()) centre = a;
    const bool interior = (x[a].array() > 0.05).all() && (x[a].array() < 0.25).all();
    if (interior) {
      m.interior_min = std::min(m.interior_min, s[a]);
      m.interior_max = std::max(m.interior_max, s[a]);
    }
  }
  const auto f = [](const Vec2& p) { return 3.0 * p[0] + 2.0 * p[1]; };
  for (auto it = list.begin(centre); it != list.end(centre); ++it) {
    const Vec2 grad = kernel.grad_factor(it->r) * it->x_ab;
    m.plain += volume[it->b] * (f(x[it->b]) - f(x[centre])) * grad;
  }
  m.centre_scale = s[centre];
  m.renormalised = s[centre] * m.plain;
  return m;
}

TEST(ParticleGradient, SquareLatticeIsLeftAsTheLatticeFactorMadeIt) {
  const Measured m = measure(false);
  EXPECT_NEAR(m.interior_min, 1.0, 1e-12);
  EXPECT_NEAR(m.interior_max, 1.0, 1e-12);
  EXPECT_NEAR(m.plain[0], 3.0, 1e-10);
  EXPECT_NEAR(m.plain[1], 2.0, 1e-10);
}

TEST(ParticleGradient, HexagonalPackingGetsExactLinearGradients) {
  // The hexagonal packing's second-moment tensor is isotropic, so the trace renormalisation makes
  // linear gradients exact; the square lattice's factor alone leaves them too strong by
  // tr(L) / 2 - 1 = 3.6 % (a perfect hexagonal packing; 2.8-3.5 % in the seepage weir's collapsed
  // lattice).
  const Measured m = measure(true);
  EXPECT_GT(m.plain[0] / 3.0 - 1.0, 0.01);  // the defect is there
  EXPECT_NEAR(m.renormalised[0], 3.0, 1e-9);
  EXPECT_NEAR(m.renormalised[1], 2.0, 1e-9);
  EXPECT_LT(m.centre_scale, 0.99);
}

}  // namespace
}  // namespace porosph::water
