// `coupler run` with a dummy water solver and a dummy soil solver (tests/dummies): the coupler
// evaluates the soil-water interaction every step, sends the accelerations back, keeps the
// ledger, and reports it in run.json and timeseries.csv.
// The dummies: 10 water particles on the row y = 2 dp moving at (0.1, 0) m/s, 10 soil particles on
// the row y = 0 moving at (0, -0.05) m/s, x = i dp, all sent as overlap particles every step.
#include <gtest/gtest.h>

#include <map>

#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

const char* kTwoPhaseScene = R"(
[scene]
name = "dummy_interaction"
[run]
end_time = 0.02
output_interval = 0.005
dp = 0.01
dt0 = 0.001
solver_timeout = 5.0
gravity = [0.0, -9.81]
[domain]
min = [-0.5, -0.5]
max = [1.0, 1.0]
[water]
sound_speed = 10.0
viscosity = 1.0e-3
[[water.blocks]]
shape = "box"
min = [0.1, 0.1]
max = [0.2, 0.2]
[soil]
[[soil.materials]]
name = "sand"
density = 2000.0
porosity = 0.4
young_modulus = 1.0e7
poisson_ratio = 0.3
friction_angle = 30.0
seepage = "darcy_kozeny_carman"
effective_diameter = 0.001
[[soil.blocks]]
shape = "box"
min = [0.3, 0.3]
max = [0.4, 0.4]
material = "sand"
)";

/// timeseries.csv as columns by name (plain numbers, unquoted names).
std::map<std::string, std::vector<double>> read_columns(const std::string& path) {
  std::ifstream file(path);
  std::string line, cell;
  std::getline(file, line);
  std::vector<std::string> names;
  for (std::istringstream header(line); std::getline(header, cell, ',');) names.push_back(cell);
  std::map<std::string, std::vector<double>> columns;
  for (const auto& name : names) columns[name];
  while (std::getline(file, line)) {
    std::istringstream row(line);
    for (std::size_t k = 0; k < names.size() && std::getline(row, cell, ','); ++k) {
      columns[names[k]].push_back(std::stod(cell));
    }
  }
  return columns;
}

struct CouplerRunResult {
  CommandResult result;
  nlohmann::json record;
  std::string out;
};

CouplerRunResult run_two_dummies(const std::string& name, const std::string& scene_text,
                                 bool with_soil) {
  CouplerRunResult run;
  const std::string dir = fresh_dir(name);
  run.out = dir + "/out";
  const std::string scene = write_text(dir + "/scene.toml", scene_text);
  std::vector<std::string> argv = {bin("coupler"),
                                   "run",
                                   scene,
                                   "--out",
                                   run.out,
                                   "--no-progress",
                                   "--water-solver",
                                   bin("dummy_solver") + " --phase water --overlap 10"};
  if (with_soil) {
    argv.insert(argv.end(), {"--soil-solver", bin("dummy_solver") + " --phase soil --overlap 10"});
  }
  run.result = run_process(argv, dir + "/log.txt", 60);
  if (std::filesystem::exists(run.out + "/run.json")) run.record = read_json(run.out + "/run.json");
  return run;
}

TEST(CouplerInteractionRun, BooksTheInteractionAndBalancesTheLedger) {
  const CouplerRunResult run = run_two_dummies("interaction", kTwoPhaseScene, true);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& r = run.record;
  EXPECT_EQ(r.at("status"), "completed");
  const int steps = r.at("steps").get<int>();
  EXPECT_NEAR(r.at("simulated_time").get<double>(), 0.02, 1e-12);

  // Pairs at t = 0: water i pairs with soil i (r = 2 dp) and i +- 1 (r = 2.24 dp) but not i +- 2
  // (r = 2.83 dp), with 2h = 2.4 dp: 10 + 2 x 9 = 28. The rows then drift apart.
  const auto& interaction = r.at("interaction");
  EXPECT_EQ(interaction.at("evaluations").get<int>(), steps + 1);  // every step and the last state
  EXPECT_EQ(interaction.at("pairs").at("max").get<int>(), 28);
  EXPECT_GT(interaction.at("pairs").at("min").get<int>(), 0);
  EXPECT_EQ(interaction.at("overlap_max").at("soil").get<int>(), 10);
  // Eq. 21 with the interaction reaches the controller: the drag is largest at t = 0 (largest
  // relative velocity, all 28 pairs), and its limit C_a sqrt(h / |a|max) (~0.9 ms) is below dt0
  // (1 ms), so it is the first step's dt (the controller decreases at once, Fig. 1).
  const double dt_interaction = interaction.at("dt_limit_min").get<double>();
  EXPECT_LT(dt_interaction, 1e-3);
  EXPECT_GE(interaction.at("seconds").get<double>(), 0.0);

  // The ledger: a real impulse, balanced to round-off (the issue: below 1e-10 relative).
  const auto& ledger = r.at("ledger");
  const auto to_soil = ledger.at("impulse_to_soil").get<std::vector<double>>();
  const auto to_water = ledger.at("impulse_to_water").get<std::vector<double>>();
  ASSERT_EQ(to_soil.size(), 2u);
  // v_r = v_water - v_soil = (0.1, 0.05): the water drags the soil along +x and +y.
  EXPECT_GT(to_soil[0], 0.0);
  EXPECT_GT(to_soil[1], 0.0);
  EXPECT_LT(ledger.at("relative_imbalance").get<double>(), 1e-10);
  EXPECT_GT(ledger.at("impulse_magnitude_sum").get<double>(), 0.0);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(to_water[k], -to_soil[k], 1e-10 * to_soil[0]);

  // timeseries.csv: cumulative impulses per axis and the pair count; 0 at t = 0, the ledger's
  // totals at the end.
  auto series = read_columns(run.out + "/timeseries.csv");
  for (const char* column : {"impulse_to_soil_x", "impulse_to_soil_y", "impulse_to_water_x",
                             "impulse_to_water_y", "soil_water_pairs"}) {
    ASSERT_EQ(series[column].size(), 5u) << "timeseries.csv lacks " << column;
  }
  EXPECT_EQ(series["soil_water_pairs"].front(), 28.0);
  EXPECT_NEAR(series["dt"].front(), dt_interaction, 1e-9 * dt_interaction);  // %.10g
  EXPECT_EQ(series["impulse_to_soil_x"].front(), 0.0);
  // %.10g in the file: 10 significant digits.
  EXPECT_NEAR(series["impulse_to_soil_x"].back(), to_soil[0], 1e-9 * to_soil[0]);
  EXPECT_NEAR(series["impulse_to_water_y"].back(), to_water[1], 1e-9 * to_soil[1]);
}

TEST(CouplerInteractionRun, SinglePhaseRunHasNoInteraction) {
  std::string scene = kTwoPhaseScene;
  scene = scene.substr(0, scene.find("[soil]"));
  const CouplerRunResult run = run_two_dummies("no-interaction", scene, false);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_FALSE(run.record.contains("interaction"));
  EXPECT_EQ(run.record.at("ledger").at("relative_imbalance").get<double>(), 0.0);
  const auto series = read_columns(run.out + "/timeseries.csv");
  EXPECT_EQ(series.count("water_mass"), 1u);
  EXPECT_EQ(series.count("soil_water_pairs"), 0u);
  EXPECT_EQ(series.count("impulse_to_water_x"), 0u);
}

}  // namespace
}  // namespace porosph::testing
