// A constant-head reservoir (fluid_solver/reservoirs.h) through the real coupler and solvers:
// water held at 0.25 m above a fixed porous bed drains through the bed into an outflow zone at its
// bottom; the reservoir's level holds and the mass it adds is in run.json and timeseries.csv.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/cases/case_runner.h"
#include "tools/validation/run_directory.h"

namespace porosph::testing {
namespace {

const char* kReservoirBed = R"([scene]
name = "reservoir_bed"
description = "A reservoir held at 0.25 m drains through a fixed porous bed into an outflow zone"

[run]
end_time = 0.3
output_interval = 0.05
dp = 0.01
dt0 = 1.0e-4

[domain]
min = [-0.05, -0.05]
max = [0.35, 0.45]

[water]
sound_speed = 15.0

[[water.blocks]]
shape = "box"
min = [0.0, 0.0]
max = [0.3, 0.25]

[[water.reservoir]]
min = [0.0, 0.1]
max = [0.3, 0.4]
level = 0.25

[[water.outflow]]
min = [0.0, 0.0]
max = [0.3, 0.02]

[soil]

[[soil.materials]]
name = "bed"
density = 1600.0
porosity = 0.4
young_modulus = 1.0e7
poisson_ratio = 0.3
friction_angle = 30.0
fixed = true
seepage = "darcy_kozeny_carman"
effective_diameter = 0.001
variable_permeability = false

[[soil.blocks]]
shape = "box"
min = [0.0, 0.0]
max = [0.3, 0.1]
material = "bed"

[[walls]]
shape = "container"
min = [0.0, 0.0]
max = [0.3, 0.4]
open_faces = ["y+"]

[[observables]]
name = "reservoir_top"
kind = "max_height"
phase = "water"
direction = [0.0, 1.0]
origin = [0.0, 0.0]
region_min = [0.0, 0.1]
region_max = [0.3, 0.4]
)";

// Measured (0.3 s, 11,466 steps, 6 s): 6.06 kg/m removed at once (the outflow zone's initial
// rows), then 3.0 kg/m seeped through the bed, 2.6 kg/m added by the reservoir (one row of 26
// particles at t ~ 0.2 s); highest particle centre in the reservoir 0.2417 - 0.2500 m (the
// surface, + dp/2, within dp/2 of the level); mass balance 2e-15.
TEST(ReservoirCase, LevelHoldsWhileTheWaterSeepsThroughABed) {
  const CaseRun run = run_scene_text("reservoir_bed", kReservoirBed, {});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& water = run.record.at("phases").at("water");
  const auto& terms = water.at("terms");
  EXPECT_NE(std::find(terms.begin(), terms.end(), "reservoir"), terms.end()) << terms.dump();
  const auto& mass = water.at("mass");
  EXPECT_LT(mass.at("relative_imbalance_max_over_outputs").get<double>(), 1e-9) << mass.dump();
  EXPECT_GT(mass.at("inflow").get<double>(), 1.0) << mass.dump();  // at least one row added
  const auto series = validation::read_timeseries(run.out);
  const auto& top = series.column("reservoir_top");
  const auto& total = series.column("water_mass");
  const auto& in = series.column("water_mass_inflow");
  const auto& out = series.column("water_mass_outflow");
  ASSERT_EQ(top.size(), 7u);
  const double level = 0.25, dp = 0.01;
  for (std::size_t i = 0; i < top.size(); ++i) {
    // Surface = highest centre + dp/2 within dp/2 of the level.
    EXPECT_GE(top[i] + 0.5 * dp, level - 0.5 * dp - 1e-9) << "row " << i;
    EXPECT_LE(top[i] + 0.5 * dp, level + 0.5 * dp + 1e-9) << "row " << i;
    const double expected = total.front() + in[i] - out[i];
    EXPECT_NEAR(total[i], expected, 1e-9 * expected) << "row " << i;
  }
  EXPECT_GT(out.back() - out[1], 1.0) << "water seeped through the bed after the first output";
}

}  // namespace
}  // namespace porosph::testing
