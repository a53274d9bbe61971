// Per-pair soil terms: Gray-Monaghan artificial stress, Monaghan artificial viscosity (dissipative
// sign), stress divergence of eq. 5 / 16.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "soil_solver/artificial_stress.h"
#include "soil_solver/soil_artificial_viscosity.h"
#include "soil_solver/straight_walls.h"
#include "soil_solver/stress_divergence.h"
#include "sph/domain_box.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using V2 = sph::Vec<2>;
using V3 = sph::Vec<3>;

constexpr double kRoundOff = 1e-12;  // relative, eigen-decomposition of a 2x2 / 3x3 tensor

// R diag(a, b, c) R^T with R an in-plane rotation by theta.
Matrix3d rotated_principal(double a, double b, double c, double theta) {
  Matrix3d r = Matrix3d::Identity();
  r(0, 0) = r(1, 1) = std::cos(theta);
  r(1, 0) = std::sin(theta);
  r(0, 1) = -std::sin(theta);
  return r * Eigen::Vector3d(a, b, c).asDiagonal() * r.transpose();
}

TEST(ArtificialStress, ZeroInCompression) {
  const Matrix3d sigma = rotated_principal(-100e3, -30e3, -60e3, 0.4);
  EXPECT_EQ(artificial_stress<2>(sigma, 1800.0, 0.5), Matrix3d::Zero());
  EXPECT_EQ(artificial_stress<3>(sigma, 1800.0, 0.5), Matrix3d::Zero());
}

TEST(ArtificialStress, CompressionTestAgreesWithTheEigenvalues) {
  // The shortcut (no eigen decomposition when every principal minor of -sigma is >= 0) must
  // say "no tension" exactly when the largest eigenvalue is <= 0. Random stresses built from
  // chosen eigenvalues (one of them in [-1, 0.1] x 100 kPa, so about one in eleven is tensile)
  // and a random 3D rotation; cases within 1e-9 of the boundary are skipped (rounding decides).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> compressive(-100e3, -1e3), last(-100e3, 10e3);
  std::normal_distribution<double> normal;
  int tensile_seen = 0;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    const Eigen::Vector3d lambda(compressive(rng), compressive(rng), last(rng));
    const Matrix3d sigma =
        q.toRotationMatrix() * lambda.asDiagonal() * q.toRotationMatrix().transpose();
    const Eigen::Matrix2d block = sigma.topLeftCorner<2, 2>();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen_2d;
    eigen_2d.computeDirect(block);
    const double max_2d = eigen_2d.eigenvalues()[1];
    const double max_3d = lambda.maxCoeff();
    if (std::abs(max_2d) > 1e-9 * 100e3) {
      EXPECT_EQ(no_principal_tension<2>(sigma), max_2d <= 0.0);
    }
    if (std::abs(max_3d) > 1e-9 * 100e3) {
      EXPECT_EQ(no_principal_tension<3>(sigma), max_3d <= 0.0);
    }
    tensile_seen += max_3d > 0.0;
  }
  EXPECT_GT(tensile_seen, 50);  // both branches exercised
}

TEST(ArtificialStress, TensilePrincipalStressOnly) {
  // Principal stresses 20 kPa (tension, along e = (cos t, sin t)) and -50 kPa; rho 2000, eps 0.5:
  //   R = -0.5 * 2e4 / 2000^2 e (x) e = -2.5e-3 e (x) e   [Pa m^6/kg^2]
  const double t = 0.7, rho = 2000.0;
  const Matrix3d sigma = rotated_principal(20e3, -50e3, -10e3, t);
  Matrix3d expected = Matrix3d::Zero();
  const Eigen::Vector3d e(std::cos(t), std::sin(t), 0.0);
  expected = -2.5e-3 * e * e.transpose();
  EXPECT_LE((artificial_stress<2>(sigma, rho, 0.5) - expected).norm(), kRoundOff * 2.5e-3);
  EXPECT_LE((artificial_stress<3>(sigma, rho, 0.5) - expected).norm(), kRoundOff * 2.5e-3);
  // Out-of-plane tension: only 3D sees it (2D uses the in-plane block, zz is not in the
  // 2D momentum balance).
  const Matrix3d zz_tension = rotated_principal(-1e3, -2e3, 40e3, 0.3);
  EXPECT_EQ(artificial_stress<2>(zz_tension, rho, 0.5), Matrix3d::Zero());
  EXPECT_NEAR(artificial_stress<3>(zz_tension, rho, 0.5)(2, 2), -0.5 * 40e3 / (rho * rho),
              kRoundOff * 5e-3);
}

