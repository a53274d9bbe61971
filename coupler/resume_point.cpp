#include "coupler/resume_point.h"

#include <filesystem>
#include <optional>
#include <system_error>

#include "coupler/checkpoint.h"
#include "coupler/run_errors.h"
#include "proto/checkpoint_names.h"
#include "scene/scene_loader.h"

namespace porosph::coupler {

namespace fs = std::filesystem;

ResumePoint load_resume_point(const std::string& dir, RunRecord& record) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    throw BadInput("cannot resume: '" + dir + "' is not a run directory");
  }
  ResumePoint point;
  point.out_dir = fs::absolute(dir).lexically_normal().string();
  try {
    point.lock = std::make_unique<RunDirectoryLock>(point.out_dir);
  } catch (const RunDirectoryError& e) {
    throw BadInput(std::string("cannot resume: ") + e.what());
  }
  std::optional<CheckpointManifest> manifest;
  try {
    manifest = load_latest_checkpoint(point.out_dir, record, point.loop);
  } catch (const std::exception& e) {
    throw BadInput(std::string("cannot resume: ") + e.what());
  }
  if (!manifest) {
    throw BadInput("cannot resume: " + point.out_dir + " has no checkpoint (no " +
                   coupling::checkpoint_dir(point.out_dir) +
                   "/latest.json; checkpoints come from run.checkpoint_interval, "
                   "run.checkpoint_wall_minutes or a SIGINT/SIGTERM past t = 0)");
  }
  try {
    check_checkpoint_scene(point.out_dir, *manifest, scene_hash(record.resolved_toml));
    point.scene = scene::load_scene_text(record.resolved_toml, manifest->coupler_file);
    // The run keeps its own text: this binary may resolve it with keys added since the run began
    // (their defaults, said by the caller), and its checkpoints must name the run's hash.
    point.newer_key_notices = newer_key_notices(record.resolved_toml, point.scene.resolved_toml);
    point.scene.resolved_toml = record.resolved_toml;
  } catch (const scene::SceneError& e) {
    throw BadInput(std::string("cannot resume: bad scene in the checkpoint: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw BadInput(std::string("cannot resume: ") + e.what());
  }
  for (const std::string& phase : point.scene.phases()) {
    if (!manifest->solvers.count(phase)) {
      throw BadInput("cannot resume: the checkpoint has no " + phase + " solver state");
    }
  }
  try {
    rename_former_snapshot_files(point.out_dir);
  } catch (const RunDirectoryError& e) {
    throw BadInput(std::string("cannot resume: ") + e.what());
  }
  record.status = "running";
  record.message.clear();
  record.resumes += 1;
  record.start_segment();  // the wall time goes on from the checkpoint's
  point.checkpoint_index = manifest->index;
  point.time = manifest->time;
  point.step = manifest->step;
  return point;
}

}  // namespace porosph::coupler
