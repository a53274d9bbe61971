// Shortened versions of the seed paper's dam and excavation cases (issue 6): the rockfill shell
// overtopped over its core (4.2) and the hydraulic heave next to a sheet pile (4.3), through the
// real coupler and solvers at twice the paper's spacing: set-up, a few hundred stable steps, the
// run-directory contract and conservation. The full runs and their errors against the
// experiments: tools/validation/report.py, docs/validation.md.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/cases/case_runner.h"
#include "tests/io/xdmf_check.h"
#include "tools/validation/dam_case_checks.h"
#include "tools/validation/run_directory.h"

namespace porosph::testing {
namespace {

/// Contract of a finished coupled run: completed, both phases' files, XDMF references valid, mass
/// of each phase = initial + inflow - outflow to round-off, interaction impulses balanced.
void expect_coupled_contract(const CaseRun& run) {
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& r = run.record;
  EXPECT_EQ(r.at("status"), "completed");
  for (const char* phase : {"water", "soil"}) {
    const auto& mass = r.at("phases").at(phase).at("mass");
    EXPECT_LT(mass.at("relative_imbalance").get<double>(), 1e-12) << phase << " " << mass.dump();
  }
  EXPECT_LT(r.at("ledger").at("relative_imbalance").get<double>(), 1e-10);
  EXPECT_TRUE(std::filesystem::exists(run.out + "/water.h5"));
  EXPECT_TRUE(std::filesystem::exists(run.out + "/soil.h5"));
  const auto problems = test::check_xdmf_references(run.out + "/run.xdmf");
  EXPECT_TRUE(problems.empty()) << problems.front();
}

// Rockfill shell at dp 0.02: the shell polygon (area 0.95 m^2) holds 0.95 / dp^2 = 2,375 free soil
// particles (lattice fill of the slope: within 2 %); the inflow starts after a shortened damping
// stage and feeds water in (inflow mass > 0); the dry shell stands on its 1.5 kPa cohesion: no
// slope particle moves more than D15 / 2 = 13 mm (B = 0 at that threshold), and the soil stays
// slow (< 0.05 m/s: an unstable slope or a tensile blow-up would exceed it within these steps).
TEST(DamCases, RockfillOvertoppingShortenedIsStableAndFedByTheInflow) {
  const auto run = run_case("rockfill_overtopping",
                            {"run.dp=0.02", "run.max_steps=3000", "run.output_interval=0.02",
                             "soil.damping_duration=0.02", "water.inflow.0.start_time=0.02"});
  expect_coupled_contract(run);
  const auto& r = run.record;
  const auto& soil = r.at("phases").at("soil");
  EXPECT_NEAR(soil.at("particles").at("free").get<double>(), 2375.0, 0.02 * 2375);
  EXPECT_GT(r.at("phases").at("water").at("mass").at("inflow").get<double>(), 0.0);
  EXPECT_LT(soil.at("final").at("max_speed").get<double>(), 0.05);
  const auto c = validation::check_rockfill(run.out);
  EXPECT_NEAR(c.x_toe, 1.7, 1e-12);
  EXPECT_NEAR(c.x_crest, 0.2, 1e-12);
  EXPECT_NEAR(c.flume_width, 2.5, 1e-9);  // cross_section 0.1 m^2 over the 4 cm sheet
  EXPECT_EQ(c.b[0], 0.0);
}

// Hydraulic heave at dp 5 mm, 1,000 steps after a shortened damping stage: water and soil overlap
// from the start (interaction evaluated every step), the overall head starts at 0.30 - 0.08 =
// 0.22 m (the levels are the top particle centres, both dp / 2 below the surface: within 1e-9),
// the gravel sits on the sand (bottom centre at 0.07 + dp / 2) and the water under the pile flows
// towards the pit (mean velocity_x < 0) but slowly (|v| < 0.1 m/s; the Darcy estimate with the
// mean gradient 2.3 is ~0.02 m/s).
TEST(DamCases, HydraulicHeaveShortenedDrivesWaterUnderThePile) {
  const auto run =
      run_case("hydraulic_heave", {"run.dp=0.005", "run.max_steps=1000",
                                   "run.output_interval=0.002", "soil.damping_duration=0.002"});
  expect_coupled_contract(run);
  EXPECT_GT(run.record.at("interaction").at("evaluations").get<double>(), 900);
  const auto c = validation::check_heave(run.out);
  EXPECT_NEAR(c.head_at_start, 0.22, 1e-9);
  EXPECT_NEAR(c.gravel_top_of_sand, 0.0725, 1e-9);
  EXPECT_NEAR(c.pile_tip, 0.03, 1e-12);
  EXPECT_LT(c.failure_time, 0.0);  // no failure within 20 ms
  const auto series = validation::read_timeseries(run.out);
  const double gap_velocity = series.column("gap_velocity_x").back();
  EXPECT_LT(gap_velocity, 0.0);
  EXPECT_GT(gap_velocity, -0.1);
}

}  // namespace
}  // namespace porosph::testing
