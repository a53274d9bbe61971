// The coupled cases (issue 4) through the real coupler, fluid_solver and soil_solver: Darcy and
// Forchheimer columns against their seepage laws, and the fluidised bed (seed paper 4.1), with the
// conservation ledger and the mass balance of in/outflow.
#include <gtest/gtest.h>

#include <algorithm>

#include "io/snapshot_reader.h"
#include "sph/kernels.h"
#include "tests/cases/case_runner.h"
#include "tests/io/xdmf_check.h"
#include "tools/validation/fluidized_bed_check.h"
#include "tools/validation/lattice_registry.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/seepage_checks.h"

namespace porosph::testing {
namespace {

/// The run-directory contract of a run with both phases, and its conservation: the interaction
/// impulses balance (pairwise antisymmetric forces: round-off only, far below 1e-10 of the total
/// impulse exchanged) and each phase's mass is initial + inflow - outflow to round-off.
void expect_coupled_run_directory(const CaseRun& run) {
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& r = run.record;
  EXPECT_EQ(r.at("status"), "completed");
  ASSERT_EQ(r.at("phases").size(), 2u);
  for (const char* phase : {"water", "soil"}) {
    const auto& mass = r.at("phases").at(phase).at("mass");
    EXPECT_LT(mass.at("relative_imbalance").get<double>(), 1e-12) << phase << " " << mass.dump();
    EXPECT_LT(mass.at("relative_imbalance_max_over_outputs").get<double>(), 1e-9) << phase;
  }
  EXPECT_TRUE(r.at("interaction").at("evaluations").get<double>() > 0);
  const auto& ledger = r.at("ledger");
  EXPECT_GT(ledger.at("impulse_magnitude_sum").get<double>(), 0.0);
  EXPECT_LT(ledger.at("relative_imbalance").get<double>(), 1e-10) << ledger.dump();
  const auto series = validation::read_timeseries(run.out);
  for (const char* column : {"water_overlap", "soil_overlap", "soil_water_pairs",
                             "impulse_to_soil_y", "impulse_to_water_y"}) {
    EXPECT_TRUE(series.columns.count(column)) << "timeseries.csv lacks " << column;
  }
  EXPECT_GT(series.column("soil_water_pairs").back(), 0.0);
  // The mass in the domain is the first row's + inflow - outflow at every output (issue 23: to
  // 1e-9; particles carry fixed masses, so only the sums' round-off remains).
  for (const char* phase : {"water", "soil"}) {
    const std::string p = phase;
    const auto& mass = series.column(p + "_mass");
    const auto& in = series.column(p + "_mass_inflow");
    const auto& out = series.column(p + "_mass_outflow");
    for (std::size_t i = 0; i < mass.size(); ++i) {
      const double expected = mass.front() + in[i] - out[i];
      EXPECT_NEAR(mass[i], expected, 1e-9 * expected) << phase << " row " << i;
    }
  }
  EXPECT_TRUE(std::filesystem::exists(run.out + "/water.h5"));
  EXPECT_TRUE(std::filesystem::exists(run.out + "/soil.h5"));
  const auto problems = test::check_xdmf_references(run.out + "/run.xdmf");
  EXPECT_TRUE(problems.empty()) << problems.front();
}

// Gravity-driven water through a fixed Kozeny-Carman block, periodic: unit gradient, so the
// continuum's steady velocity is K = 1 / a (9.69 mm/s). The coupler's drag sums over the soil
// lattice, which the water lattice slides through in registry: the velocity is K / S(o), S the
// kernel's lattice sum at the particles' offset o, and its mean over one lattice period dp / K is
// K times the mean of 1 / S along the flow (tools/validation/lattice_registry.h): +0.112 % for the
// cubic spline at h = 1.2 dp, at every dp. At dp 5 mm (period 0.52 s; 0.6 s, ~17 s) the measured
// mean is that prediction to 3e-7 and its swing +-0.063 % (S from 0.99849 to 0.99976: +-0.064 %).
// Bounds: the mean within 1e-5 of the prediction (the outputs every 5 ms sample the swing; a drag
// off by one part in 1e4 fails), the swing within 0.01 points of S's, and the 2 % of K.
TEST(SeepageCases, DarcyColumnFollowsDarcysLawUpToTheKernelsLatticeSum) {
  const auto run = run_case("darcy_column", {"run.dp=0.005", "run.end_time=0.6"});
  expect_coupled_run_directory(run);
  const auto c = validation::check_darcy_column(run.out);
  EXPECT_EQ(c.seepage, "darcy_kozeny_carman");
  ASSERT_TRUE(c.period_covered);
  EXPECT_NEAR(c.period_mean / c.registry_prediction, 1.0, 1e-5)
      << "mean " << c.period_mean << " predicted " << c.registry_prediction;
  const sph::CubicSpline<2> kernel(1.2 * 0.005);
  double s_min = 1e300, s_max = -1e300;
  for (int k = 0; k < 64; ++k) {
    const double s = validation::lattice_kernel_sum(kernel, 0.005, 1, (k + 0.5) * 0.005 / 64);
    s_min = std::min(s_min, s);
    s_max = std::max(s_max, s);
  }
  EXPECT_NEAR(c.period_swing, 0.5 * (1.0 / s_min - 1.0 / s_max), 1e-4);
  EXPECT_LE(c.rel_error, 0.02) << "simulated " << c.simulated << " expected " << c.expected;
}

// Forchheimer / Den Adel: i = a q + b q^2 = 1 with the quadratic term 62 % of i (the issue asks
// for at least a third). The mean over the last lattice period (23 ms) solves S (a q + b q^2) = 1
// averaged over the lattice sum S as the water slides through the soil: +0.069 % of q, measured to
// 1e-6 (t = 0.13 s, ~12 s). Bounds: 1e-5 of that prediction (a drag off by 1e-4 fails), the
// issue's 2 % of q.
TEST(SeepageCases, ForchheimerColumnFollowsDenAdel) {
  const auto run = run_case_scene("darcy_column", "scene_forchheimer.toml", {});
  expect_coupled_run_directory(run);
  const auto c = validation::check_darcy_column(run.out);
  EXPECT_EQ(c.seepage, "forchheimer_den_adel");
  EXPECT_GE(c.quadratic_share, 1.0 / 3.0);
  ASSERT_TRUE(c.period_covered);
  EXPECT_NEAR(c.period_mean / c.registry_prediction, 1.0, 1e-5)
      << "mean " << c.period_mean << " predicted " << c.registry_prediction;
  EXPECT_LE(c.rel_error, 0.02) << "simulated " << c.simulated << " expected " << c.expected;
}

// The paper's bed at its own resolution for 300 steps (~1 ms; the damping stage shortened to its
// first 0.2 ms so that the drag acts): free sand, fixed filters, free water, inflow and outflow;
// every conservation figure and the contract.
TEST(SeepageCases, FluidizedBedShortened) {
  const auto run =
      run_case("fluidized_bed", {"run.max_steps=300", "run.output_interval=1e-4",
                                 "soil.damping_duration=2e-4", "water.inflow.0.start_time=2e-4"});
  expect_coupled_run_directory(run);
  const auto& soil = run.record.at("phases").at("soil");
  EXPECT_EQ(soil.at("mass").at("final").get<double>(), soil.at("mass").at("initial").get<double>());
}

// The fluidised bed at dp = 2 mm with the flow ramped in 1 s instead of 12 s and the soil 25x
// softer (the equilibrium porosity depends on the drag and the submerged weight, not on E; the
// soil's elastic wave speed then no longer sets dt): ~160 s. Measured at t = 4 s: porosity over
// the last 0.5 s 0.513 (paper 0.508, experiment 0.51), effective stress down to 7 % of the settled
// bed's, onset (effective stress below 10 %) at 0.106 l/s. Bounds: the 0.51 +- 0.02 and
// 0.07-0.12 l/s; the effective stress must have fallen below a third (a bed that carries its weight
// on its grains is not fluidised).
const std::vector<std::string> kQuickBed = {"run.dp=0.002",
                                            "run.dt0=1e-4",
                                            "run.end_time=4.0",
                                            "run.output_interval=0.1",
                                            "water.inflow.0.ramp_time=1.0",
                                            "soil.materials.0.young_modulus=0.2e6",
                                            "soil.materials.1.young_modulus=0.2e6",
                                            "soil.materials.2.young_modulus=0.2e6"};

TEST(SeepageCases, FluidizedBedExpandsToThePaperPorosity) {
  const auto run = run_case("fluidized_bed", kQuickBed, 1500);
  expect_coupled_run_directory(run);
  const auto c = validation::check_fluidized_bed(run.out, 0.5);
  EXPECT_TRUE(c.porosity_in_target) << "steady porosity " << c.steady_porosity;
  EXPECT_TRUE(c.onset_in_target) << "onset at " << c.onset_flow_rate << " m^3/s";
  EXPECT_LT(c.stress_ratio, 1.0 / 3.0);
  EXPECT_GT(c.bed_height_final, c.bed_height_initial + 0.001);  // the bed has risen
  // ... and (nearly) stopped: measured 0.15 mm/s over the last 0.5 s, against 1.7 mm/s with the
  // permeability frozen (next test); the bound lies between the two with a margin of 2x each way.
  EXPECT_LT(std::abs(c.bed_rise_rate), 0.4e-3) << "rising at " << c.bed_rise_rate << " m/s";
  // The water's mass flux through the bed, sum m v / V, is the inflow's rho U: measured 0.9952
  // over 3.5-4 s on the validation run of this recipe (docs/validation.md); the row-by-row inflow
  // makes a 0.5 s window swing by ~1 %, and a lost row of the inflow zone would take 7 % off it.
  EXPECT_NEAR(c.mass_flux_density_ratio, 1.0, 0.025);
  // The particles' volumes fill the bed: measured 0.9968 (0.999-1.001 over 6-12 s; with the
  // Shepard filter every 30 steps they crowded to 1.014 and moved at 0.985 Q/A).
  EXPECT_NEAR(c.volume_fill, 1.0, 0.03);
  // Issue 23: the water inside the bed moves at the superficial velocity Q / A within 1 %. The
  // water rises as lattice rows, one every dp / U, and their handover at the inflow and removal at
  // the outflow send pulses through the bed, so the check averages the observable
  // bed_water_velocity over a whole period: measured 1.0022 (0.9870 with the Shepard filter,
  // which this bound rejects).
  ASSERT_TRUE(c.velocity_over_periods);
  EXPECT_NEAR(c.velocity_ratio, 1.0, 0.01);
  // The 0.2 % above Q / A is the water's compressibility: the zone hands over mass at
  // m / dp^2 U, and the bed's water is less compressed than the zone's. The mass flux through the
  // bed against the zone's: measured 1.00022 (1.00040 at dp 4 mm); the bound is 2.5 times the
  // coarse level's. A bound on v / U alone could not tell 0.2 % of the flow lost from that offset.
  EXPECT_NEAR(c.period_mass_flux_ratio, 1.0, 1e-3);
}

// The paper's argument for eq. 20: with the permeability frozen at n0 the drag on the expanding
// bed never drops back to its submerged weight, so the bed does not settle but rises as a plug
// (its porosity stays near n0). Measured: 1.7 mm/s over the last 0.5 s, porosity 0.462.
TEST(SeepageCases, FluidizedBedWithFrozenPermeabilityDoesNotSettle) {
  auto overrides = kQuickBed;
  overrides.push_back("soil.materials.2.variable_permeability=false");
  const auto run = run_case("fluidized_bed", overrides, 1500);
  expect_coupled_run_directory(run);
  const auto c = validation::check_fluidized_bed(run.out, 0.5);
  EXPECT_GT(c.bed_rise_rate, 0.8e-3) << "rising at " << c.bed_rise_rate << " m/s";
  EXPECT_LT(c.steady_porosity, 0.49);
}

}  // namespace
}  // namespace porosph::testing
