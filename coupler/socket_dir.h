// The private directory of a run's default ipc:// socket: <tmp>/porosph-<pid>-XXXXXX, mode 0700
// (mkdtemp), so that only this user can reach the socket whatever the umask, and its name cannot
// be guessed and taken first. The directory holds a lock file that the coupler keeps locked
// (flock) for as long as it runs; the lock dies with the process, even on SIGKILL, so a later
// coupler removes the directories of dead couplers before it makes its own (sweep_stale_dirs).
#pragma once

#include <string>

namespace porosph::coupler {

class PrivateSocketDir {
 public:
  /// Sweeps `base` (default: $TMPDIR, else /tmp; /tmp when $TMPDIR is too long for a socket
  /// path), then creates the directory and locks it. Throws std::runtime_error.
  explicit PrivateSocketDir(const std::string& base = "");
  ~PrivateSocketDir();  ///< removes the directory and everything in it
  PrivateSocketDir(const PrivateSocketDir&) = delete;
  PrivateSocketDir& operator=(const PrivateSocketDir&) = delete;

  const std::string& path() const { return path_; }
  /// ipc://<path>/coupler.ipc
  std::string endpoint() const;

 private:
  std::string path_;
  int lock_fd_ = -1;
};

/// Removes the porosph-* directories in `base` that this user owns and whose lock file no running
/// coupler holds. Returns how many it removed.
int sweep_stale_socket_dirs(const std::string& base);

}  // namespace porosph::coupler
