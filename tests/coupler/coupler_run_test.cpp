// `coupler run` as a process with the test dummy as its water solver: the run-directory contract
// and every fault path of issue 2 (solver error, NaN, crash, hang, killed solver, killed coupler,
// protocol mismatch, bad input). Each fault must stop the run within seconds with exit code 1 and
// run.json status "failed" naming the reason, and leave no process behind.
#include <gtest/gtest.h>

#include "tests/support/dummy_scene.h"
#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

// A valid water-only scene; the dummy ignores its particles but the coupler validates it.
const std::string kScene = dummy_water_scene("dummy_run",
                                             "end_time = 0.02\n"
                                             "output_interval = 0.005\n"
                                             "dp = 0.01\n"
                                             "dt0 = 0.001\n"
                                             "solver_timeout = 2.0\n");

struct CouplerRun {
  CommandResult result;
  nlohmann::json run_json;
  std::string dir;
};

CouplerRun run_with_dummy(const std::string& name, const std::string& dummy_flags,
                          std::vector<std::string> extra = {}) {
  CouplerRun run;
  run.dir = fresh_dir(name);
  const std::string scene = write_text(run.dir + "/scene.toml", kScene);
  std::vector<std::string> argv = {bin("coupler"),
                                   "run",
                                   scene,
                                   "--out",
                                   run.dir + "/out",
                                   "--water-solver",
                                   bin("dummy_solver") + " --phase water " + dummy_flags,
                                   "--no-progress"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  run.result = run_process(argv, run.dir + "/log.txt", 60);
  if (std::filesystem::exists(run.dir + "/out/run.json")) {
    run.run_json = read_json(run.dir + "/out/run.json");
  }
  return run;
}

pid_t solver_pid(const nlohmann::json& run_json) {
  return run_json.at("phases").at("water").at("pid").get<pid_t>();
}

TEST(CouplerRun, CompletesWithTheDummyAndWritesTheRunRecord) {
  const auto run = run_with_dummy("complete", "--phase water");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_EQ(run.run_json.at("status"), "completed");
  EXPECT_EQ(run.run_json.at("steps").get<int>(), 20);  // end_time / dt0, no active limit
  EXPECT_NEAR(run.run_json.at("simulated_time").get<double>(), 0.02, 1e-12);
  EXPECT_EQ(run.run_json.at("phases").at("water").at("finished"), true);
  EXPECT_EQ(run.run_json.at("parameters").at("run").at("dp").get<double>(), 0.01);
  // Outputs at 0, 0.005, ..., 0.02: five rows after the header.
  const std::string csv = read_text(run.dir + "/out/timeseries.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6) << csv;
  EXPECT_TRUE(wait_gone(solver_pid(run.run_json), 5.0));
}

TEST(CouplerRun, SetOverridesReachTheRun) {
  const auto run = run_with_dummy("override", "", {"--set", "run.end_time=0.004"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_EQ(run.run_json.at("steps").get<int>(), 4);
}

void expect_failed(const CouplerRun& run, const std::string& reason_part) {
  EXPECT_EQ(run.result.exit_code, 1) << run.result.output;
  ASSERT_FALSE(run.run_json.is_null()) << "run.json missing; output:\n" << run.result.output;
  EXPECT_EQ(run.run_json.at("status"), "failed");
  const std::string message = run.run_json.at("message");
  EXPECT_NE(message.find(reason_part), std::string::npos) << message;
  EXPECT_NE(run.result.output.find(reason_part), std::string::npos) << run.result.output;
  EXPECT_TRUE(wait_gone(solver_pid(run.run_json), 5.0)) << "solver process left behind";
  // "within seconds": the slowest fault (a hang) waits the 2 s solver_timeout of the scene.
  EXPECT_LT(run.result.seconds, 15.0);
}

TEST(CouplerRunFaults, SolverErrorStopsTheRun) {
  expect_failed(run_with_dummy("error", "--fail-at-step 5"), "failed at step 5");
}

TEST(CouplerRunFaults, NanInASolverNamesProcessStepAndParticle) {
  const auto run = run_with_dummy("nan", "--nan-at-step 3");
  expect_failed(run, "particle 7");
  const std::string message = run.run_json.at("message");
  EXPECT_NE(message.find("water solver"), std::string::npos) << message;
  EXPECT_NE(message.find("step 3"), std::string::npos) << message;
}

TEST(CouplerRunFaults, CrashingSolverIsDetected) {
  expect_failed(run_with_dummy("crash", "--crash-at-step 4"), "signal 6");
}

TEST(CouplerRunFaults, SilentSolverTimesOut) {
  expect_failed(run_with_dummy("hang", "--hang-at-step 4"), "did not answer within 2");
}

// A stalled solver is named, not the healthy one beside it (issue 29): the soil dummy sleeps at
// step 4 while the water dummy keeps waiting. The coupler waits run.solver_timeout (2 s) and the
// solvers wait 2 x that + 5 s for the coupler (solver_side_timeout), so the coupler's timeout
// fires first and the message names the soil solver. Before, both timed out at the same moment
// and the water solver's exit was reported as the failure.
TEST(CouplerRunFaults, StalledSolverIsNamedNotTheHealthyOne) {
  const std::string dir = fresh_dir("stall");
  std::string scene_text = kScene;
  scene_text += R"(
[soil]
[[soil.materials]]
name = "sand"
density = 2000.0
porosity = 0.4
young_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 30.0
[[soil.blocks]]
shape = "box"
min = [0.5, 0.1]
max = [0.6, 0.2]
material = "sand"
)";
  const std::string scene = write_text(dir + "/scene.toml", scene_text);
  const auto result =
      run_process({bin("coupler"), "run", scene, "--out", dir + "/out", "--water-solver",
                   bin("dummy_solver") + " --phase water", "--soil-solver",
                   bin("dummy_solver") + " --phase soil --hang-at-step 4", "--no-progress"},
                  dir + "/log.txt", 60);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  const auto run_json = read_json(dir + "/out/run.json");
  const std::string message = run_json.at("message");
  EXPECT_NE(message.find("the soil solver did not answer"), std::string::npos) << message;
  EXPECT_EQ(message.find("water solver"), std::string::npos) << message;
  EXPECT_LT(result.seconds, 15.0);
}

TEST(CouplerRunFaults, ProtocolVersionMismatchIsRefused) {
  expect_failed(run_with_dummy("version", "--protocol-version 99"), "protocol version mismatch");
}

/// Starts a run whose dummy solver hangs at step 2 (with a long timeout), in the background.
pid_t start_hanging_run(const std::string& dir, const std::string& scene) {
  return start_process({bin("coupler"), "run", scene, "--out", dir + "/out", "--water-solver",
                        bin("dummy_solver") + " --phase water --hang-at-step 2", "--no-progress",
                        "--set", "run.solver_timeout=30"},
                       dir + "/log.txt");
}

/// The solver's pid from run.json, which is written at the first output (t = 0); 0 after 5 s.
pid_t wait_for_solver_pid(const std::string& dir) {
  for (int i = 0; i < 250; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (std::filesystem::exists(dir + "/out/run.json")) {
      return solver_pid(read_json(dir + "/out/run.json"));
    }
  }
  return 0;
}

TEST(CouplerRunFaults, KilledSolverStopsTheRun) {
  const std::string dir = fresh_dir("killed-solver");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const pid_t coupler = start_hanging_run(dir, scene);
  const pid_t solver = wait_for_solver_pid(dir);
  ASSERT_GT(solver, 0);
  kill(solver, SIGKILL);
  EXPECT_EQ(wait_process(coupler, 10.0), 1) << read_text(dir + "/log.txt");
  const auto record = read_json(dir + "/out/run.json");
  EXPECT_EQ(record.at("status"), "failed");
  EXPECT_NE(record.at("message").get<std::string>().find("signal 9"), std::string::npos);
}

TEST(CouplerRunFaults, KilledCouplerTakesItsSolversWithIt) {
  const std::string dir = fresh_dir("killed-coupler");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const pid_t coupler = start_hanging_run(dir, scene);
  const pid_t solver = wait_for_solver_pid(dir);
  ASSERT_GT(solver, 0);
  kill(coupler, SIGKILL);
  wait_process(coupler, 5.0);
  EXPECT_TRUE(wait_gone(solver, 5.0)) << "the solver outlived a killed coupler";
}

// SIGTERM while the solver answers every step (no receive ever times out): the coupler must still
// notice, stop its solver and exit 1 with the reason. The dummy writes no checkpoint when asked for
// the one a signal triggers (docs/checkpoints.md), so the message says there is none.
TEST(CouplerRunFaults, TerminatedCouplerStopsABusyRun) {
  const std::string dir = fresh_dir("terminated-coupler");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const pid_t coupler =
      start_process({bin("coupler"), "run", scene, "--out", dir + "/out", "--water-solver",
                     bin("dummy_solver") + " --phase water", "--no-progress", "--set",
                     "run.end_time=1000", "--set", "run.output_interval=100"},
                    dir + "/log.txt");
  const pid_t solver = wait_for_solver_pid(dir);
  ASSERT_GT(solver, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // well inside the step loop
  kill(coupler, SIGTERM);
  EXPECT_EQ(wait_process(coupler, 10.0), 1) << read_text(dir + "/log.txt");
  EXPECT_TRUE(wait_gone(solver, 5.0)) << "the solver outlived a terminated coupler";
  const auto record = read_json(dir + "/out/run.json");
  EXPECT_EQ(record.at("status"), "failed");
  EXPECT_NE(record.at("message").get<std::string>().find("interrupted by signal 15"),
            std::string::npos)
      << record.at("message");
  EXPECT_NE(record.at("message").get<std::string>().find("no checkpoint"), std::string::npos)
      << record.at("message");
}

// A signal while a solver hangs: the coupler waits for the checkpoint the signal asks for, but a
// second signal stops the run at once (docs/checkpoints.md).
TEST(CouplerRunFaults, SecondSignalStopsAHungRunAtOnce) {
  const std::string dir = fresh_dir("second-signal");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const pid_t coupler = start_hanging_run(dir, scene);
  const pid_t solver = wait_for_solver_pid(dir);
  ASSERT_GT(solver, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the dummy hangs at step 2
  kill(coupler, SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_TRUE(process_exists(coupler)) << "the first signal waits for the checkpoint";
  kill(coupler, SIGINT);
  EXPECT_EQ(wait_process(coupler, 5.0), 1) << read_text(dir + "/log.txt");
  EXPECT_TRUE(wait_gone(solver, 5.0));
  const std::string message = read_json(dir + "/out/run.json").at("message");
  EXPECT_NE(message.find("interrupted by signal 2 a second time"), std::string::npos) << message;
}

TEST(CouplerRunInput, BadSceneExitsTwoNamingFileLineAndKey) {
  const std::string dir = fresh_dir("bad-scene");
  std::string text = kScene;
  text.replace(text.find("dp = 0.01"), 9, "dp = -0.01");
  const std::string scene = write_text(dir + "/scene.toml", text);
  const auto result =
      run_process({bin("coupler"), "run", scene, "--out", dir + "/out"}, dir + "/log.txt");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("scene.toml:7"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("run.dp"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/run.json"));
}

TEST(CouplerRunInput, UnknownSolverExecutableExitsTwo) {
  const std::string dir = fresh_dir("no-solver");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const auto result = run_process({bin("coupler"), "run", scene, "--out", dir + "/out",
                                   "--water-solver", "/nonexistent/solver"},
                                  dir + "/log.txt");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("/nonexistent/solver"), std::string::npos) << result.output;
}

// --fluid-solver, the option's name before the phase had one name (issue 24), still names the
// water solver, with a deprecation message; given with --water-solver it is refused.
TEST(CouplerRunInput, DeprecatedFluidSolverOptionNamesTheWaterSolver) {
  const std::string dir = fresh_dir("fluid-solver-option");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const auto alias = run_process({bin("coupler"), "run", scene, "--out", dir + "/out",
                                  "--fluid-solver", "/nonexistent/solver"},
                                 dir + "/log.txt");
  EXPECT_EQ(alias.exit_code, 2) << alias.output;
  EXPECT_NE(alias.output.find("--fluid-solver is deprecated"), std::string::npos) << alias.output;
  EXPECT_NE(alias.output.find("cannot find the water solver executable '/nonexistent/solver'"),
            std::string::npos)
      << alias.output;
  const auto both = run_process({bin("coupler"), "run", scene, "--out", dir + "/out2",
                                 "--fluid-solver", "/a", "--water-solver", "/b"},
                                dir + "/log2.txt");
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_NE(both.output.find("not both"), std::string::npos) << both.output;
}

TEST(CouplerRunInput, CheckPrintsTheResolvedScene) {
  const std::string dir = fresh_dir("check");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const auto result =
      run_process({bin("coupler"), "check", scene, "--set", "run.cfl=0.1"}, dir + "/log.txt");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("cfl = 0.1"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("h_factor = 1.2"), std::string::npos) << "defaults filled in";
}

}  // namespace
}  // namespace porosph::testing