TEST(ArtificialStress, PairFactor) {
  EXPECT_DOUBLE_EQ(artificial_stress_factor(3.0, 3.0, 2.55), 1.0);  // r = dp
  // 0.5^2.55 = exp(-2.55 ln 2) = exp(-1.767543) = 0.1707550
  EXPECT_NEAR(artificial_stress_factor(1.0, 2.0, 2.55), std::exp(-2.55 * std::log(2.0)), 1e-15);
  EXPECT_NEAR(artificial_stress_factor(1.0, 2.0, 2.55), 0.1707550, 1e-7);
}

TEST(ArtificialStress, RepulsiveInTension) {
  // Two particles in uniaxial tension along x, a spacing dp apart along x.
  const double dp = 1e-3, h = 1.2e-3, rho = 2000.0, m = rho * dp * dp;
  const sph::CubicSpline<2> kernel(h);
  const V2 x_ij(dp, 0.0);  // x_i - x_j: i to the right of j
  const V2 grad = kernel.gradient(x_ij, dp);
  const Matrix3d sigma = rotated_principal(10e3, -5e3, -1e3, 0.0);
  const Matrix3d r = artificial_stress<2>(sigma, rho, 0.5);
  const double f = artificial_stress_factor(kernel.w(dp), kernel.w(dp), 2.55);
  const V2 a_i = artificial_stress_acceleration<2>(m, r, r, f, grad);
  EXPECT_GT(a_i.dot(x_ij), 0.0);  // pushes i away from j
  // Hand value: a_x = m * 2 * (-0.5 * 1e4 / rho^2) * 1 * dW/dr(dp) (dW/dr < 0), a_y = 0.
  EXPECT_NEAR(a_i.x(), m * 2.0 * (-0.5 * 1e4 / (rho * rho)) * kernel.dw_dr(dp),
              kRoundOff * std::abs(a_i.x()));
  EXPECT_NEAR(a_i.y(), 0.0, kRoundOff * std::abs(a_i.x()));
  // Same pair under compression: no artificial stress at all.
  const Matrix3d rc = artificial_stress<2>(Matrix3d(-sigma), rho, 0.5);
  EXPECT_EQ(artificial_stress_acceleration<2>(m, rc, rc, f, grad), V2::Zero());
}

TEST(SoilArtificialViscosity, DissipatesApproachingPairsOnly) {
  const double h = 1.2e-3, dp = 1e-3, rho = 1800.0, c = 60.0, m = rho * dp * dp;
  const sph::CubicSpline<2> kernel(h);
  const SoilArtificialViscosity av{0.1, 0.1, h};
  const V2 x_ij(dp, 0.0);
  const V2 grad = kernel.gradient(x_ij, dp);
  const V2 approaching(-0.2, 0.05);  // v_i - v_j with v_ij . x_ij < 0
  const V2 a_i = av.acceleration<2>(m, approaching, x_ij, x_ij.norm(), c, c, rho, rho, grad);
  // mu = h v.x / (r^2 + 0.01 h^2) = 1.2e-3 * (-2e-4) / (1e-6 + 1.44e-8) = -2.3659e-4... m/s ->
  // Pi = (0.1 * 60 * 2.3659e-1 + 0.1 * mu^2) / 1800, with mu = -0.236593 m/s.
  const double mu = h * (-0.2 * dp) / (dp * dp + 0.01 * h * h);
  const double pi = (-0.1 * c * mu + 0.1 * mu * mu) / rho;
  EXPECT_NEAR(av.pi(approaching.dot(x_ij), dp, c, rho), pi, kRoundOff * pi);
  EXPECT_NEAR(mu, -0.2365930599, 1e-10);
  EXPECT_LT(a_i.dot(approaching), 0.0);  // decelerates the relative motion
  EXPECT_GT(a_i.dot(x_ij), 0.0);         // a repulsion
  // Receding: exactly zero.
  EXPECT_EQ(av.acceleration<2>(m, V2(-approaching), x_ij, x_ij.norm(), c, c, rho, rho, grad),
            V2::Zero());
  // Sound speed: sqrt(K / (rho_sat - rho_w)) of docs/cases.md, K = 4.1667 MPa, 1810 - 1000 = 810.
  EXPECT_NEAR(soil_sound_speed(5e6 / 1.2, 810.0), std::sqrt(5e6 / 1.2 / 810.0), 1e-12);
  EXPECT_NEAR(soil_sound_speed(5e6 / 1.2, 810.0), 71.7219, 1e-4);
}

