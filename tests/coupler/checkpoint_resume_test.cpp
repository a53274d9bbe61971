// Checkpoints and `coupler run --resume` with the real coupler and solvers (docs/checkpoints.md):
// a run killed (SIGKILL) right after a checkpoint, or stopped by SIGTERM, and then resumed ends
// with the same snapshots, time series and ledgers as the same run left alone. OMP_NUM_THREADS=1
// keeps every reduction in one order, so the comparison is to round-off (in practice bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "coupler/run_directory.h"
#include "io/snapshot_reader.h"
#include "tests/coupler/run_comparison.h"
#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

namespace fs = std::filesystem;

/// The water scene: ~1600 steps, checkpoints at t = 0.01, 0.02, 0.03 s; snapshots every 4 ms
/// (the scene's output_interval), time-series rows every 1 ms (run.timeseries_interval).
std::vector<std::string> dam_break_run(const std::string& out) {
  return {bin("coupler"),
          "run",
          source("cases/dam_break/scene.toml"),
          "--out",
          out,
          "--no-progress",
          "--set",
          "run.dp=0.002",
          "--set",
          "run.end_time=0.04",
          "--set",
          "run.checkpoint_interval=0.01",
          "--set",
          "run.timeseries_interval=0.001"};
}

/// The coupled scene: water driven up through a free sand layer on fixed filters (the quick
/// fluidised-bed recipe of docs/coupling.md, shortened: a 5 ms damping stage, then a strong
/// inflow), so particles are born in the inflow zone and removed in the outflow zone across the
/// checkpoint.
std::vector<std::string> fluidized_bed_run(const std::string& out) {
  std::vector<std::string> argv = {bin("coupler"), "run", source("cases/fluidized_bed/scene.toml"),
                                   "--out",        out,   "--no-progress"};
  for (const char* set :
       {"run.dp=0.002", "run.end_time=0.03", "run.output_interval=0.005",
        "run.checkpoint_interval=0.01", "soil.damping_duration=0.005",
        "water.inflow.0.start_time=0.005", "water.inflow.0.ramp_time=0.002",
        "water.inflow.0.flow_rate=5e-3", "soil.materials.0.young_modulus=0.2e6",
        "soil.materials.1.young_modulus=0.2e6", "soil.materials.2.young_modulus=0.2e6"}) {
    argv.insert(argv.end(), {"--set", set});
  }
  return argv;
}

/// The same run, ten times as long after its checkpoint at 0.01 s: a solver killed after it is
/// killed well before the end, however slowly the test process polls on a loaded machine.
std::vector<std::string> long_fluidized_bed_run(const std::string& out) {
  std::vector<std::string> argv = fluidized_bed_run(out);
  argv.insert(argv.end(), {"--set", "run.end_time=0.2"});
  return argv;
}

/// One thread per solver: every sum in one order, so runs agree to the last bit.
void single_threaded() { setenv("OMP_NUM_THREADS", "1", 1); }

