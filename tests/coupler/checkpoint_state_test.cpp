// The coupler's side of checkpoints (coupler/checkpoint.h, checkpoint_state.h): its state reads
// back bit for bit, the schedule, the confirmation handshake, the manifest and the clean-up.
#include "coupler/checkpoint_state.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <thread>

#include "coupler/checkpoint.h"
#include "proto/checkpoint_names.h"
#include "scene/scene_loader.h"
#include "tests/support/dummy_scene.h"

namespace porosph::coupler {
namespace {

namespace fs = std::filesystem;

const std::string kScene = testing::dummy_water_scene("checkpoint_state",
                                                      "end_time = 1.0\n"
                                                      "output_interval = 0.1\n"
                                                      "dp = 0.01\n"
                                                      "dt0 = 0.001\n"
                                                      "checkpoint_interval = 0.25\n");

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("porosph-checkpoint-state-" + std::to_string(getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir / "checkpoint");
  return dir.string();
}

RunRecord sample_record() {
  RunRecord r;
  r.scene_name = "checkpoint_state";
  r.resolved_toml = kScene;
  r.steps = 4321;
  r.time = 0.1 + 0.2;  // not a short decimal
  r.dt_min = 1.0 / 3.0 * 1e-5;
  r.dt_max = 1e-4;
  r.dt_sum = 0.30000000000000004;
  r.coupler_seconds = 2.5;
  r.ledger.impulse_to_water = {1e-300, -std::sqrt(2.0)};
  r.ledger.impulse_to_soil = {-1e-300, std::sqrt(2.0)};
  r.ledger.impulse_magnitude_sum = 3.0;
  r.interaction.active = true;
  r.interaction.evaluations = 17;
  r.interaction.dt_limit_min = std::numeric_limits<double>::infinity();
  r.observables["front"] = std::nan("");
  PhaseRecord& water = r.phases["water"];
  water.phase = "water";
  water.h5_file = "water.h5";
  water.initial.mass = 12.345678901234567;
  water.initial.momentum = {0.1, -0.7};
  water.initial.observables["front"] = 0.05;
  water.last.inflow_mass = 0.125;
  water.snapshots = {{0, 0.0, 100}, {1, 0.1000000000000001, 101}};
  water.reported = {12.5, 9.75, 2.25};  // wall, physics, communication
  water.initial.balance_momentum = {1.0 / 7.0, -0.0};
  water.external.sources = {"gravity", "walls"};
  water.external.impulse = {0.0, -1.0 / 3.0, 1e-300, std::sqrt(3.0)};
  water.external.relative_residual_max = 2.5e-15;
  r.resumes = 2;
  return r;
}

TEST(CouplerCheckpointState, RoundTripsBitForBit) {
  const RunRecord in = sample_record();
  LoopState loop;
  loop.output_index = 4;
  loop.next_output_time = 0.4;
  loop.last_output_time = 0.30000000000000004;
  loop.outputs_pending = true;
  loop.controller_dt = 7.123456789012345e-5;
  loop.row_index = 17;
  loop.next_row_time = 0.17;
  loop.last_row_time = 0.16000000000000003;
  RunRecord out;
  LoopState loop_out;
  restore_coupler_state(coupler_state_json(in, loop), "test", out, loop_out);
  EXPECT_EQ(loop_out.output_index, 4u);
  EXPECT_EQ(loop_out.row_index, 17u);
  EXPECT_EQ(loop_out.next_row_time, loop.next_row_time);
  EXPECT_EQ(loop_out.last_row_time, loop.last_row_time);
  EXPECT_EQ(loop_out.next_output_time, loop.next_output_time);
  EXPECT_EQ(loop_out.last_output_time, loop.last_output_time);
  EXPECT_TRUE(loop_out.outputs_pending);
  EXPECT_EQ(loop_out.controller_dt, loop.controller_dt);
  EXPECT_EQ(out.resolved_toml, in.resolved_toml);
  EXPECT_EQ(out.steps, in.steps);
  EXPECT_EQ(out.time, in.time);
  EXPECT_EQ(out.dt_min, in.dt_min);
  EXPECT_EQ(out.dt_sum, in.dt_sum);
  EXPECT_EQ(out.ledger.impulse_to_water, in.ledger.impulse_to_water);
  EXPECT_EQ(out.ledger.impulse_to_soil, in.ledger.impulse_to_soil);
  EXPECT_EQ(out.ledger.impulse_magnitude_sum, in.ledger.impulse_magnitude_sum);
  EXPECT_EQ(out.interaction.evaluations, 17u);
  EXPECT_TRUE(std::isinf(out.interaction.dt_limit_min));
  EXPECT_TRUE(std::isnan(out.observables.at("front")));
  const PhaseRecord& water = out.phases.at("water");
  EXPECT_EQ(water.initial.mass, in.phases.at("water").initial.mass);
  EXPECT_EQ(water.initial.momentum, in.phases.at("water").initial.momentum);
  EXPECT_EQ(water.initial.observables.at("front"), 0.05);
  EXPECT_EQ(water.last.inflow_mass, 0.125);
  ASSERT_EQ(water.snapshots.size(), 2u);
  EXPECT_EQ(water.snapshots[1].time, 0.1000000000000001);
  EXPECT_EQ(water.snapshots[1].particle_count, 101u);
  EXPECT_EQ(out.resumes, 2u);
  EXPECT_EQ(water.reported.wall_seconds, 12.5);
  EXPECT_EQ(water.reported.physics_seconds, 9.75);
  EXPECT_EQ(water.reported.communication_seconds, 2.25);
  const PhaseRecord& water_in = in.phases.at("water");
  EXPECT_EQ(water.initial.balance_momentum, water_in.initial.balance_momentum);
  EXPECT_EQ(water.external.sources, water_in.external.sources);
  EXPECT_EQ(water.external.impulse, water_in.external.impulse);
  EXPECT_EQ(water.external.relative_residual_max, 2.5e-15);
  EXPECT_TRUE(water.external.booked());
  EXPECT_THROW(restore_coupler_state("{}", "test", out, loop_out), std::runtime_error);
}

// A checkpoint written before run.timeseries_interval (no row fields) resumes with one row per
// snapshot, as such a run wrote them.
TEST(CouplerCheckpointState, OlderStateWithoutRowsTakesTheSnapshotCounters) {
  LoopState loop;
  loop.output_index = 6;
  loop.next_output_time = 0.6;
  loop.last_output_time = 0.5;
  auto state = nlohmann::json::parse(coupler_state_json(sample_record(), loop));
  for (const char* key : {"row_index", "next_row_time", "last_row_time"}) {
    ASSERT_TRUE(state.at("loop").contains(key)) << key;
    state["loop"].erase(key);
  }
  RunRecord out;
  LoopState restored;
  restore_coupler_state(state.dump(), "test", out, restored);
  EXPECT_EQ(restored.row_index, 6u);
  EXPECT_EQ(restored.next_row_time, 0.6);
  EXPECT_EQ(restored.last_row_time, 0.5);
}

// A checkpoint written before the external-impulse books: the sums of the earlier segment are
// unknown, so the resumed run reports no momentum balance for the phase (rather than a wrong one).
TEST(CouplerCheckpointState, OlderStateWithoutBooksReportsNoBalance) {
  auto state = nlohmann::json::parse(coupler_state_json(sample_record(), LoopState{}));
  state["record"]["phases"]["water"].erase("external_impulse");
  RunRecord out;
  LoopState restored;
  restore_coupler_state(state.dump(), "test", out, restored);
  ExternalImpulseRecord& books = out.phases.at("water").external;
  EXPECT_FALSE(books.booked());
  coupling::Diagnostics d;
  d.impulse_sources = {"gravity"};
  d.external_impulse = {0.0, -1.0};
  books.add(d, 2, "water");  // the resumed solver's books change nothing
  EXPECT_FALSE(books.booked());
}

// A resumed run's run.json counts the solver time of all its segments: the reports summed up to
// the checkpoint plus the Goodbye of the resumed process (which knows only its own segment).
TEST(CouplerCheckpointState, ResumedPhaseTimingAddsTheEarlierSegments) {
  RunRecord resumed;
  LoopState loop;
  restore_coupler_state(coupler_state_json(sample_record(), loop), "test", resumed, loop);
  PhaseRecord& water = resumed.phases.at("water");
  water.reported.wall_seconds += 1.0;  // the resumed segment's reports, before its Goodbye
  EXPECT_EQ(phase_timing(water).wall_seconds, 13.5);  // no Goodbye (failed): the reports
  water.timing = {4.0, 3.0, 0.5};                     // Goodbye: this process only
  water.finished = true;
  const coupling::Timing total = phase_timing(water);
  EXPECT_EQ(total.wall_seconds, 12.5 + 4.0);
  EXPECT_EQ(total.physics_seconds, 9.75 + 3.0);
  EXPECT_EQ(total.communication_seconds, 2.25 + 0.5);
}

// The run's wall time goes on from the checkpoint's, and is current whenever it is refreshed (a
// checkpoint holds the time up to its own step, not to the last output).
TEST(CouplerCheckpointState, ResumedRunWallTimeGoesOnFromTheCheckpoint) {
  RunRecord resumed;
  LoopState loop;
  restore_coupler_state(coupler_state_json(sample_record(), loop), "test", resumed, loop);
  resumed.wall_seconds = 100.0;  // as restored from the checkpoint
  resumed.start_segment();
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  resumed.update_wall_seconds();
  EXPECT_GE(resumed.wall_seconds, 100.03);
  EXPECT_LT(resumed.wall_seconds, 110.0);  // 10 s: a loaded machine, far below a second segment
}

TEST(CheckpointKeeper, FollowsTheIntervalAndNeverTheFinalStep) {
  const scene::Scene scene = scene::load_scene_text(kScene, "scene");
  const std::string dir = scratch("schedule");
  CheckpointKeeper keeper(scene, dir, {"water"}, 0, 0.0);
  EXPECT_FALSE(keeper.due(0.0, 0.1, false, false));
  EXPECT_TRUE(keeper.due(0.2, 0.05, false, false));  // reaches 0.25
  EXPECT_FALSE(keeper.due(0.2, 0.05, true, false));  // but that is the last step
  EXPECT_TRUE(keeper.due(0.0, 0.001, true, true));   // forced (a signal)
  fs::remove_all(dir);
}

TEST(CheckpointKeeper, WritesTheManifestOnlyWhenEverySolverConfirmed) {
  const scene::Scene scene = scene::load_scene_text(kScene, "scene");
  const std::string dir = scratch("handshake");
  CheckpointKeeper keeper(scene, dir, {"soil", "water"}, 0, 0.0);
  std::map<std::string, coupling::StepState> states;
  states["soil"].checkpoint_written = 1;
  states["water"].checkpoint_written = 0;  // a solver without checkpoints

  ASSERT_TRUE(keeper.due(0.2, 0.05, false, false));
  EXPECT_EQ(keeper.begin(), 1u);
  keeper.hold("{\"state\": 1}", 0.25, 250);
  EXPECT_TRUE(keeper.pending());
  EXPECT_NE(keeper.complete(states).find("water solver did not confirm"), std::string::npos);
  EXPECT_FALSE(keeper.pending());
  EXPECT_FALSE(read_checkpoint_manifest(dir).has_value());

  for (const char* phase : {"soil", "water"}) {  // the solvers' files, as they would write them
    std::ofstream(coupling::solver_checkpoint_path(dir, phase, 1)) << "x";
    std::ofstream(coupling::solver_checkpoint_path(dir, phase, 2)) << "x";
  }
  states["water"].checkpoint_written = 1;
  keeper.hold("{\"state\": 1}", 0.25, 250);
  EXPECT_EQ(keeper.complete(states), "");
  auto manifest = read_checkpoint_manifest(dir);
  ASSERT_TRUE(manifest.has_value());
  EXPECT_EQ(manifest->index, 1u);
  EXPECT_EQ(manifest->time, 0.25);
  EXPECT_EQ(manifest->step, 250u);
  EXPECT_EQ(manifest->solvers.at("soil"), coupling::solver_checkpoint_path(dir, "soil", 1));

  ASSERT_TRUE(keeper.due(0.45, 0.05, false, false));  // next at 0.5
  EXPECT_EQ(keeper.begin(), 2u);
  keeper.hold("{\"state\": 2}", 0.5, 500);
  states["soil"].checkpoint_written = states["water"].checkpoint_written = 2;
  EXPECT_EQ(keeper.complete(states), "");
  manifest = read_checkpoint_manifest(dir);
  EXPECT_EQ(manifest->index, 2u);
  EXPECT_FALSE(fs::exists(coupling::solver_checkpoint_path(dir, "soil", 1))) << "previous kept";
  EXPECT_FALSE(fs::exists(dir + "/checkpoint/coupler_0001.json"));
  for (const auto& entry : fs::directory_iterator(dir + "/checkpoint")) {
    EXPECT_EQ(entry.path().extension().string().find("tmp"), std::string::npos) << entry.path();
  }
  fs::remove_all(dir);
}

// A resume names the settings a newer binary adds to a run's scene: the keys the run's text lacks,
// by table (and by array-of-tables header), with the default they take; the run's own keys and
// repeated tables are matched line by line, so nothing the run had is reported.
TEST(KeysAddedSince, NamesOnlyTheKeysTheRunsTextLacks) {
  const std::string run =
      "[coupling]\nimplicit_drag = true\n\n[water]\nalpha = 0.05\n\n    [[water.reservoir]]\n"
      "    level = 0.35\n\n    [[water.reservoir]]\n    level = 0.3\n";
  const std::string now =
      "[coupling]\ndrag_at_walls = 'renormalised'\nimplicit_drag = true\n\n[water]\nalpha = 0.05\n"
      "\n    [[water.reservoir]]\n    absorbing = false\n    level = 0.35\n\n"
      "    [[water.reservoir]]\n    absorbing = false\n    level = 0.3\n";
  const std::vector<std::string> added = keys_added_since(run, now);
  ASSERT_EQ(added.size(), 3u);
  EXPECT_EQ(added[0], "coupling.drag_at_walls = 'renormalised'");
  EXPECT_EQ(added[1], "[[water.reservoir]] absorbing = false");
  EXPECT_EQ(added[2], "[[water.reservoir]] absorbing = false");
  EXPECT_TRUE(keys_added_since(now, now).empty());
}

}  // namespace
}  // namespace porosph::coupler
