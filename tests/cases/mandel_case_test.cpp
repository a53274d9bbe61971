// Mandel's problem (cases/mandel, issue 23) at the CI size through the real coupler, fluid_solver
// and soil_solver, with the rigid plate (soil.loads[].rigid), the lid that moves with it
// (walls[].moves_with) and carries the water's push back to it (plus_force_from); the closed form
// itself (tools/validation/mandel.h) against its limits and an independent implementation. The
// full targets (docs/verification.md) are met at the finest level of the resolution series; this
// test runs the coarsest one (dp = 0.01 m, 20 x 10 soil particles, ~10 s) with bounds set from its
// measured errors plus a margin, tight enough that a broken piece fails: with a lid that stays put
// the centre carries 0.46 p0 at most, without the lid's force on the plate 2.35 p0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/cases/case_runner.h"
#include "tools/validation/mandel.h"
#include "tools/validation/mandel_check.h"

namespace porosph::testing {
namespace {

// The scene's sample (K = G = 0.1 MPa, K_w = 2.5 MPa, k = 2e-4 m/s, a = 0.1 m, sigma0 = 1 kPa).
validation::MandelClosedForm sample(double ramp) {
  return validation::MandelClosedForm(1e5, 1e5, 2.5e6, 2e-4, 1000.0 * 9.80665, 0.1, 1000.0, ramp);
}

TEST(MandelClosedForm, MatchesItsLimitsAndAnIndependentSeries) {
  const auto m = sample(0.0);
  EXPECT_NEAR(m.poisson(), 0.125, 1e-12);  // (3K - 2G) / (2 (3K + G))
  EXPECT_NEAR(m.undrained_poisson(), 7.6 / 15.8, 1e-12);
  EXPECT_NEAR(m.skempton(), 2.5 / 2.6, 1e-12);
  const double p0 = 1000.0 * m.skempton() * (1 + m.undrained_poisson()) / 3;
  EXPECT_NEAR(m.initial_pressure(), p0, 1e-9);
  // At once the pressure is p0 everywhere inside (the series' Gibbs tail is ~1e-3 at T = 1e-5),
  // 0 at the drained side, and it has drained by T = 10 (the slowest term: exp(-1.44 T)).
  EXPECT_NEAR(m.pressure(0.0, 1e-5), p0, 2e-3 * p0);
  EXPECT_NEAR(m.pressure(0.05, 1e-5), p0, 2e-3 * p0);
  EXPECT_NEAR(m.pressure(0.1, 0.1), 0.0, 1e-9 * p0);
  EXPECT_LT(m.pressure(0.0, 10.0), 1e-5 * p0);
  // The plate: undrained -sigma0 b (1 - nu_u) / (2 G) at once, drained -sigma0 b (1 - nu) / (2 G).
  EXPECT_NEAR(m.plate_displacement(0.1, 1e-6), -1000.0 * 0.1 * (1 - m.undrained_poisson()) / 2e5,
              1e-3 * 1000.0 * 0.1 / 2e5);
  EXPECT_NEAR(m.plate_displacement(0.1, 30.0), -1000.0 * 0.1 * (1 - m.poisson()) / 2e5, 1e-12);
  // The Mandel-Cryer peak at the centre: 1.1186 p0 at T = 0.0745, from an independent series
  // (Python, scipy.optimize.brentq roots, 200 terms, T sampled every 2.5e-4; gamma_w 9810).
  double peak = 0.0, at = 0.0;
  for (double t = 0.05; t <= 0.1; t += 2.5e-4)
    if (m.pressure(0.0, t) > peak) peak = m.pressure(0.0, t), at = t;
  EXPECT_NEAR(peak / p0, 1.1186, 1e-3);
  EXPECT_NEAR(at, 0.0745, 1.5e-3);
  // A ramp over T_r: nothing before, about the step shifted by T_r / 2 long after it.
  const auto ramp = sample(0.04);
  EXPECT_EQ(ramp.pressure(0.0, 0.0), 0.0);
  const double tr = ramp.time_factor(0.04);
  EXPECT_NEAR(ramp.pressure(0.0, 0.3), m.pressure(0.0, 0.3 - tr / 2), 2e-4 * p0);
}

TEST(MandelCase, CoarseSampleShowsTheMandelCryerRiseAndFall) {
  const auto run = run_case("mandel", {});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto m = validation::check_mandel(run.out);
  EXPECT_NEAR(m.p0, 474.68, 0.01);
  ASSERT_GE(m.samples.size(), 140u);
  // Measured at dp = 0.01 m (2026-12-05, the whole width): the first share -5.7 %, the centre's
  // peak 1.100 p0 (-1.5 %) at 0.187 s (-2.9 %), profiles after the ramp within 0.081 / 0.059 /
  // 0.045 / 0.046 p0, the plate +6.7 % at the end. Bounds about 1.5 x those (the targets
  // are met at dp 5 and 2.5 mm).
  EXPECT_LE(std::abs(m.initial_error), 0.085);
  EXPECT_LE(std::abs(m.peak_error), 0.03);
  EXPECT_LE(std::abs(m.peak_time_error), 0.05);
  ASSERT_EQ(m.profiles.size(), 5u);
  for (const auto& p : m.profiles)
    if (p.judged) {
      EXPECT_LE(p.max_error, 0.12) << "T " << p.time_factor;
    }
  EXPECT_LE(std::abs(m.final_plate_error), 0.1);
  // Non-monotonic: the centre rises above its first share, then falls well below its peak.
  EXPECT_GT(m.peak, 1.05 * m.initial);
  EXPECT_LT(m.samples.back().centre, m.peak - 0.15);
}

}  // namespace
}  // namespace porosph::testing