/// Runs argv to completion in `dir` (log in dir/log.txt); expects exit 0.
void run_to_completion(const std::vector<std::string>& argv, const std::string& dir) {
  const CommandResult result = run_process(argv, dir + "/log.txt", 120);
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

/// Waits (up to 60 s) for `path` to exist; polls every 2 ms.
bool wait_for_file(const std::string& path) {
  for (int i = 0; i < 30000; ++i) {
    if (fs::exists(path)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

/// The pids of the solver processes named in run.json.
std::vector<pid_t> solver_pids(const std::string& out) {
  std::vector<pid_t> pids;
  for (const auto& [phase, record] : read_json(out + "/run.json").at("phases").items()) {
    pids.push_back(record.at("pid").get<pid_t>());
  }
  return pids;
}

/// The uninterrupted reference run of a scene, made once per test process.
const std::string& reference_run(const std::string& name,
                                 std::vector<std::string> (*scene)(const std::string&)) {
  static std::map<std::string, std::string> done;
  auto it = done.find(name);
  if (it != done.end()) return it->second;
  single_threaded();
  const std::string dir = fresh_dir("reference-" + name);
  run_to_completion(scene(dir + "/out"), dir);
  return done[name] = dir + "/out";
}

/// Rows in timeseries.csv before the latest checkpoint (its row index).
std::size_t rows_before_checkpoint(const std::string& out) {
  const auto manifest = read_json(out + "/checkpoint/latest.json");
  const auto state = read_json(out + "/checkpoint/" + manifest.at("coupler").get<std::string>());
  return state.at("loop").at("row_index").get<std::size_t>();
}

/// Makes the killed run look like one a binary without the key `water.artificial_viscosity_in_soil`
/// wrote: the line is dropped from the checkpoint's resolved scene, and the hashes in latest.json
/// and run.json are those of the shorter text. Returns that hash.
std::string drop_a_defaulted_key(const std::string& out) {
  const std::string latest = out + "/checkpoint/latest.json";
  auto manifest = read_json(latest);
  const std::string coupler_file = out + "/checkpoint/" + manifest.at("coupler").get<std::string>();
  auto state = read_json(coupler_file);
  std::string text = state.at("record").at("resolved_toml").get<std::string>();
  const std::string line = "artificial_viscosity_in_soil = 'drag_limited'\n";
  const std::size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos) << text;
  if (at != std::string::npos) text.erase(at, line.size());
  state["record"]["resolved_toml"] = text;
  manifest["scene_hash"] = coupler::scene_hash(text);
  auto record = read_json(out + "/run.json");
  record["scene"]["hash"] = coupler::scene_hash(text);
  write_text(coupler_file, state.dump(1));
  write_text(latest, manifest.dump(2));
  write_text(out + "/run.json", record.dump(2));
  return coupler::scene_hash(text);
}

/// Starts the run and, once the first checkpoint is complete and a row past it is in
/// timeseries.csv (so the resume must drop output), SIGKILLs the coupler (`victim` empty) or the
/// solver of phase `victim`; checks that everything stops (a killed solver: the coupler exits 1
/// within 5 s naming the phase and the signal, the other solvers go within 5 s), and resumes.
/// `as_older_run`: before resuming, the water's snapshots are renamed to fluid.h5, their name
/// before issue 24, which the resume must rename back. Returns the resumed run's directory.
std::string kill_after_checkpoint_and_resume(const std::string& name,
                                             std::vector<std::string> (*scene)(const std::string&),
                                             const std::string& victim = "",
                                             bool as_older_run = false) {
  single_threaded();
  const std::string dir = fresh_dir("killed-" + name + (victim.empty() ? "" : "-" + victim));
  const std::string out = dir + "/out";
  const pid_t coupler = start_process(scene(out), dir + "/log.txt");
  EXPECT_TRUE(wait_for_file(out + "/checkpoint/latest.json")) << read_text(dir + "/log.txt");
  const std::size_t kept = rows_before_checkpoint(out);
  for (int i = 0; i < 30000 && csv_rows(out + "/timeseries.csv").size() <= kept; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_GT(csv_rows(out + "/timeseries.csv").size(), kept) << "no output past the checkpoint";
  if (victim.empty()) {
    kill(coupler, SIGKILL);
    EXPECT_EQ(wait_process(coupler, 10.0), -1) << "the run ended before the kill";
    for (pid_t solver : solver_pids(out)) EXPECT_TRUE(wait_gone(solver, 10.0));
    EXPECT_NE(read_json(out + "/run.json").at("status"), "completed");
  } else {
    const auto phases = read_json(out + "/run.json").at("phases");
    kill(phases.at(victim).at("pid").get<pid_t>(), SIGKILL);
    EXPECT_EQ(wait_process(coupler, 5.0), 1) << read_text(dir + "/log.txt");
    for (const auto& [phase, record] : phases.items()) {
      EXPECT_TRUE(wait_gone(record.at("pid").get<pid_t>(), 5.0)) << phase << " outlived the run";
    }
    const auto failed = read_json(out + "/run.json");
    EXPECT_EQ(failed.at("status"), "failed");
    const std::string message = failed.at("message");
    EXPECT_NE(message.find(victim), std::string::npos) << message;
    EXPECT_NE(message.find("signal 9"), std::string::npos) << message;
  }
  std::string older_hash;
  if (as_older_run) {
    std::filesystem::rename(out + "/water.h5", out + "/fluid.h5");
    older_hash = drop_a_defaulted_key(out);
  }
  const CommandResult resumed =
      run_process({bin("coupler"), "run", "--resume", out, "--no-progress"}, dir + "/resume.txt");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming"), std::string::npos) << resumed.output;
  if (as_older_run) {
    EXPECT_NE(resumed.output.find("renamed fluid.h5 to water.h5"), std::string::npos)
        << resumed.output;
    EXPECT_FALSE(std::filesystem::exists(out + "/fluid.h5"));
    EXPECT_NE(resumed.output.find("water.artificial_viscosity_in_soil is newer than the run's "
                                  "scene; from here on it takes this binary's default, "
                                  "'drag_limited'"),
              std::string::npos)
        << resumed.output;
    // The checkpoints the resumed run wrote name the run's own scene, so it can be resumed again
    // (before: the hash of this binary's re-resolution, refused as "files of two runs").
    EXPECT_EQ(read_json(out + "/checkpoint/latest.json").at("scene_hash"), older_hash);
    EXPECT_EQ(read_json(out + "/run.json").at("scene").at("hash"), older_hash);
  }
  return out;
}

// The killed run is also made to look like one written before issue 24 (its water snapshots in
// fluid.h5), by a binary without a key this one has: the resume renames the file, appends to it,
// and keeps the run's scene text and hash.
TEST(CheckpointResume, KilledWaterRunResumesToTheSameResult) {
  const std::string& reference = reference_run("dam_break", dam_break_run);
  const std::string out =
      kill_after_checkpoint_and_resume("dam_break", dam_break_run, "", /*as_older_run=*/true);
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("status"), "completed");
  EXPECT_EQ(record.at("resumes"), 1);
  const auto expected = read_json(reference + "/run.json");
  EXPECT_EQ(record.at("steps"), expected.at("steps"));
  EXPECT_EQ(record.at("simulated_time"), expected.at("simulated_time"));
  expect_same_timeseries(reference, out);
  expect_same_snapshots(reference, out, "water.h5",
                        {"position", "velocity", "density", "pressure"});
  EXPECT_NE(read_text(out + "/run.xdmf").find("000010"), std::string::npos);
  // Rows at t = 0, 1, ..., 40 ms; snapshots at 0, 4, ..., 40 ms: independent of each other.
  const auto rows = csv_rows(out + "/timeseries.csv");
  ASSERT_EQ(rows.size(), 41u);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    // The row is the first step boundary at or past r ms (dt ~ 2.5e-5 s).
    EXPECT_GE(rows[r][0], 1e-3 * static_cast<double>(r) - 1e-12) << r;
    EXPECT_LT(rows[r][0], 1e-3 * static_cast<double>(r) + 1e-4) << r;
  }
  EXPECT_EQ(io::SnapshotReader(out + "/water.h5").snapshots().size(), 11u);
}

TEST(CheckpointResume, KilledCoupledRunResumesSoilStateAndLedger) {
  const std::string& reference = reference_run("fluidized_bed", fluidized_bed_run);
  const std::string out = kill_after_checkpoint_and_resume("fluidized_bed", fluidized_bed_run);
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("status"), "completed");
  const auto expected = read_json(reference + "/run.json");
  EXPECT_EQ(record.at("steps"), expected.at("steps"));
  for (const char* key : {"impulse_to_water", "impulse_to_soil"}) {
    for (int k = 0; k < 2; ++k) {
      expect_close(record.at("ledger").at(key).at(k).get<double>(),
                   expected.at("ledger").at(key).at(k).get<double>(), key);
    }
  }
  expect_close(record.at("ledger").at("impulse_magnitude_sum").get<double>(),
               expected.at("ledger").at("impulse_magnitude_sum").get<double>(), "magnitude sum");
  // The external-impulse books: the checkpoint holds their sums, the restored solvers the step
  // before it (docs/coupling.md).
  for (const char* phase : {"water", "soil"}) {
    const auto& books = record.at("ledger").at("external_impulse").at(phase);
    for (const auto& [source, impulse] : books.items()) {
      for (int k = 0; k < 2; ++k) {
        expect_close(impulse.at(k).get<double>(),
                     expected.at("ledger").at("external_impulse").at(phase).at(source).at(k),
                     std::string(phase) + " " + source);
      }
    }
    const auto& balance = record.at("ledger").at("momentum_balance").at(phase);
    EXPECT_LT(balance.at("relative_residual_max_over_outputs").get<double>(), 1e-10) << phase;
  }
  for (const char* phase : {"water", "soil"}) {
    const auto& mass = record.at("phases").at(phase).at("mass");
    for (const char* key : {"initial", "final", "inflow", "outflow"}) {
      expect_close(mass.at(key).get<double>(),
                   expected.at("phases").at(phase).at("mass").at(key).get<double>(),
                   std::string(phase) + " mass " + key);
    }
    EXPECT_EQ(record.at("phases").at(phase).at("particles"),
              expected.at("phases").at(phase).at("particles"));
  }
  EXPECT_GT(record.at("phases").at("water").at("mass").at("inflow").get<double>(), 0.0);
  EXPECT_GT(record.at("phases").at("water").at("particles").at("removed").get<int>(), 0);
  EXPECT_EQ(record.at("interaction").at("evaluations"),
            expected.at("interaction").at("evaluations"));
  expect_same_timeseries(reference, out);
  expect_same_snapshots(reference, out, "water.h5", {"position", "velocity", "density"});
  expect_same_snapshots(reference, out, "soil.h5",
                        {"position", "velocity", "density", "stress", "porosity", "plastic_strain",
                         "displacement", "saturation"});
}

// Issue 24 (hardening): a solver killed with SIGKILL in the middle of a coupled run stops the
// whole run cleanly, and the resume from the last checkpoint ends where the run left alone does.
TEST(CheckpointResume, KilledSolverStopsTheCoupledRunAndTheResumeMatches) {
  const std::string& reference = reference_run("long_fluidized_bed", long_fluidized_bed_run);
  const std::string out =
      kill_after_checkpoint_and_resume("long_fluidized_bed", long_fluidized_bed_run, "water");
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("status"), "completed");
  EXPECT_EQ(record.at("steps"), read_json(reference + "/run.json").at("steps"));
  expect_same_timeseries(reference, out);
  expect_same_snapshots(reference, out, "water.h5", {"position", "velocity", "density"});
  expect_same_snapshots(reference, out, "soil.h5", {"position", "velocity", "stress", "porosity"});
}

