// Every case in cases/ runs, shortened, through the real coupler and fluid_solver, and its run
// directory keeps the contract of docs/design.md section 6. The hydrostatic tank also runs its full
// 2 s (at a coarser spacing) against the analytic pressure.
#include <gtest/gtest.h>

#include <cmath>

#include "io/snapshot_reader.h"
#include "tests/cases/case_runner.h"
#include "tests/io/xdmf_check.h"
#include "tools/validation/dam_break_check.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/still_water_check.h"

namespace porosph::testing {
namespace {

/// The run-directory contract for a water-only run with `outputs` snapshots.
void expect_water_run_directory(const CaseRun& run, std::size_t outputs) {
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& r = run.record;
  EXPECT_EQ(r.at("status"), "completed");
  for (const char* key : {"scene", "parameters", "steps", "simulated_time", "wall_seconds",
                          "phases", "dt", "ledger", "observables"}) {
    EXPECT_TRUE(r.contains(key)) << "run.json lacks " << key;
  }
  const auto& water = r.at("phases").at("water");
  EXPECT_GT(water.at("particles").at("free").get<double>(), 0);
  // Mass: no particle leaves a closed tank, so the free mass is exactly conserved (same particles,
  // same masses; only round-off in the sum).
  EXPECT_NEAR(water.at("mass").at("final").get<double>(),
              water.at("mass").at("initial").get<double>(),
              1e-9 * water.at("mass").at("initial").get<double>());
  EXPECT_EQ(r.at("ledger").at("relative_imbalance").get<double>(), 0.0);

  const auto series = validation::read_timeseries(run.out);
  for (const char* column : {"t", "dt", "water_kinetic_energy", "water_momentum_x",
                             "water_momentum_y", "water_mass", "water_particles"}) {
    EXPECT_TRUE(series.columns.count(column)) << "timeseries.csv lacks " << column;
  }
  EXPECT_EQ(series.column("t").size(), outputs);

  io::SnapshotReader h5(run.out + "/water.h5");
  const auto snapshots = h5.snapshots();
  ASSERT_EQ(snapshots.size(), outputs);
  const auto last = snapshots.back();
  EXPECT_NEAR(last.time, r.at("simulated_time").get<double>(), 1e-12);
  const std::size_t n = water.at("particles").at("total").get<std::size_t>();
  EXPECT_EQ(h5.read_f64(last.index, "position").rows, n);
  EXPECT_EQ(h5.read_f64(last.index, "position").cols, 2u);
  EXPECT_EQ(h5.read_f64(last.index, "velocity").cols, 2u);
  EXPECT_EQ(h5.read_f64(last.index, "density").rows, n);
  EXPECT_EQ(h5.read_f64(last.index, "pressure").rows, n);
  EXPECT_EQ(h5.read_i64(last.index, "id").rows, n);
  EXPECT_EQ(h5.read_u8(last.index, "fixed").rows, n);

  const auto problems = test::check_xdmf_references(run.out + "/run.xdmf");
  EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST(Cases, DamBreakShortened) {
  // ~300 steps at the default resolution (dt ~ 1.9e-5 s from the CFL limit).
  const auto run = run_case("dam_break", {"run.end_time=0.006", "run.output_interval=0.002"});
  expect_water_run_directory(run, 4);
  // The column starts to collapse: the front moves forward and the kinetic energy grows.
  const auto series = validation::read_timeseries(run.out);
  const auto& front = series.column("front");
  EXPECT_GT(front.back(), front.front());
  EXPECT_GT(series.column("water_kinetic_energy").back(), 0.0);
}

TEST(Cases, HydrostaticTankShortened) {
  const auto run = run_case("hydrostatic_tank",
                            {"run.end_time=0.03", "run.output_interval=0.01", "run.dp=0.02"});
  expect_water_run_directory(run, 4);
}

// The full 2 s of the hydrostatic tank at dp = 0.02 m (30 x 20 particles, ~6,000 steps), against
// still weakly compressible water p(d) (tools/validation/still_water.h). Measured at this spacing
// with the lattice-normalised kernel gradient, the density diffusion's linear correction and the
// start from p(d): per-particle error 0.29 %, row-mean 0.09 %, bottom-quarter bias -0.004 % of
// rho0 g H, max speed 0.005 % of sqrt(g H) (before those changes: 3.9 %, 2.3 %, +0.7 %, 1.1 %).
// Bounds: the issue-30 bias target 0.2 % itself; the others 2-6x the measurement, far below the
// old values, so a return of the lattice bias (+0.93 %) or the diffusion creep fails.
TEST(Cases, HydrostaticTankStaysHydrostaticForTwoSeconds) {
  const auto run = run_case("hydrostatic_tank", {"run.dp=0.02", "run.output_interval=0.5"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto check = validation::check_hydrostatic(run.out);
  EXPECT_NEAR(check.time, 2.0, 1e-9);
  EXPECT_NEAR(check.depth, 0.6, 0.01);  // the column compresses by ~gH/(2c^2) only
  EXPECT_LE(std::abs(check.bottom_quarter_bias), 0.002);
  EXPECT_LE(check.max_row_rel_error, 0.005);
  EXPECT_LE(check.max_rel_error, 0.006);
  EXPECT_LE(check.max_speed_ratio, 3e-4);
  // Against the incompressible rho0 g d the bias adds the water's own compression,
  // p(d) - rho0 g d = rho0 g d^2 g / (2 c0^2): the mean of d^2 over the bottom quarter is
  // (1 - 0.75^3) / (3 * 0.25) H^2 = 0.771 H^2, so 0.771 g H / (2 c0^2) = 0.384 % of rho0 g H
  // (c0 = 24.3 m/s); measured 0.372 %. Tolerance 0.05 %: the particles sit at the row centres.
  EXPECT_NEAR(check.bottom_quarter_bias_incompressible - check.bottom_quarter_bias,
              0.771 * 9.81 * 0.6 / (2 * 24.3 * 24.3), 5e-4);
}

// The whole dam break at a/20 (20 x 40 particles): the bulk front against Martin & Moyce (1952).
// The converged model leads the table by a nearly constant dT = 0.18-0.21 at every dp (the
// experiment's release took time; Lethe's VOF benchmark shifts the same table by 0.175), which
// leaves a raw mean |dZ| of 0.22-0.25 (docs/validation-studies.md, dam break). So this test checks
// what does not depend on the time origin, with bounds about 1.5 times the measured figures:
// - the late front speed (T >= 2.2) within 6 % of the table's (measured +4.0 %; the model lacks
//   the floor's physical drag on the thin tip, estimated at 3-5 % of the speed);
// - the shape: the least mean |dZ| over release delays 0..0.6 <= 0.05 (measured 0.030; the
//   table's Z are 0.22-wide marks), at a delay between 0.1 and 0.3 (measured 0.18);
// - the raw mean |dZ| <= 0.30 (measured 0.216), max <= 0.45 (0.333).
TEST(Cases, DamBreakFrontFollowsMartinMoyce) {
  const auto run = run_case("dam_break", {"run.dp=0.0028575"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto c = validation::compare_dam_break(run.out, source("cases/dam_break/reference.csv"));
  EXPECT_EQ(c.T.size(), 15u);
  EXPECT_LE(std::abs(c.late_speed / c.late_speed_reference - 1.0), 0.06) << c.late_speed;
  EXPECT_LE(c.mean_abs_error_shifted, 0.05);
  EXPECT_GE(c.best_shift, 0.1);
  EXPECT_LE(c.best_shift, 0.3);
  EXPECT_LE(c.mean_abs_error, 0.30);
  EXPECT_LE(c.max_abs_error, 0.45);
}

}  // namespace
}  // namespace porosph::testing
