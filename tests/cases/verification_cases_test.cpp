// The closed-form verification cases (docs/verification.md), small versions run through the real
// coupler and solvers and checked with the porosph_validate code (verification_checks.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scene/scene_schema.h"
#include "tests/cases/case_runner.h"
#include "tools/validation/verification_checks.h"

namespace porosph::testing {
namespace {

// Taylor-Green vortex at Re = 100 at dp = L/50 and L/100 (~3 s and ~20 s on one core): the
// kinetic-energy decay rate against 4 nu k^2, and the mean density (docs/verification.md). Without
// particle shifting the rate is +125 % off (the lattice breaks down at t ~ 0.1 s).
TEST(VerificationCases, TaylorGreenDecayRateConverges) {
  // Each run's check before the next run (both use the case's run directory).
  const auto coarse = run_case("taylor_green", {"run.dp=0.02"});
  ASSERT_EQ(coarse.result.exit_code, 0) << coarse.result.output;
  const auto c = validation::check_taylor_green(coarse.out);
  const auto fine = run_case("taylor_green", {"run.dp=0.01"});
  ASSERT_EQ(fine.result.exit_code, 0) << fine.result.output;
  const auto f = validation::check_taylor_green(fine.out);
  EXPECT_NEAR(c.rate_analytic, 4 * 0.01 * 4 * M_PI * M_PI, 1e-12);
  // Measured (2026-12-05, the continuity equation sees the particle shift, the density diffusion
  // of a Verlet step acts on rho^{n-1}; docs/verification.md): +2.76 % at dp 0.02, +1.28 % at
  // dp 0.01 (order 1.1; before: -2.14 / +0.44 %, whose sign turn came from a density drift).
  // Bounds: the 2 % at the finer level, 4 % at the coarse one; the symmetric pressure
  // form's +5.9 / +3.7 % fails both. The error must fall with refinement.
  EXPECT_LT(std::abs(c.rel_error), 0.04) << "rate " << c.rate_simulated;
  EXPECT_LT(std::abs(f.rel_error), 0.02) << "rate " << f.rate_simulated;
  EXPECT_LT(std::abs(f.rel_error), std::abs(c.rel_error));
  // The box's volume is fixed, so its mean density is rho0: measured +0.140 % / +0.084 % over the
  // window (+2.32 / +0.96 % while the continuity equation did not see the shift). Bound 0.5 %.
  EXPECT_LT(std::abs(c.density_drift), 0.005);
  EXPECT_LT(std::abs(f.density_drift), 0.005);
  // ln E stays on a line (an exponential decay; a breakdown of the lattice gives ~1): measured
  // 0.012 at dp 0.01 (acoustic noise of the particle disorder, 0.0026 at dp 0.005).
  EXPECT_LT(f.fit_residual, 0.02);
  EXPECT_NEAR(f.energy0, f.energy0_analytic, 1e-3 * f.energy0_analytic);
}

// Every laminar viscosity law (water.laminar_viscosity, fluid_solver/laminar_viscosity.h) on the
// Taylor-Green vortex at dp = L/50 (~3 s each): a law that is a consistent discretisation of
// mu lap v decays the vortex at the rate 2 nu k^2 like the Morris term (measured +2.76 % at this
// resolution, above). Bound 4.5 %; a law with a wrong factor of 2 or a wrong density weighting
// would be off by tens of percent.
TEST(VerificationCases, TaylorGreenDecaysAtTheRateOfEveryLaminarViscosityLaw) {
  const scene::SceneSchema schema = scene::make_scene_schema();
  const scene::KeySpec* key = schema.find_key("water.laminar_viscosity");
  ASSERT_NE(key, nullptr);
  ASSERT_FALSE(key->allowed.empty());
  for (const std::string& law : key->allowed) {
    const auto run =
        run_case("taylor_green", {"run.dp=0.02", "water.laminar_viscosity=\"" + law + "\""});
    ASSERT_EQ(run.result.exit_code, 0) << law << ": " << run.result.output;
    const auto c = validation::check_taylor_green(run.out);
    EXPECT_LT(std::abs(c.rel_error), 0.045) << law << ": rate " << c.rate_simulated;
    std::printf("laminar viscosity %s: decay rate error %+.2f %%\n", law.c_str(),
                100.0 * c.rel_error);
  }
}

// Elastic column loaded suddenly by gravity at dp = 0.02 m for 3 periods (~3 s). Measured (full
// 5 periods): period +0.02 %, settlement -0.01 % with the lattice-normalised gradient; +0.95 % and
// +1.85 % with the plain kernel, whose gradient on the lattice at h = 1.2 dp is 0.9908 short
// (squared 0.9817: a 1.8 % softer column; docs/verification.md). Bounds: 0.5 %, which the plain
// kernel's lattice error fails; a wrong modulus (plane stress, E for M) would be off by 10 % or
// more. The soil must stay elastic (plastic strain exactly 0).
TEST(VerificationCases, ElasticColumnPeriodAndSettlement) {
  const auto run = run_case("elastic_column", {"run.dp=0.02", "run.end_time=0.16"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto c = validation::check_elastic_column(run.out);
  EXPECT_EQ(c.max_plastic_strain, 0.0);
  EXPECT_GE(c.periods, 3u);
  EXPECT_LT(std::abs(c.period_error), 0.005) << "period " << c.period_simulated;
  EXPECT_LT(std::abs(c.settlement_error), 0.005) << "settlement " << c.settlement_simulated;
  EXPECT_TRUE(c.met());
}

}  // namespace
}  // namespace porosph::testing