TEST(CheckpointResume, SigtermWritesACheckpointAndTheResumeCompletes) {
  const std::string& reference = reference_run("dam_break", dam_break_run);
  single_threaded();
  const std::string dir = fresh_dir("sigterm");
  const std::string out = dir + "/out";
  const pid_t coupler = start_process(dam_break_run(out), dir + "/log.txt");
  // Past the first outputs (t >= 0.004 s), before the scheduled checkpoint at 0.02 s.
  for (int i = 0; i < 30000 && csv_rows(out + "/timeseries.csv").size() < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(coupler, SIGTERM);
  EXPECT_EQ(wait_process(coupler, 20.0), 1) << read_text(dir + "/log.txt");
  for (pid_t solver : solver_pids(out)) EXPECT_TRUE(wait_gone(solver, 5.0));
  const auto failed = read_json(out + "/run.json");
  EXPECT_EQ(failed.at("status"), "failed");
  const std::string message = failed.at("message");
  EXPECT_NE(message.find("interrupted by signal 15; checkpoint at t = "), std::string::npos)
      << message;
  EXPECT_NE(message.find("coupler run --resume " + out), std::string::npos) << message;
  EXPECT_NE(read_text(dir + "/log.txt").find(message), std::string::npos);
  ASSERT_TRUE(fs::exists(out + "/checkpoint/latest.json"));
  const auto manifest = read_json(out + "/checkpoint/latest.json");
  EXPECT_EQ(manifest.at("step"), failed.at("steps"));
  // The solver's time reports up to the checkpoint, which the resumed run's run.json adds to the
  // resumed process's own (ResumedPhaseTimingAddsTheEarlierSegments).
  const auto water_before =
      read_json(out + "/checkpoint/" + manifest.at("coupler").get<std::string>())
          .at("record")
          .at("phases")
          .at("water");
  const double wall_before = water_before.at("wall_seconds").get<double>();
  EXPECT_GT(wall_before, 0.0);
  EXPECT_GE(wall_before, water_before.at("physics_seconds").get<double>());
  EXPECT_GT(water_before.at("communication_seconds").get<double>(), 0.0);

  const CommandResult resumed =
      run_process({bin("coupler"), "run", "--resume", out, "--no-progress"}, dir + "/resume.txt");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  const auto record = read_json(out + "/run.json");
  EXPECT_EQ(record.at("status"), "completed");
  EXPECT_GT(record.at("wall_seconds").at("water").at("total").get<double>(), wall_before);
  expect_same_timeseries(reference, out);
  expect_same_snapshots(reference, out, "water.h5",
                        {"position", "velocity", "density", "pressure"});
}

TEST(CheckpointResume, DirectoryWithoutCheckpointIsRefusedWithExitTwo) {
  const std::string dir = fresh_dir("no-checkpoint");
  fs::create_directories(dir + "/out");
  const CommandResult result =
      run_process({bin("coupler"), "run", "--resume", dir + "/out"}, dir + "/log.txt");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("has no checkpoint"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir + "/out/run.json"));

  const CommandResult missing =
      run_process({bin("coupler"), "run", "--resume", dir + "/nowhere"}, dir + "/log2.txt");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("not a run directory"), std::string::npos) << missing.output;

  const CommandResult with_scene = run_process(
      {bin("coupler"), "run", source("cases/dam_break/scene.toml"), "--resume", dir + "/out"},
      dir + "/log3.txt");
  EXPECT_EQ(with_scene.exit_code, 2) << with_scene.output;
}

}  // namespace
}  // namespace porosph::testing
