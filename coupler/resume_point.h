// `coupler run --resume DIR`: what a run continues from (docs/checkpoints.md): its directory,
// locked; the run record and step-loop state of its latest checkpoint; and the scene that
// checkpoint keeps (the run's own text, not the scene file as it reads today).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "coupler/checkpoint_state.h"
#include "coupler/run_directory.h"
#include "coupler/run_record.h"
#include "scene/scene.h"

namespace porosph::coupler {

struct ResumePoint {
  std::unique_ptr<RunDirectoryLock> lock;  ///< held for the resumed session's life
  std::string out_dir;                     ///< absolute, normalised
  scene::Scene scene;
  LoopState loop;
  std::uint32_t checkpoint_index = 0;
  double time = 0.0;
  std::uint64_t step = 0;
  /// Keys this binary knows that the run's scene text predates (their defaults apply).
  std::vector<std::string> newer_key_notices;
};

/// Loads the latest checkpoint of run directory `dir` into `record` (status "running", one more
/// resume, a new wall-time segment) and returns the rest. Throws BadInput (run_errors.h) naming
/// the reason: not a run directory, locked by another run, no checkpoint, a checkpoint whose
/// scene or solver states do not match its run.
ResumePoint load_resume_point(const std::string& dir, RunRecord& record);

}  // namespace porosph::coupler
