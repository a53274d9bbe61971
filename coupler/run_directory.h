// A run directory belongs to one run (docs/reliability.md): the advisory lock a coupler holds on
// RUN_DIR/.porosph.lock for its whole life, the outputs that mark an earlier run (a fresh run
// refuses them unless --overwrite), and the hash that ties a checkpoint to its scene.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::coupler {

/// The lock file's name in a run directory.
inline constexpr const char* kLockFileName = ".porosph.lock";

/// A problem with the run directory the user named (exit code 2): it cannot be created or
/// written, another run holds it, or it holds an earlier run.
struct RunDirectoryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// flock(2) on RUN_DIR/.porosph.lock, held until destruction (or the process's death: the kernel
/// releases it, so a killed run never blocks the directory). The file holds "PID HOST" of the
/// holder. Not inherited by the solvers (close-on-exec).
class RunDirectoryLock {
 public:
  /// Creates `dir` if needed and takes its lock. Throws RunDirectoryError when the directory
  /// cannot be created or written (with the system's reason), or another process holds the lock
  /// (naming its pid and host).
  explicit RunDirectoryLock(const std::string& dir);
  ~RunDirectoryLock();
  RunDirectoryLock(const RunDirectoryLock&) = delete;
  RunDirectoryLock& operator=(const RunDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

/// Whether some process holds `dir`'s lock, and the "PID HOST" text of its lock file ("" if none).
struct LockProbe {
  bool exists = false;  ///< the lock file exists
  bool held = false;    ///< a process holds the lock now
  std::string owner;    ///< the file's text, e.g. "1234 node7"
};
LockProbe probe_run_directory_lock(const std::string& dir);

/// The outputs of an earlier run present in `dir` (run.json, timeseries.csv, run.xdmf, water.h5,
/// soil.h5, fluid.h5 of older runs, checkpoint/latest.json): the names, empty when there are none.
std::vector<std::string> earlier_run_outputs(const std::string& dir);

/// Before a resume: a run written before the phases had one name (issue 24) keeps the water's
/// snapshots in fluid.h5; renamed to the current name (coupler/phase_slots.h) so the solvers append
/// to it, with a note on stderr. Throws RunDirectoryError when the rename fails.
void rename_former_snapshot_files(const std::string& dir);

/// --overwrite: removes the earlier run's outputs and its checkpoint/ directory. Throws
/// RunDirectoryError naming the file that cannot be removed.
void remove_earlier_run(const std::string& dir);

/// A fresh run's directory: creates and locks `dir`; if it holds an earlier run, removes that
/// run's outputs with `overwrite`, else throws RunDirectoryError (naming them and --overwrite).
std::unique_ptr<RunDirectoryLock> claim_run_directory(const std::string& dir, bool overwrite);

/// This machine's host name ("" if unknown).
std::string host_name();

/// The current time as ISO 8601 UTC with seconds, e.g. "2026-12-03T14:05:09Z".
std::string utc_now();

/// A 64-bit FNV-1a hash of a resolved scene text, as 16 hex digits: what ties run.json and a
/// checkpoint to the scene they were made with.
std::string scene_hash(const std::string& resolved_toml);

}  // namespace porosph::coupler
