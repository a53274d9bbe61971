// Terzaghi consolidation (cases/consolidation, issue 23) at the CI size through the real coupler,
// fluid_solver and soil_solver; the closed form itself (tools/validation/terzaghi.h) checked
// against its own limits. The full targets (docs/verification.md) are met at the finest level of
// the resolution series; this test runs the coarsest level (dp = 0.01 m, 20 rows, ~10 s) with
// bounds set from its measured errors plus a margin, tight enough that a broken coupling fails:
// without the pore water taking the load (B = 0) U would be 1 from the start (error ~0.8); with
// the storage n / K_w instead of the model's 1 / K_w c_v is 4 % off and B 5.8 % off.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/cases/case_runner.h"
#include "tools/validation/consolidation_check.h"
#include "tools/validation/terzaghi.h"

namespace porosph::testing {
namespace {

// The series: U(0) = 0, U -> 1, U(T_v = 0.2) = 0.5040 and U(1) = 0.9313 (Verruijt 2012, table
// 15.1: 0.504, 0.931); the excess pressure is B p0 at the impermeable base early, 0 at the top.
TEST(ConsolidationClosedForm, MatchesTheTabulatedDegreeAndLimits) {
  const validation::TerzaghiColumn step(1.0, 1.0, 0.9, 1e-6, 1000.0, 0.0);
  EXPECT_NEAR(step.degree(0.2), 0.5040, 1e-3);
  EXPECT_NEAR(step.degree(1.0), 0.9313, 1e-3);
  EXPECT_NEAR(step.degree(10.0), 1.0, 1e-9);
  EXPECT_NEAR(step.excess_pressure(1.0, 1e-3), 900.0, 1e-3);  // base, just after loading
  EXPECT_NEAR(step.excess_pressure(0.0, 0.5), 0.0, 1e-9);     // drained top
  // U = 2 sqrt(T / pi) for small T (the half-space limit).
  EXPECT_NEAR(step.degree(0.01), 2.0 * std::sqrt(0.01 / M_PI), 1e-4);
  // Settlement: s = m_v p0 H (1 - B (1 - U)): (1 - B) m_v p0 H undrained, m_v p0 H drained.
  EXPECT_NEAR(step.settlement(1e-3), 1e-3 * (1.0 - 0.9 * (1.0 - 2.0 * std::sqrt(1e-3 / M_PI))),
              1e-3 * 1e-3);
  EXPECT_NEAR(step.settlement(10.0), 1e-3, 1e-9);
  // A ramp: nothing at T = 0, the step solution shifted by about half the ramp long after it.
  const validation::TerzaghiColumn ramp(1.0, 1.0, 0.9, 1e-6, 1000.0, 0.02);
  EXPECT_GE(ramp.degree(1e-4), 0.0);  // a ramp consolidates later than the step
  EXPECT_LT(ramp.degree(1e-4), step.degree(1e-4));
  EXPECT_NEAR(ramp.degree(0.5), step.degree(0.49), 2e-4);
}

TEST(ConsolidationCase, CoarseColumnFollowsTerzaghi) {
  const auto run = run_case("consolidation", {});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto c = validation::check_consolidation(run.out);
  EXPECT_NEAR(c.b_model, 0.9091, 1e-4);
  EXPECT_NEAR(c.c_v, 0.046335, 1e-5);
  ASSERT_GE(c.samples.size(), 300u);
  // Measured at dp = 0.01 m (2026-12-05): U 0.0140, isochrones 0.0075 / 0.0058 / 0.0037 p0,
  // B -0.53 %, settlement +0.73 % (with the code of 2026-12-04:
  // U 0.041, isochrones 0.019 / 0.031 / 0.047 p0; docs/verification.md). Bounds about 1.5x the
  // new figures: a return to the old ones fails.
  EXPECT_LE(c.max_degree_error, 0.021);
  for (const auto& iso : c.isochrones) EXPECT_LE(iso.max_error, 0.012) << "T_v " << iso.time_factor;
  EXPECT_LE(std::abs(c.b_error), 0.01);
  EXPECT_LE(std::abs(c.settlement_error), 0.011);
}

}  // namespace
}  // namespace porosph::testing
