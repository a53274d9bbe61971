// Modified Verlet on a constant acceleration: exact parabola for Euler and Verlet steps alike.
#include "sph/integrator.h"

#include <gtest/gtest.h>

namespace porosph::sph {
namespace {

TEST(SphIntegrator, ConstantAccelerationIsIntegratedExactly) {
  // x = x0 + v0 t + a t^2 / 2 and v = v0 + a t hold exactly for both step kinds at constant dt:
  // only round-off (1e-12 relative) remains after 1000 steps.
  const Vec<2> x0(0.1, 2.0), v0(1.5, -0.5), a(0.3, -9.81);
  Vec<2> x = x0, v = v0, v_prev = v0;
  const double dt = 1e-3;
  for (int n = 0; n < 1000; ++n) verlet_step<2>(x, v, v_prev, a, dt, is_euler_step(n, 40));
  const double t = 1000 * dt;
  EXPECT_LT((x - (x0 + v0 * t + 0.5 * a * t * t)).norm(), 1e-12 * 10);
  EXPECT_LT((v - (v0 + a * t)).norm(), 1e-12 * 10);
}

TEST(SphIntegrator, ScalarStepsAndEulerSchedule) {
  double q = 1.0, q_prev = 1.0;
  verlet_step_scalar(q, q_prev, 2.0, 0.1, true);  // Euler: 1 + 0.2
  EXPECT_DOUBLE_EQ(q, 1.2);
  EXPECT_DOUBLE_EQ(q_prev, 1.0);
  verlet_step_scalar(q, q_prev, 2.0, 0.1, false);  // Verlet: q^{n-1} + 2 dt r = 1 + 0.4
  EXPECT_DOUBLE_EQ(q, 1.4);
  EXPECT_DOUBLE_EQ(q_prev, 1.2);
  EXPECT_TRUE(is_euler_step(0, 40));
  EXPECT_FALSE(is_euler_step(39, 40));
  EXPECT_TRUE(is_euler_step(40, 40));
  EXPECT_FALSE(is_euler_step(5, 0));
  EXPECT_TRUE(is_euler_step(5, 1));
}

}  // namespace
}  // namespace porosph::sph

namespace porosph::sph {
namespace {

// Implicit drag: a particle with drag rate lambda toward a partner at rest (a = -lambda v), with
// lambda dt = 100 - a relaxation time 100x below dt. The explicit scheme's factor per step is
// |1 - lambda dt| = 99 (blow-up); the implicit one must decay: Euler by 1 / (1 + lambda dt) per
// step, Verlet by 1 / (1 + 2 lambda dt) per two steps. 20 mixed steps: below 1e-10.
TEST(SphIntegrator, ImplicitDragIsStableFarBelowTheRelaxationTime) {
  const double dt = 1e-4, lambda = 100.0 / dt;
  Vec<2> x(0.0, 0.0), v(1.0, 0.0), v_previous(1.0, 0.0);
  double largest = 1.0;
  for (int step = 0; step < 20; ++step) {
    const Vec<2> a = -lambda * v;
    verlet_step_implicit_drag<2>(x, v, v_previous, a, lambda, dt, is_euler_step(step, 8));
    largest = std::max(largest, v.norm());
    ASSERT_TRUE(v.allFinite());
  }
  EXPECT_LE(largest, 1.0);        // never above the start
  EXPECT_LT(v.norm(), 1e-1);      // and decaying
  EXPECT_LT(x.norm(), 2.0 * dt);  // moved about v / lambda = dt (no dt^2 a kick)
}

// A steady state (a = 0 with a drag balancing the rest) is kept exactly, and lambda = 0 is the
// explicit scheme.
TEST(SphIntegrator, ImplicitDragKeepsASteadyStateAndReducesToVerlet) {
  Vec<2> x(0.0, 0.0), v(0.3, -0.2), v_previous(0.3, -0.2);
  for (int step = 0; step < 5; ++step) {
    verlet_step_implicit_drag<2>(x, v, v_previous, Vec<2>::Zero(), 1e6, 1e-3, step == 0);
  }
  EXPECT_LT((v - Vec<2>(0.3, -0.2)).norm(), 1e-15);
  Vec<2> x1(0.1, 0.2), v1(1.0, 2.0), p1(0.5, 1.0), x2 = x1, v2 = v1, p2 = p1;
  const Vec<2> a(3.0, -4.0);
  verlet_step<2>(x1, v1, p1, a, 0.01, false);
  verlet_step_implicit_drag<2>(x2, v2, p2, a, 0.0, 0.01, false);
  EXPECT_EQ(x1, x2);
  EXPECT_EQ(v1, v2);
  EXPECT_EQ(p1, p2);
}

}  // namespace
}  // namespace porosph::sph
