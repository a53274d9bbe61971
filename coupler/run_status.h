// `coupler status DIR` (docs/reliability.md): whether the run in a directory is running, completed,
// failed or died - from run.json and whether a coupler holds the directory's lock.
#pragma once

#include <string>

namespace porosph::coupler {

/// Exit codes of `coupler status`.
enum StatusCode {
  kStatusCompleted = 0,
  kStatusFailed = 1,
  kStatusNoRun = 2,  ///< not a directory, no run in it, or an unreadable run.json
  kStatusRunning = 3,
  kStatusDied = 4,  ///< run.json says running but no coupler holds the lock
};

struct RunStatusReport {
  StatusCode code = kStatusNoRun;
  std::string text;  ///< one line: "running: ...", "completed: ...", "failed: ...", "died: ..."
};

/// The status of the run in `dir`.
RunStatusReport run_status(const std::string& dir);

}  // namespace porosph::coupler
