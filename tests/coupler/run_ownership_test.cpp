// A run directory belongs to one run, and its status tells the truth (issue 29,
// docs/reliability.md): `coupler run` as a process with the test dummy (and, for a failure inside
// the step loop, the real water solver). A second run into a busy directory exits 2 naming the
// first one's pid; an earlier run is never silently overwritten; an unwritable --out is found
// before the solvers start; `coupler status` tells running / completed / failed / died; a run.json
// that cannot be written is reported on stderr with exit code 1; a solver failure names the real
// step and time.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "tests/support/dummy_scene.h"
#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

namespace fs = std::filesystem;

// The water-only scene of coupler_run_test.cpp (the dummy ignores its particles).
const std::string kScene = dummy_water_scene("ownership",
                                             "end_time = 0.02\n"
                                             "output_interval = 0.005\n"
                                             "dp = 0.01\n"
                                             "dt0 = 0.001\n"
                                             "solver_timeout = 30.0\n");

std::vector<std::string> dummy_run(const std::string& scene, const std::string& out,
                                   const std::string& dummy_flags = "",
                                   std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {bin("coupler"),
                                   "run",
                                   scene,
                                   "--out",
                                   out,
                                   "--water-solver",
                                   bin("dummy_solver") + " --phase water " + dummy_flags,
                                   "--no-progress"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

CommandResult status_of(const std::string& out, const std::string& log) {
  return run_process({bin("coupler"), "status", out}, log, 10);
}

/// Waits (up to 5 s) for run.json; returns its content (null if it never came).
nlohmann::json wait_for_run_json(const std::string& out) {
  for (int i = 0; i < 250; ++i) {
    if (fs::exists(out + "/run.json")) return read_json(out + "/run.json");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return nullptr;
}

TEST(RunOwnership, ASecondRunIntoABusyDirectoryExitsTwoNamingTheFirst) {
  const std::string dir = fresh_dir("busy");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const std::string out = dir + "/out";
  const pid_t first = start_process(dummy_run(scene, out, "--hang-at-step 2"), dir + "/first.txt");
  const auto record = wait_for_run_json(out);
  ASSERT_FALSE(record.is_null()) << read_text(dir + "/first.txt");
  EXPECT_EQ(record.at("coupler").at("pid").get<pid_t>(), first);
  EXPECT_FALSE(record.at("coupler").at("heartbeat_utc").get<std::string>().empty());

  const auto second = run_process(dummy_run(scene, out), dir + "/second.txt", 30);
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("in use"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("pid " + std::to_string(first)), std::string::npos) << second.output;
  EXPECT_EQ(read_json(out + "/run.json").at("coupler").at("pid").get<pid_t>(), first)
      << "the refused run touched the first one's run.json";
  // Nor does a resume.
  const auto resume =
      run_process({bin("coupler"), "run", "--resume", out, "--no-progress"}, dir + "/resume.txt");
  EXPECT_EQ(resume.exit_code, 2) << resume.output;
  EXPECT_NE(resume.output.find("cannot resume: the run directory '" + out + "' is in use"),
            std::string::npos)
      << resume.output;
  // --overwrite does not take a directory from a live run either.
  const auto forced = run_process(dummy_run(scene, out, "", {"--overwrite"}), dir + "/forced.txt");
  EXPECT_EQ(forced.exit_code, 2) << forced.output;

  const auto running = status_of(out, dir + "/status1.txt");
  EXPECT_EQ(running.exit_code, 3) << running.output;
  EXPECT_EQ(running.output.rfind("running: coupler pid " + std::to_string(first), 0), 0)
      << running.output;

  kill(first, SIGKILL);  // run.json stays "running": status must see through it
  wait_process(first, 5.0);
  EXPECT_EQ(read_json(out + "/run.json").at("status"), "running");
  const auto died = status_of(out, dir + "/status2.txt");
  EXPECT_EQ(died.exit_code, 4) << died.output;
  EXPECT_EQ(died.output.rfind("died: ", 0), 0) << died.output;

  // The dead run's directory is free again, but holds its outputs: refused without --overwrite.
  const auto refused = run_process(dummy_run(scene, out), dir + "/refused.txt");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("--overwrite"), std::string::npos) << refused.output;
  const auto again = run_process(dummy_run(scene, out, "", {"--overwrite"}), dir + "/again.txt");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  const auto completed = status_of(out, dir + "/status3.txt");
  EXPECT_EQ(completed.exit_code, 0) << completed.output;
  EXPECT_EQ(completed.output.rfind("completed: ", 0), 0) << completed.output;
}

TEST(RunOwnership, TwoRunsStartedTogetherOneRunsTheOtherIsRefused) {
  const std::string dir = fresh_dir("together");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const std::string out = dir + "/out";
  const auto argv = dummy_run(scene, out, "", {"--set", "run.end_time=0.5"});
  const pid_t a = start_process(argv, dir + "/a.txt");
  const pid_t b = start_process(argv, dir + "/b.txt");
  const int code_a = wait_process(a, 60), code_b = wait_process(b, 60);
  EXPECT_EQ(std::min(code_a, code_b), 0) << read_text(dir + "/a.txt") << read_text(dir + "/b.txt");
  EXPECT_EQ(std::max(code_a, code_b), 2) << read_text(dir + "/a.txt") << read_text(dir + "/b.txt");
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("status"), "completed");
  EXPECT_EQ(record.at("coupler").at("pid").get<pid_t>(), code_a == 0 ? a : b);
  const std::string csv = read_text(out + "/timeseries.csv");
  EXPECT_EQ(csv.find('\0'), std::string::npos) << "NUL bytes in timeseries.csv";
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 102) << "header + 101 outputs";
}

