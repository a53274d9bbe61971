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
