// Fig. 1 smoothing (docs/design.md section 4) over single steps and long random sequences.
#include "coupler/time_step_controller.h"

#include <gtest/gtest.h>

#include <random>

namespace porosph::coupler {
namespace {

TEST(TimeStepController, StartsAtDt0AndStaysThereWithoutActiveLimit) {
  TimeStepController c(1e-4);
  EXPECT_DOUBLE_EQ(c.current(), 1e-4);
  for (int i = 0; i < 10; ++i) EXPECT_DOUBLE_EQ(c.next(1.0), 1e-4);
}

TEST(TimeStepController, DecreasesAtOnceToTheLimit) {
  TimeStepController c(1e-4);
  EXPECT_DOUBLE_EQ(c.next(3e-5), 3e-5);
  EXPECT_DOUBLE_EQ(c.next(1e-5), 1e-5);
}

TEST(TimeStepController, RisesByHarmonicMeanTowardsALargerLimit) {
  TimeStepController c(1e-4);
  c.next(1e-5);
  // limit 5e-5 (still < dt0): 2 * 1e-5 * 5e-5 / 6e-5
  EXPECT_NEAR(c.next(5e-5), 2 * 1e-5 * 5e-5 / 6e-5, 1e-18);
}

TEST(TimeStepController, RelaxesBackToDt0WhenNoLimitIsActive) {
  TimeStepController c(1e-4);
  c.next(1e-6);
  double prev = c.current();
  for (int i = 0; i < 200; ++i) {
    const double dt = c.next(1.0);
    // Harmonic mean, snapped to dt0 once within 1e-12 relative of it.
    EXPECT_NEAR(dt, 2 * prev * 1e-4 / (prev + 1e-4), 1e-12 * 1e-4);
    EXPECT_GE(dt, prev);
    prev = dt;
  }
  // With r = dt0/dt the iteration is r -> (r + 1)/2: r - 1 halves each step, exactly dt0 long
  // before 200.
  EXPECT_EQ(c.current(), 1e-4);
}

TEST(TimeStepController, SmoothingOffTakesTheMinimum) {
  TimeStepController c(1e-4, /*smoothing=*/false);
  EXPECT_DOUBLE_EQ(c.next(1e-6), 1e-6);
  EXPECT_DOUBLE_EQ(c.next(5e-5), 5e-5);
  EXPECT_DOUBLE_EQ(c.next(1.0), 1e-4);
}

TEST(TimeStepController, StopsWithAClearErrorWhenCollapsing) {
  TimeStepController c(1e-4);
  EXPECT_NO_THROW(c.next(1.1e-9));
  try {
    c.next(0.9e-9);  // below 1e-5 * dt0 = 1e-9
    FAIL() << "expected TimeStepCollapse";
  } catch (const TimeStepCollapse& e) {
    EXPECT_NE(std::string(e.what()).find("blowing up"), std::string::npos);
  }
  EXPECT_THROW(c.next(std::nan("")), TimeStepCollapse);
  EXPECT_THROW(c.next(0.0), TimeStepCollapse);
}

// Long random sequences: the invariants of Fig. 1 hold at every one of 100,000 steps.
TEST(TimeStepController, LongRandomSequencesKeepTheInvariants) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> log_ratio(-4.0, 1.0);  // limits 1e-4 .. 10 x dt0
  const double dt0 = 2e-5;
  for (bool smoothing : {true, false}) {
    TimeStepController c(dt0, smoothing);
    double prev = c.current();
    for (int i = 0; i < 100000; ++i) {
      const double limit = dt0 * std::pow(10.0, log_ratio(rng));
      const double dt = c.next(limit);
      ASSERT_LE(dt, limit * (1 + 1e-14)) << "step " << i << ": above the active limit";
      ASSERT_LE(dt, dt0) << "step " << i << ": above dt0";
      ASSERT_GT(dt, 0.0);
      if (limit < prev) {
        ASSERT_DOUBLE_EQ(dt, limit) << "step " << i << ": must decrease at once";
      } else if (smoothing) {
        ASSERT_GE(dt, prev) << "step " << i << ": a rise must not go down";
        // Harmonic mean of prev and min(limit, dt0) lies between them.
        ASSERT_LE(dt, std::min(limit, dt0) * (1 + 1e-14));
      }
      prev = dt;
    }
  }
}

}  // namespace
}  // namespace porosph::coupler
