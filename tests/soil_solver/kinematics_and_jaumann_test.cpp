// Velocity gradient (eq. 7-8), Jaumann stress rate (eq. 6 / 12a first terms): per-pair
// accumulation, a linear-velocity patch, the rotation sign, invariants under rigid rotation.
#include <gtest/gtest.h>

#include <cmath>

#include "soil_solver/jaumann_rate.h"
#include "soil_solver/stress_invariants.h"
#include "soil_solver/velocity_gradient.h"
#include "sph/kernels.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using V2 = sph::Vec<2>;

constexpr double kRoundOff = 1e-12;  // relative; sums of a few hundred terms of O(1)

Matrix3d sample_stress() {
  Matrix3d s;
  s << -120e3, 15e3, 0.0,  //
      15e3, -80e3, 0.0,    //
      0.0, 0.0, -60e3;     // plane strain: sigma_zz is a real component
  return s;
}

TEST(VelocityGradient, OnePairContributionIsVolumeTimesOuterProduct) {
  MatD<2> l = MatD<2>::Zero();
  const V2 v_ji(0.3, -0.2), grad(-50.0, 20.0);
  accumulate_velocity_gradient<2>(l, 2e-6, v_ji, grad);
  // L^{ab} = V_j v_ji^a gradW^b, written out by hand:
  EXPECT_DOUBLE_EQ(l(0, 0), 2e-6 * 0.3 * -50.0);
  EXPECT_DOUBLE_EQ(l(0, 1), 2e-6 * 0.3 * 20.0);
  EXPECT_DOUBLE_EQ(l(1, 0), 2e-6 * -0.2 * -50.0);
  EXPECT_DOUBLE_EQ(l(1, 1), 2e-6 * -0.2 * 20.0);
  // Strain rate and spin are its symmetric and antisymmetric parts (eq. 7, 8), embedded in 3x3.
  const Matrix3d l3 = embed_in_3d<2>(l);
  EXPECT_DOUBLE_EQ(strain_rate(l3)(0, 1), 0.5 * (l(0, 1) + l(1, 0)));
  EXPECT_DOUBLE_EQ(spin(l3)(0, 1), 0.5 * (l(0, 1) - l(1, 0)));
  EXPECT_EQ(l3.row(2).norm() + l3.col(2).norm(), 0.0);
  EXPECT_TRUE((strain_rate(l3) + spin(l3)).isApprox(l3, kRoundOff));
}

// A lattice patch with a linear velocity field v = A x: the SPH sum gives L = A M with the
// lattice moment M = sum_j V_j x_ji (x) grad_i W_ij, exactly (linearity); M is close to I for
// the cubic spline at h = 1.2 dx. The uniform strain rate then gives the Hooke stress increment.
struct Patch {
  static constexpr double dx = 1e-3, h = 1.2e-3;
  MatD<2> velocity_gradient = MatD<2>::Zero();
  MatD<2> moment = MatD<2>::Zero();
  explicit Patch(const MatD<2>& a) {
    const sph::CubicSpline<2> kernel(h);
    const double volume = dx * dx;
    for (int ix = -4; ix <= 4; ++ix) {
      for (int iy = -4; iy <= 4; ++iy) {
        if (ix == 0 && iy == 0) continue;
        const V2 x_ji(ix * dx, iy * dx);  // x_j - x_i, particle i at the origin
        const double r = x_ji.norm();
        if (r >= kernel.support()) continue;
        const V2 grad_i = kernel.gradient(V2(-x_ji), r);  // grad_i W_ij, x_ij = -x_ji
        accumulate_velocity_gradient<2>(velocity_gradient, volume, V2(a * x_ji), grad_i);
        moment += volume * x_ji * grad_i.transpose();
      }
    }
  }
};

