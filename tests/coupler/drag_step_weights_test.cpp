// The implicit drag's weights over a step (coupler/interaction/drag_step_weights.h) against the
// exact solution of one linear pair, dv/dt = d - lambda v.
#include "coupler/interaction/drag_step_weights.h"

#include <gtest/gtest.h>

#include <cmath>

namespace porosph::coupler {
namespace {

/// The exact mean of lambda v over a step dt from v0 (per unit drag coefficient and mass): the
/// impulse of the drag is that of d less the velocity change (v0 - d / lambda)(e^-x - 1), the
/// change written with expm1 so that it keeps its digits at small x.
double exact_mean_drag(double lambda, double d, double v0, double dt) {
  const double change = (v0 - d / lambda) * std::expm1(-lambda * dt);
  return d - change / dt;
}

double weighted_drag(DragStep step, double lambda, double d, double v0, double dt) {
  const DragStepWeights w = drag_step_weights(step, lambda * dt);
  const double v_star = v0 + dt * d;
  return lambda * (w.start * v0 + w.change * (v_star - v0));
}

// The exponential weights give the exact mean drag of the linear pair at every lambda dt, across
// the series branch (x < 1e-4) and the closed form: to 1e-12 relative of the drag scale.
TEST(DragStepWeights, ExponentialIsTheExactMeanOfTheLinearPair) {
  const double d = 3.0, v0 = -0.7;
  for (double x : {1e-9, 1e-6, 9.9e-5, 1.01e-4, 1e-3, 0.1, 1.0, 10.0, 1e3}) {
    const double lambda = 200.0, dt = x / lambda;
    const double scale = lambda * std::abs(v0) + std::abs(d);
    EXPECT_NEAR(weighted_drag(DragStep::kExponential, lambda, d, v0, dt),
                exact_mean_drag(lambda, d, v0, dt), 1e-12 * scale)
        << "x = " << x;
  }
}

// Both steps keep the steady state v0 = d / lambda exactly (the drag balances d) at any lambda dt.
TEST(DragStepWeights, BothKeepASteadyStateExactly) {
  const double lambda = 50.0, d = 2.0;
  for (double x : {1e-3, 0.3, 30.0}) {
    for (DragStep step : {DragStep::kBackwardEuler, DragStep::kExponential}) {
      EXPECT_NEAR(weighted_drag(step, lambda, d, d / lambda, x / lambda), d, 1e-12 * d);
    }
  }
}

// Away from the steady state, backward Euler's error in the mean drag is first order in dt:
// halving dt halves it (ratio 2 within 5 % at lambda dt = 0.02 -> 0.01).
TEST(DragStepWeights, BackwardEulerIsFirstOrderAwayFromTheSteadyState) {
  const double lambda = 100.0, d = 5.0, v0 = 0.0;
  const auto error = [&](double dt) {
    return std::abs(weighted_drag(DragStep::kBackwardEuler, lambda, d, v0, dt) -
                    exact_mean_drag(lambda, d, v0, dt));
  };
  EXPECT_NEAR(error(2e-4) / error(1e-4), 2.0, 0.1);
}

// The two weights meet at x = 1e-4, where the series hands over to the closed form.
TEST(DragStepWeights, SeriesAndClosedFormAgreeWhereTheyMeet) {
  const DragStepWeights below = drag_step_weights(DragStep::kExponential, 0.99999e-4);
  const DragStepWeights above = drag_step_weights(DragStep::kExponential, 1.00001e-4);
  EXPECT_NEAR(below.start, above.start, 1e-9);
  EXPECT_NEAR(below.change, above.change, 1e-8);
  const DragStepWeights zero = drag_step_weights(DragStep::kExponential, 0.0);
  EXPECT_EQ(zero.start, 1.0);
  EXPECT_EQ(zero.change, 0.5);
}

}  // namespace
}  // namespace porosph::coupler