TEST(StressDivergence, PressureLikeRepulsionAndAntisymmetry) {
  const double h = 1.2e-3, dp = 1e-3;
  const sph::CubicSpline<3> kernel(h);
  const V3 x_ij(dp, 0.3 * dp, -0.2 * dp);
  const double r = x_ij.norm();
  const V3 grad_i = kernel.gradient(x_ij, r), grad_j = kernel.gradient(V3(-x_ij), r);
  const double m_i = 2e-6, m_j = 3e-6, rho_i = 1900.0, rho_j = 2000.0;
  const Matrix3d s_i = -50e3 * Matrix3d::Identity(), s_j = -70e3 * Matrix3d::Identity();
  const V3 a_i = stress_divergence_acceleration<3>(m_j, s_i, s_j, rho_i, rho_j, grad_i);
  const V3 a_j = stress_divergence_acceleration<3>(m_i, s_j, s_i, rho_j, rho_i, grad_j);
  // Isotropic compression acts like a pressure: -m_j (p_i + p_j) / (rho_i rho_j) grad_i W.
  EXPECT_TRUE(a_i.isApprox(-m_j * 120e3 / (rho_i * rho_j) * grad_i, kRoundOff));
  EXPECT_GT(a_i.dot(x_ij), 0.0);
  // Momentum conservation pair by pair.
  EXPECT_LE((m_i * a_i + m_j * a_j).norm(), kRoundOff * m_i * a_i.norm());
  // 2D uses only the in-plane block: an out-of-plane stress has no 2D effect.
  Matrix3d zz = Matrix3d::Zero();
  zz(2, 2) = -1e5;
  EXPECT_EQ(stress_divergence_acceleration<2>(1.0, zz, zz, 1.0, 1.0, V2(1.0, 2.0)), V2::Zero());
}

// A straight wall (two rows of fixed particles below y = 0, spacing dp) and one soil particle in
// the first soil row, slid along the wall by o. Sums the wall pairs of both forms.
struct WallSums {
  V2 symmetric = V2::Zero(), wall_form = V2::Zero();
};
WallSums wall_pair_sums(double o, const Matrix3d& sigma_i, const Matrix3d& sigma_w) {
  const double dp = 0.01;
  const sph::CubicSpline<2> kernel(1.2 * dp);
  const double rho = 1800.0, m = rho * dp * dp;
  const V2 x_i(o, 0.5 * dp), normal(0.0, 1.0);
  WallSums sums;
  for (int row = 0; row < 2; ++row) {
    for (int k = -4; k <= 4; ++k) {
      const V2 x_w(k * dp, -(row + 0.5) * dp);
      const V2 x_iw = x_i - x_w;
      const double r = x_iw.norm();
      if (r >= kernel.support()) continue;
      const V2 grad = kernel.grad_factor(r) * x_iw;
      sums.symmetric += stress_divergence_acceleration<2>(m, sigma_i, sigma_w, rho, rho, grad);
      sums.wall_form +=
          wall_stress_divergence_acceleration<2>(m, sigma_i, sigma_w, rho, rho, grad, normal);
    }
  }
  return sums;
}

TEST(WallStressDivergence, NoForceAlongTheWallFromAUniformStressWhateverTheRegistry) {
  // Uniform compression of 10 kPa on both sides. Slid by 0.1 dp, the symmetric form's lattice
  // ripple pushes along the wall (the measured defect); the wall form gives exactly zero there and
  // keeps the wall's normal support unchanged.
  const Matrix3d sigma = -1e4 * Matrix3d::Identity();
  const WallSums slid = wall_pair_sums(0.001, sigma, sigma);
  EXPECT_GT(std::abs(slid.symmetric.x()), 1e-4 * std::abs(slid.symmetric.y()));
  EXPECT_EQ(slid.wall_form.x(), 0.0);
  EXPECT_NEAR(slid.wall_form.y(), slid.symmetric.y(), 1e-12 * std::abs(slid.symmetric.y()));
  EXPECT_GT(slid.wall_form.y(), 0.0);  // the wall holds the compressed soil off
}

TEST(WallStressDivergence, SameAsTheSymmetricFormInRegistry) {
  // In registry the tangential zeroth-order sum vanishes, so the two forms agree for any stress
  // (here a shear and unequal normal stresses, different on the wall).
  Matrix3d sigma_i, sigma_w;
  sigma_i << -2e4, 300.0, 0.0, 300.0, -1e4, 0.0, 0.0, 0.0, -1e4;
  sigma_w << -2.1e4, -250.0, 0.0, -250.0, -1.2e4, 0.0, 0.0, 0.0, -1e4;
  const WallSums aligned = wall_pair_sums(0.0, sigma_i, sigma_w);
  EXPECT_LE((aligned.wall_form - aligned.symmetric).norm(), 1e-9 * aligned.symmetric.norm());
}

