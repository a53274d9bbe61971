// Seepage under a weir (cases/seepage_weir), shortened, through the real coupler, the water solver,
// the rigid soil solver and the open constant-head reservoirs, checked with porosph_validate's
// seepage_weir check against the grid-converged FV Laplace reference (issue 30 item 5; the full
// verdict, not met yet, is in docs/verification.md).
#include <gtest/gtest.h>

#include <cmath>

#include "tests/cases/case_runner.h"
#include "tools/validation/seepage_weir_check.h"

namespace porosph::testing {
namespace {

// dp = 0.02 m for 0.6 s (~15 s on one core), averaged over 0.45-0.6 s, the pools open onto their
// reservoirs (open boundaries). Measured: pool heads 0.3442 / 0.3001 m (levels 0.35 / 0.30; the
// upstream pool is still rising to its level), discharge -1.7 % of the FV reference, probe
// pressures within 0.59 %, heads up to 3.4 % of dh, exit gradient -22 %. Bounds: the reservoirs
// hold the pools within dp/2 of their levels; the pressures within the 1 %; the discharge
// within 5 % (a broken drag, reservoir or reference is off by far more; the 1 % is not met
// at the finer levels, docs/verification.md); the exit gradient within 40 % below the reference
// and 10 % above (it converges from below: the kernel smooths the weir's corner singularity).
TEST(SeepageWeirCase, ShortRunSeepsUnderTheWeirNearTheFvReference) {
  const auto run = run_case("seepage_weir", {"run.dp=0.02", "run.end_time=0.6"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto c = validation::check_seepage_weir(run.out);
  EXPECT_EQ(c.outputs, 4u);
  EXPECT_NEAR(c.head_upstream, 0.35, 0.01);
  EXPECT_NEAR(c.head_downstream, 0.30, 0.01);
  EXPECT_GT(c.discharge, 0.0);
  EXPECT_LT(std::abs(c.discharge_error()), 0.05) << "q " << c.discharge;
  EXPECT_LE(c.max_pressure_error(), 0.01);
  EXPECT_GT(c.exit_gradient, 0.6 * c.exit_gradient_reference);
  EXPECT_LT(c.exit_gradient, 1.1 * c.exit_gradient_reference);
}

}  // namespace
}  // namespace porosph::testing
