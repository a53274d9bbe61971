// Only the effects a scene calls for (issue 7): a one-phase scene starts only its solver, phases
// that never meet exchange nothing, and run.json lists the terms each phase evaluated - a term
// switched off in the scene is absent (the list comes from the same predicates that pick the
// compiled pair loop, so absent means not evaluated).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cases/case_runner.h"
#include "tools/validation/run_directory.h"

namespace porosph::testing {
namespace {

std::vector<std::string> terms_of(const nlohmann::json& record, const std::string& phase) {
  return record.at("phases").at(phase).at("terms").get<std::vector<std::string>>();
}

bool has(const std::vector<std::string>& terms, const std::string& term) {
  return std::find(terms.begin(), terms.end(), term) != terms.end();
}

/// A one-phase run: only `phase` in run.json, no interaction, no snapshot file of the other phase.
void expect_one_phase(const CaseRun& run, const std::string& phase, const std::string& absent_h5) {
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& phases = run.record.at("phases");
  ASSERT_EQ(phases.size(), 1u) << phases.dump();
  EXPECT_TRUE(phases.contains(phase));
  EXPECT_FALSE(run.record.contains("interaction"));
  EXPECT_FALSE(std::filesystem::exists(run.out + "/" + absent_h5));
}

TEST(SceneTerms, WaterOnlySceneStartsOnlyTheWaterSolver) {
  const auto run = run_case("dam_break", {"run.max_steps=5"});
  expect_one_phase(run, "water", "soil.h5");
  const auto terms = terms_of(run.record, "water");
  for (const char* term : {"continuity", "pressure_gradient", "gravity", "morris_viscosity",
                           "artificial_viscosity", "density_diffusion", "walls_no_slip"}) {
    EXPECT_TRUE(has(terms, term)) << term;
  }
  EXPECT_FALSE(has(terms, "inflow"));
  EXPECT_FALSE(has(terms, "periodic"));
}

TEST(SceneTerms, SoilOnlySceneStartsOnlyTheSoilSolver) {
  const auto run = run_case("granular_collapse", {"run.max_steps=5"});
  expect_one_phase(run, "soil", "water.h5");
  const auto terms = terms_of(run.record, "soil");
  EXPECT_TRUE(has(terms, "drucker_prager_return"));
  EXPECT_TRUE(has(terms, "artificial_viscosity"));
  EXPECT_FALSE(has(terms, "artificial_stress"));  // off in the scene
  EXPECT_FALSE(has(terms, "wet_cohesion_loss"));  // no water
}

TEST(SceneTerms, SwitchedOffTermsAreNotEvaluated) {
  const auto water = run_case("dam_break", {"run.max_steps=5", "water.viscosity=0", "water.alpha=0",
                                            "water.density_diffusion=0"});
  ASSERT_EQ(water.result.exit_code, 0) << water.result.output;
  const auto w = terms_of(water.record, "water");
  EXPECT_FALSE(has(w, "morris_viscosity"));
  EXPECT_FALSE(has(w, "artificial_viscosity"));
  EXPECT_FALSE(has(w, "density_diffusion"));
  EXPECT_TRUE(has(w, "pressure_gradient"));
  const auto soil = run_case("granular_collapse", {"run.max_steps=5", "soil.alpha=0", "soil.beta=0",
                                                   "soil.materials.0.artificial_stress=true"});
  ASSERT_EQ(soil.result.exit_code, 0) << soil.result.output;
  const auto s = terms_of(soil.record, "soil");
  EXPECT_FALSE(has(s, "artificial_viscosity"));
  EXPECT_TRUE(has(s, "artificial_stress"));  // switched on by the override
}

// Water in a tank at x in [0, 0.2] m and a dry soil column at x in [1.0, 1.2] m, each with its
// own walls: 0.8 m apart, far beyond the 2h = 0.024 m reach of the interaction.
constexpr const char* kApartScene = R"(
[scene]
name = "apart"
[run]
dimension = 2
end_time = 0.01
output_interval = 0.005
dp = 0.01
h_factor = 1.2
dt0 = 1.0e-4
gravity = [0.0, -9.81]
[domain]
min = [-0.05, -0.05]
max = [1.25, 0.5]
[water]
sound_speed = 20.0
[[water.blocks]]
label = "pool"
shape = "box"
min = [0.0, 0.0]
max = [0.2, 0.2]
[soil]
[[soil.materials]]
name = "sand"
density = 1800.0
young_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 30.0
[[soil.blocks]]
label = "column"
shape = "box"
min = [1.0, 0.0]
max = [1.2, 0.2]
material = "sand"
[[walls]]
label = "tank"
shape = "container"
min = [0.0, 0.0]
max = [0.2, 0.3]
layers = 3
open_faces = ["y+"]
phases = ["water"]
[[walls]]
label = "bin"
shape = "container"
min = [1.0, 0.0]
max = [1.2, 0.3]
layers = 3
open_faces = ["y+"]
phases = ["soil"]
)";

TEST(SceneTerms, PhasesThatNeverMeetExchangeNoParticles) {
  const auto run = run_scene_text("apart", kApartScene, {}, 120);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& record = run.record;
  const std::string& out = run.out;
  ASSERT_EQ(record.at("phases").size(), 2u);
  const auto& interaction = record.at("interaction");
  EXPECT_EQ(interaction.at("evaluations"), 0) << interaction.dump();
  EXPECT_EQ(interaction.at("overlap_max").at("water"), 0);
  EXPECT_EQ(interaction.at("overlap_max").at("soil"), 0);
  EXPECT_EQ(record.at("ledger").at("impulse_magnitude_sum").get<double>(), 0.0);
  const auto series = validation::read_timeseries(out);
  ASSERT_GT(series.column("water_overlap").size(), 2u);
  for (const char* column : {"water_overlap", "soil_overlap", "soil_water_pairs"}) {
    for (double value : series.column(column)) EXPECT_EQ(value, 0.0) << column;
  }
}

}  // namespace
}  // namespace porosph::testing