TEST(RunOwnership, AnEarlierRunIsNeverSilentlyOverwritten) {
  const std::string dir = fresh_dir("earlier");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const std::string out = dir + "/out";
  ASSERT_EQ(run_process(dummy_run(scene, out), dir + "/first.txt").exit_code, 0);
  const std::string first_record = read_text(out + "/run.json");
  const std::string first_csv = read_text(out + "/timeseries.csv");
  const auto other =
      run_process(dummy_run(scene, out, "", {"--set", "run.end_time=0.01"}), dir + "/second.txt");
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("holds an earlier run (run.json, timeseries.csv)"), std::string::npos)
      << other.output;
  EXPECT_NE(other.output.find("--overwrite"), std::string::npos) << other.output;
  EXPECT_EQ(read_text(out + "/run.json"), first_record);
  EXPECT_EQ(read_text(out + "/timeseries.csv"), first_csv);

  const auto replaced = run_process(
      dummy_run(scene, out, "", {"--overwrite", "--set", "run.end_time=0.01"}), dir + "/third.txt");
  ASSERT_EQ(replaced.exit_code, 0) << replaced.output;
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("steps").get<int>(), 10);
  EXPECT_NE(record.at("scene").at("hash"),
            nlohmann::json::parse(first_record).at("scene").at("hash"));
}

TEST(RunOwnership, AnUnwritableOutIsFoundBeforeTheSolversStart) {
  const std::string dir = fresh_dir("unwritable");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  std::string out = dir + "/out";
  fs::create_directories(out);
  chmod(out.c_str(), 0555);
  if (geteuid() == 0) out = "/sys";  // root writes anywhere but in sysfs
  const auto result = run_process(dummy_run(scene, out, "--hang-at-step 0"), dir + "/log.txt", 30);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("cannot write to the run directory '" + out + "'"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("denied"), std::string::npos) << result.output;
  EXPECT_LT(result.seconds, 5.0) << "a hanging solver was started";
  chmod((dir + "/out").c_str(), 0755);
}

TEST(RunStatusTruth, ARunJsonThatCannotBeWrittenIsReportedAndExitsOne) {
  const std::string dir = fresh_dir("no-run-json");
  const std::string scene = write_text(dir + "/scene.toml", kScene);
  const std::string out = dir + "/out";
  fs::create_directories(out + "/run.json.tmp");  // a directory where the temp file goes
  write_text(out + "/run.json.tmp/keep", "");     // ... that cannot be removed either
  const auto result = run_process(dummy_run(scene, out), dir + "/log.txt", 30);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("cannot create " + out + "/run.json.tmp: Is a directory"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(out + "/run.json"));
  const auto status = status_of(out, dir + "/status.txt");
  EXPECT_EQ(status.exit_code, 4) << status.output;
  EXPECT_NE(status.output.find("wrote no run.json"), std::string::npos) << status.output;
}

TEST(RunStatusTruth, NoRunIsNoStatus) {
  const std::string dir = fresh_dir("no-run");
  EXPECT_EQ(status_of(dir, dir + "/../no-run-status.txt").exit_code, 2);
  EXPECT_EQ(status_of(dir + "/missing", dir + "/../no-run-status.txt").exit_code, 2);
}

// A failure inside the solver's step loop (here: its checkpoint cannot be written, as
// OUT/checkpoint is a file) names the step and time it happened at, not "step 0, t = 0 s".
TEST(RunStatusTruth, ASolverFailureNamesTheRealStepAndTime) {
  const std::string dir = fresh_dir("solver-failure-step");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  write_text(out + "/checkpoint", "not a directory");
  const auto result = run_process({bin("coupler"), "run", source("cases/dam_break/scene.toml"),
                                   "--out", out, "--no-progress", "--set", "run.dp=0.004", "--set",
                                   "run.end_time=0.02", "--set", "run.checkpoint_interval=0.005"},
                                  dir + "/log.txt", 120);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  const auto record = read_json(out + "/run.json");
  const std::string message = record.at("message");
  const auto steps = record.at("steps").get<std::uint64_t>();
  EXPECT_GT(steps, 0u);
  EXPECT_NE(message.find("the water solver failed at step " + std::to_string(steps) + ", t = "),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("t = 0 s"), std::string::npos) << message;
  EXPECT_NE(message.find(out + "/checkpoint"), std::string::npos) << "the file" << message;
  EXPECT_GE(record.at("simulated_time").get<double>(), 0.005);
}

}  // namespace
}  // namespace porosph::testing
