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

// dp = 0.01 m for 0.6 s (~30 s on one core), averaged over 0.45-0.6 s, the pools open onto their
// reservoirs (open boundaries), a cut-off wall under the weir's downstream face. Measured with the
// drag replacing the artificial viscosity in the sand and the soil sums renormalised beside the
// walls (2026-12-06, latest): pool heads 0.3494 / 0.3006 m (levels 0.35 / 0.30), discharge
// -2.68 % of the FV reference (its 0.6 s still rising; the layer alone -1.05 %), probe pressures
// within 0.24 %, heads within 0.9 % of dh, exit gradient -2.7 %, each pool within 0.52 % of dh of
// its mean next to the weir (before, with truncated sums and the drag-limited viscosity: +0.44 %,
// 0.26 %, 1.0 %, +5.5 %, 0.55 %; with the trace form of the kernel gradient as well: -1.0 %,
// 0.32 %, 1.3 %, +5.4 %, 0.7 %). dp 0.02 m
// is too coarse for this geometry: the 4 cm cut-off is two particles thick there and the exit
// gradient comes out 55 % high. Bounds: the reservoirs hold the pools within dp/2 of their levels;
// the pressures within the 1 %; the discharge within 4 % and the exit gradient within 15 %
// (a broken drag, reservoir, cut-off or reference is off by far more; the 1 % and 3 % at
// the finest level are judged in docs/verification.md).
TEST(SeepageWeirCase, ShortRunSeepsUnderTheWeirNearTheFvReference) {
  const auto run = run_case("seepage_weir", {"run.dp=0.01", "run.end_time=0.6"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto c = validation::check_seepage_weir(run.out);
  EXPECT_EQ(c.outputs, 4u);
  EXPECT_NEAR(c.head_upstream, 0.35, 0.005);
  EXPECT_NEAR(c.head_downstream, 0.30, 0.005);
  EXPECT_GT(c.discharge, 0.0);
  EXPECT_LT(std::abs(c.discharge_error()), 0.04) << "q " << c.discharge;
  EXPECT_LE(c.max_pressure_error(), 0.01);
  EXPECT_LT(std::abs(c.exit_gradient_error()), 0.15) << "exit " << c.exit_gradient;
  // Each pool next to the weir within 5 % of dh of its mean (measured 0.5-1.5 % at 10 and 5 mm,
  // the pools' seiche and, with the trace form of the kernel gradient, their tilt;
  // docs/verification.md): a pool tilted by 5 % of dh would take about that much of the
  // discharge, a broken reservoir or pool far more.
  EXPECT_LT(std::abs(c.upstream_head_near_weir), 0.05);
  EXPECT_LT(std::abs(c.downstream_head_near_weir), 0.05);
}

}  // namespace
}  // namespace porosph::testing