TEST(VelocityGradient, LinearFieldOnALatticePatch) {
  MatD<2> a;
  a << 0.02, 0.05, -0.01, -0.03;  // strain rate + spin, arbitrary [1/s]
  const Patch patch(a);
  EXPECT_TRUE(patch.velocity_gradient.isApprox(a * patch.moment, kRoundOff));
  // Lattice symmetry: M is isotropic; M_xx = 0.99079 for the cubic spline at h = 1.2 dx (the
  // discrete lattice sum of the kernel's first moment, measured), so 1.5e-2 bounds |M - I| with
  // margin while still catching a wrong sign (M = -I) or a missing volume factor (M ~ 1e-6 I).
  EXPECT_NEAR(patch.moment(0, 1), 0.0, kRoundOff);
  EXPECT_NEAR(patch.moment(0, 0), patch.moment(1, 1), kRoundOff);
  EXPECT_NEAR(patch.moment(0, 0), 1.0, 1.5e-2);
}

TEST(JaumannRate, UniformStrainRateOnPatchGivesHookeStress) {
  const double k = 4.0e6, g = 1.5e6, dt = 1e-4;
  MatD<2> a;
  a << 0.02, 0.05, -0.01, -0.03;
  const Patch patch(a);
  const Matrix3d l = embed_in_3d<2>(patch.velocity_gradient);
  // Isotropic initial stress: the co-rotation term vanishes, only Hooke remains.
  const Matrix3d sigma0 = -50e3 * Matrix3d::Identity();
  const Matrix3d sigma1 = sigma0 + dt * elastic_stress_rate(k, g, sigma0, strain_rate(l), spin(l));
  // Expected: 2 G e_dev + K e_vol delta with the exact A (plane strain, eps_zz = 0):
  //   e = [[0.02, 0.02], [0.02, -0.03]], tr = -0.01,
  //   xx: 2G(0.02 + 0.01/3) + K(-0.01), yy: 2G(-0.03 + 0.01/3) - 0.01 K, zz: 2G(0.01/3) - 0.01 K,
  //   xy: 2G 0.02.
  Matrix3d expected_rate;
  expected_rate << 2 * g * (0.02 + 0.01 / 3) - 0.01 * k, 2 * g * 0.02, 0.0,  //
      2 * g * 0.02, 2 * g * (-0.03 + 0.01 / 3) - 0.01 * k, 0.0,              //
      0.0, 0.0, 2 * g * (0.01 / 3) - 0.01 * k;
  const Matrix3d increment = sigma1 - sigma0;
  // The SPH increment differs from the exact one only through M - I (9.2e-3, bound 1.5e-2, see
  // above) and round-off relative to |sigma0| (~1e-16 * 5e4 per entry).
  EXPECT_LE((increment - dt * expected_rate).norm(), 1.5e-2 * (dt * expected_rate).norm());
  // With the moment correction the chain is exact: Hooke(sym(A M)).
  const Matrix3d exact_chain = embed_in_3d<2>(MatD<2>(a * patch.moment));
  EXPECT_LE((increment - dt * hooke_stress_rate(k, g, strain_rate(exact_chain))).norm(),
            1e-9 * (dt * expected_rate).norm());
  EXPECT_DOUBLE_EQ(increment(0, 2), 0.0);
}

TEST(JaumannRate, HookeRateSplitsDeviatoricAndVolumetric) {
  const double k = 3.0, g = 2.0;
  // Pure volumetric strain rate eps = e I: sigma_dot = 3 K e I (no 2G part: deviatoric form).
  EXPECT_TRUE(hooke_stress_rate(k, g, 0.1 * Matrix3d::Identity())
                  .isApprox(3.0 * k * 0.1 * Matrix3d::Identity(), kRoundOff));
  // Pure shear eps_xy = e: sigma_xy = 2 G e.
  Matrix3d shear = Matrix3d::Zero();
  shear(0, 1) = shear(1, 0) = 0.1;
  EXPECT_TRUE(hooke_stress_rate(k, g, shear).isApprox(2.0 * g * shear, kRoundOff));
}

// Rigid rotation, counter-clockwise about z at rate w: v = (-w y, w x), L = [[0,-w],[w,0]].
Matrix3d rigid_spin(double w) {
  MatD<2> l;
  l << 0.0, -w, w, 0.0;
  return spin(embed_in_3d<2>(l));
}