// The neighbour list's fixed range, as sees_one_straight_wall reads it.
struct FixedNeighbours {
  std::vector<sph::NeighbourPair<2>> pairs;
  auto mid(std::int64_t) const { return pairs.begin(); }
  auto end(std::int64_t) const { return pairs.end(); }
};

TEST(WallStressDivergence, StraightWallOnlyWhenEveryWallNeighbourSharesTheNormal) {
  const double nan = std::nan("");
  std::vector<V2> normals = {V2(0.0, 2.0), V2(0.0, -1.0), V2(1.0, 0.0),
                             V2::Zero(),   V2(nan, nan),  V2(0.0, 1.0)};
  const std::vector<std::uint8_t> interior = {1, 1, 1, 1, 1, 0};  // 5: near the wall's end
  auto straight = [&](std::vector<std::int32_t> walls, V2& n) {
    FixedNeighbours nl;
    for (std::int32_t b : walls) nl.pairs.push_back({V2::Zero(), 1.0, b});
    return sees_one_straight_wall<2>(nl, 0, normals, interior, n);
  };
  V2 n = V2::Zero();
  EXPECT_TRUE(straight({0, 1}, n));  // one wall's two faces: parallel
  EXPECT_DOUBLE_EQ(n.norm(), 1.0);
  EXPECT_DOUBLE_EQ(std::abs(n.y()), 1.0);
  EXPECT_FALSE(straight({0, 2}, n));  // two walls at a right angle
  EXPECT_FALSE(straight({0, 3}, n));  // a corner particle
  EXPECT_FALSE(straight({0, 4}, n));  // no geometric normal
  EXPECT_FALSE(straight({}, n));      // no wall at all
  EXPECT_FALSE(straight({0, 5}, n));  // the same normal, but one of them near the wall's end
}

TEST(StraightWalls, InteriorOnlyWhereTheWallRunsOnPastTheKernelBothWays) {
  // A floor of 12 sites (normal +y) and, standing on it, a one-layer pile of 8 sites (normal +x,
  // its side) whose lower end is 2 sites above the floor; reach 3 steps (h = 1.2 dp).
  const double dp = 0.01;
  std::vector<V2> x, normal;
  std::vector<double> remove_at;
  auto add = [&](V2 p, V2 n, double removal) {
    x.push_back(p), normal.push_back(n), remove_at.push_back(removal);
  };
  add(V2(0.5 * dp, 0.5 * dp), V2::Zero(), -1.0);  // one free particle first
  for (int k = 0; k < 12; ++k) add(V2((k + 0.5) * dp, -0.5 * dp), V2(0.0, 1.0), -1.0);
  for (int k = 0; k < 8; ++k) add(V2(5.5 * dp, (k + 2.5) * dp), V2(1.0, 0.0), -1.0);
  const sph::DomainBox<2> box;
  std::vector<std::uint8_t> in = straight_wall_interior<2>(x, normal, remove_at, 1, dp, 3, box);
  EXPECT_EQ(in[0], 0);  // free
  for (int k = 0; k < 12; ++k) EXPECT_EQ(in[1 + k], k >= 3 && k <= 8 ? 1 : 0) << "floor " << k;
  for (int k = 0; k < 8; ++k) EXPECT_EQ(in[13 + k], k >= 3 && k <= 4 ? 1 : 0) << "pile " << k;
  // The same floor periodic along x: no end, every site interior.
  sph::DomainBox<2> periodic;
  periodic.min = V2(0.0, -1.0), periodic.max = V2(12 * dp, 1.0), periodic.periodic = {true, false};
  in = straight_wall_interior<2>(x, normal, remove_at, 1, dp, 3, periodic);
  for (int k = 0; k < 12; ++k) EXPECT_EQ(in[1 + k], 1) << "periodic floor " << k;
  // A gate (removed at 1 s) is not a continuation of the wall beside it.
  for (int k = 6; k < 12; ++k) remove_at[1 + k] = 1.0;
  in = straight_wall_interior<2>(x, normal, remove_at, 1, dp, 3, box);
  EXPECT_EQ(in[1 + 3], 0);  // 3 steps from the gate
  EXPECT_EQ(in[1 + 2], 0);  // 2 steps from the floor's end and 3 from the gate
}

}  // namespace
}  // namespace porosph::soil
