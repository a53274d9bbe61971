// Checkpoints of a coupled run (docs/checkpoints.md): when to take one, the handshake with the
// solvers, and the files in OUT/checkpoint:
//   <phase>_NNNN.h5     each solver's state after the step the coupler flagged (solver_runtime.h)
//   coupler_NNNN.json   the coupler's state at the same step boundary (checkpoint_state.h)
//   latest.json         the manifest naming the latest complete checkpoint: index, time, step,
//                       files. Written last, via temp file + rename: it only ever names files that
//                       are complete, so a run killed at any moment leaves a usable checkpoint.
// A checkpoint is taken at a step boundary all processes agree on: the coupler flags the command
// that advances to it; each solver advances, writes its file and confirms with its next state; then
// the coupler writes its part (held since it sent the command) and the manifest.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coupler/checkpoint_state.h"
#include "coupler/run_record.h"
#include "proto/coupling_client.h"
#include "scene/scene.h"

namespace porosph::coupler {

/// OUT/checkpoint/latest.json.
struct CheckpointManifest {
  std::uint32_t index = 0;
  double time = 0;
  std::uint64_t step = 0;
  std::string coupler_file;                    ///< path of coupler_NNNN.json
  std::map<std::string, std::string> solvers;  ///< phase -> path of <phase>_NNNN.h5
  std::string scene_hash;  ///< scene_hash() of the run's resolved scene ("" in older manifests)
};

/// The manifest of `out_dir`'s latest checkpoint, or std::nullopt when there is none. Throws
/// std::runtime_error if the manifest exists but cannot be read or names a missing file.
std::optional<CheckpointManifest> read_checkpoint_manifest(const std::string& out_dir);

/// Resume: reads `out_dir`'s latest checkpoint into `record` (coupler_state_json() fields, plus
/// checkpoint_index / time / step) and `loop`; std::nullopt when there is none. Throws
/// std::runtime_error if the checkpoint is unreadable or incomplete.
std::optional<CheckpointManifest> load_latest_checkpoint(const std::string& out_dir,
                                                         RunRecord& record, LoopState& loop);

/// Resume: throws std::runtime_error unless the checkpoint belongs to the run in `out_dir`: the
/// scene of its coupler file (`hash`, scene_hash()) is the one its manifest and OUT/run.json name
/// (where they name one: files of older versions have no hash).
void check_checkpoint_scene(const std::string& out_dir, const CheckpointManifest& manifest,
                            const std::string& hash);

/// Resume: the settings this binary adds when it resolves a run's scene text (`run_text`, the
/// run's resolved scene) again (`resolved_now`): keys introduced since the run began, which take
/// this binary's defaults from the resume on. Each as "table.key = value" (a table of an array of
/// tables by its header, e.g. "[[water.reservoir]] absorbing = false"), in the order of
/// `resolved_now`; empty when the run's text already holds every key.
std::vector<std::string> keys_added_since(const std::string& run_text,
                                          const std::string& resolved_now);

/// The resume's notice for each of keys_added_since(): "KEY is newer than the run's scene; from
/// here on it takes this binary's default, VALUE".
std::vector<std::string> newer_key_notices(const std::string& run_text,
                                           const std::string& resolved_now);

/// The coupler side of checkpointing over one run: schedule (run.checkpoint_interval,
/// run.checkpoint_wall_minutes, or forced on a signal), the pending checkpoint, and its files.
class CheckpointKeeper {
 public:
  /// `last_index` the index of the checkpoint the run resumed from (0: a fresh run).
  CheckpointKeeper(const scene::Scene& scene, const std::string& out_dir,
                   std::vector<std::string> phases, std::uint32_t last_index, double time);

  /// Whether the command advancing from `time` by `dt` must ask for a checkpoint: forced, or the
  /// interval / the wall time has elapsed; never on the final step (`final_step`) unless forced,
  /// never while one is pending or after disable().
  bool due(double time, double dt, bool final_step, bool forced);
  /// The index to put in that command (1, 2, ...); due() returned true.
  std::uint32_t begin();
  /// Holds the coupler's state at the new step boundary (after its time and step advanced) until
  /// the solvers confirm.
  void hold(std::string coupler_state, double time, std::uint64_t step);
  bool pending() const { return pending_; }
  /// With the states of the step that followed: if every solver confirmed, writes
  /// coupler_NNNN.json and latest.json and deletes the previous checkpoint's files; returns an
  /// empty string. Otherwise returns why not (nothing is written). Either way nothing is pending.
  std::string complete(const std::map<std::string, coupling::StepState>& states);
  /// No more checkpoints (a solver does not support them).
  void disable() { enabled_ = false; }
  bool enabled() const { return enabled_; }

  /// The latest complete checkpoint (index 0: none yet).
  std::uint32_t last_index() const { return last_index_; }
  double last_time() const { return last_time_; }
  std::uint64_t last_step() const { return last_step_; }
  const std::string& directory() const { return dir_; }

 private:
  using Clock = std::chrono::steady_clock;
  std::string dir_;
  std::string scene_hash_;
  std::vector<std::string> phases_;
  double interval_ = 0, wall_seconds_ = 0;
  double next_time_ = 0;
  Clock::time_point last_wall_;
  bool enabled_ = true;
  bool pending_ = false;
  std::uint32_t index_ = 0, last_index_ = 0;
  double time_ = 0, last_time_ = 0;
  std::uint64_t step_ = 0, last_step_ = 0;
  std::string state_;
};

}  // namespace porosph::coupler