TEST(JaumannRate, RotationSignFollowsTheMaterial) {
  // A uniaxial stress along x rotated by a small angle theta (counter-clockwise) becomes
  // R diag(1,0,0) R^T: sigma_xy = sin(theta) cos(theta) = theta + O(theta^3) > 0,
  // sigma_yy = sin^2(theta) = O(theta^2). One Euler step reproduces the O(theta) part exactly.
  const double w = 2.0, dt = 1e-3, theta = w * dt;
  Matrix3d s = Matrix3d::Zero();
  s(0, 0) = 1.0;
  const Matrix3d rotated = s + dt * corotational_stress_rate(s, rigid_spin(w));
  EXPECT_NEAR(rotated(0, 1), theta, kRoundOff);
  EXPECT_NEAR(rotated(1, 0), theta, kRoundOff);
  EXPECT_NEAR(rotated(0, 0), 1.0, kRoundOff);
  EXPECT_NEAR(rotated(1, 1), 0.0, kRoundOff);
  // Index form of eq. 12a equals omega sigma - sigma omega for antisymmetric omega.
  const Matrix3d om = rigid_spin(w), sg = sample_stress();
  EXPECT_TRUE(corotational_stress_rate(sg, om).isApprox(om * sg - sg * om, kRoundOff));
}

TEST(JaumannRate, RigidRotationKeepsInvariantsToSecondOrder) {
  // Spin only, zero strain rate. One Euler step s1 = s0 + dt [W, s0] (commutator):
  //   tr[W, s0] = 0                       -> I1 conserved to round-off;
  //   s0 : [W, s0] = tr(s0 W s0 - s0 s0 W) = 0 -> J2_1 - J2_0 = dt^2 |[W, s0]|^2 / 2 exactly,
  // an O(dt^2) error. Halving dt divides it by 4.
  const double w = 3.0;
  const Matrix3d spin_tensor = rigid_spin(w);
  const Matrix3d s0 = sample_stress();
  const Matrix3d zero = Matrix3d::Zero();
  const double j2_0 = second_deviatoric_invariant(s0);
  const Matrix3d commutator = corotational_stress_rate(s0, spin_tensor);
  double previous_error = 0.0;
  for (double dt : {1e-3, 5e-4}) {
    const Matrix3d s1 = s0 + dt * elastic_stress_rate(4e6, 1.5e6, s0, zero, spin_tensor);
    EXPECT_NEAR(first_invariant(s1), first_invariant(s0), kRoundOff * s0.norm());
    const double error = second_deviatoric_invariant(s1) - j2_0;
    EXPECT_NEAR(error, 0.5 * dt * dt * commutator.squaredNorm(), 1e-6 * error);
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 1e-6);
    }
    previous_error = error;
  }
  // A quarter turn in N steps: |[W, s]| <= 2 w |s| (rotation about one axis), so the relative
  // J2 drift is at most (1 + 4 w^2 dt^2)^N - 1 (~ 4 w^2 dt^2 N, first order in dt overall); and
  // the stress ends close to the exactly rotated one, R s0 R^T with R the quarter turn
  // (xx <-> yy swap, xy -> -xy), within the same first-order bound.
  const int n = 1000;
  const double dt = 0.5 * M_PI / w / n;
  Matrix3d s = s0;
  for (int i = 0; i < n; ++i) s += dt * corotational_stress_rate(s, spin_tensor);
  const double bound = std::pow(1.0 + 4.0 * w * w * dt * dt, n) - 1.0;
  EXPECT_NEAR(first_invariant(s), first_invariant(s0), kRoundOff * s0.norm());
  EXPECT_LE(std::abs(second_deviatoric_invariant(s) / j2_0 - 1.0), bound);
  EXPECT_GT(second_deviatoric_invariant(s) / j2_0 - 1.0, 0.0);  // Euler only ever grows J2
  Matrix3d exact = s0;
  exact(0, 0) = s0(1, 1);
  exact(1, 1) = s0(0, 0);
  exact(0, 1) = exact(1, 0) = -s0(0, 1);
  EXPECT_LE((s - exact).norm(), bound * s0.norm());
}

}  // namespace
}  // namespace porosph::soil
