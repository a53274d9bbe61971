// "No silent nonsense" with the real coupler and water solver (issue 29, docs/reliability.md):
// a run past Mach 0.3 fails (exit 1) naming the particle, its position and the time; one past
// Mach 0.1 warns once and records the maximum in run.json; `check` and `run` refuse a run too big
// for this machine (exit 2, no run directory) unless given --force-size (check).
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

TEST(NonsenseRun, PastTheMachLimitTheRunFailsNamingTheParticle) {
  const std::string dir = fresh_dir("mach-fail");
  // g = 2000 m/s^2 releases the dam-break column (not in equilibrium, unlike a tank that starts
  // hydrostatic) past 0.1 c0 at step 2 and past 0.3 c0 = 6 m/s at step 3 (measured: Mach 0.217,
  // then 0.302).
  const auto result =
      run_process({bin("coupler"), "run", source("cases/dam_break/scene.toml"), "--out",
                   dir + "/out", "--no-progress", "--set", "run.gravity=[0.0, -2000.0]", "--set",
                   "run.max_steps=300", "--set", "run.dp=0.0028575"},
                  dir + "/log.txt", 120);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  const auto run = read_json(dir + "/out/run.json");
  EXPECT_EQ(run["status"], "failed");
  const std::string message = run["message"];
  for (const char* part : {"the water solver failed at step", ", particle ", "Mach number",
                           "at x = (", "exceeds 0.3", "water.sound_speed"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " in " << message;
  EXPECT_GT(run["mach"]["max"].get<double>(), 0.1);
  EXPECT_EQ(run["mach"]["limit"].get<double>(), 0.3);
}

TEST(NonsenseRun, PastMachZeroPointOneTheRunWarnsOnceAndRecordsTheMaximum) {
  const std::string dir = fresh_dir("mach-warn");
  // The Taylor-Green field at U = 1.5 m/s, c0 = 10 m/s: Mach 0.15 from the start, decaying.
  const auto result =
      run_process({bin("coupler"), "run", source("cases/taylor_green/scene.toml"), "--out",
                   dir + "/out", "--no-progress", "--set", "water.taylor_green_speed=1.5", "--set",
                   "run.max_steps=5", "--set", "run.dp=0.05"},
                  dir + "/log.txt", 120);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::size_t warnings = 0;
  for (auto at = result.output.find("warning: the water reached Mach"); at != std::string::npos;
       at = result.output.find("warning: the water reached Mach", at + 1))
    ++warnings;
  EXPECT_EQ(warnings, 1u) << result.output;
  const auto run = read_json(dir + "/out/run.json");
  EXPECT_GT(run["mach"]["max"].get<double>(), 0.1);
  EXPECT_LT(run["mach"]["max"].get<double>(), 0.16);
}

TEST(NonsenseRun, ARunTooBigForThisMachineIsRefusedBeforeAnySolverStarts) {
  const std::string dir = fresh_dir("too-big");
  const std::string scene = source("cases/dam_break/scene.toml");
  const auto run = run_process({bin("coupler"), "run", scene, "--out", dir + "/out",
                                "--no-progress", "--set", "run.dp=1e-6"},
                               dir + "/run.txt", 60);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--set: key 'run.dp': "), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
  const auto check =
      run_process({bin("coupler"), "check", scene, "--set", "run.dp=1e-6"}, dir + "/check.txt", 60);
  EXPECT_EQ(check.exit_code, 2) << check.output;
  const auto forced =
      run_process({bin("coupler"), "check", scene, "--set", "run.dp=1e-6", "--force-size"},
                  dir + "/forced.txt", 60);
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_NE(forced.output.find("# size: ~6.5"), std::string::npos) << forced.output;
  // A snapshot every step is a scene error (exit 2, the key named) before any size is estimated.
  const auto every_step =
      run_process({bin("coupler"), "check", scene, "--set", "run.output_interval=1e-300"},
                  dir + "/every.txt", 60);
  EXPECT_EQ(every_step.exit_code, 2) << every_step.output;
  EXPECT_NE(every_step.output.find("key 'run.output_interval': is 1e-300 s, far below"),
            std::string::npos)
      << every_step.output;
}

}  // namespace
}  // namespace porosph::testing
