// Still water stays still (issue 30): water at rest over and inside a rigid porous bed
// (cases/still_bed), checked with porosph_validate's still-bed check against still weakly
// compressible water (tools/validation/still_water.h).
#include <gtest/gtest.h>

#include <cmath>

#include "tests/cases/case_runner.h"
#include "tools/validation/still_water_check.h"

namespace porosph::testing {
namespace {

// The still bed for its full 1 s at dp = 0.02 and 0.01 m (~3 s and ~11 s on one core). Targets of
// issue 30, as such: no water faster than 0.1 % of sqrt(g H); the mean head in the bottom quarter
// of the bed within 0.2 % of H of the free surface. Measured (docs/verification.md): head bias
// -0.00x % at both levels, max speed 0.007-0.01 % (before the lattice-normalised gradient and the
// exact hydrostatic density diffusion: +1.68 % and a creep of 2.4e-5 m/s through the bed).
TEST(StillWaterCases, StillBedStaysStillWithAFlatHead) {
  for (const char* dp : {"run.dp=0.02", "run.dp=0.01"}) {
    const auto run = run_case("still_bed", {dp});
    ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
    const auto c = validation::check_still_bed(run.out);
    EXPECT_NEAR(c.time, 1.0, 1e-9);
    EXPECT_NEAR(c.depth, 0.35, 0.01) << dp;
    EXPECT_GT(c.particles, 20u);
    EXPECT_LE(c.max_speed_ratio, 0.001) << dp;
    EXPECT_LE(std::abs(c.head_bias), 0.002) << dp;
    // The head z + p / (rho0 g) exceeds z + Phi(p) / g by the water's own compression,
    // g d^2 / (2 c0^2) at depth d: over the bed's bottom quarter (d = 0.30-0.35 m of H = 0.35 m)
    // the mean of d^2 / H^2 is 0.86, so 0.86 g H / (2 c0^2) = 0.37 % (c0 = 20 m/s); measured 0.366
    // %.
    EXPECT_NEAR(c.head_bias_incompressible - c.head_bias, 0.86 * c.compressibility,
                0.08 * c.compressibility)
        << dp;
  }
}

}  // namespace
}  // namespace porosph::testing
