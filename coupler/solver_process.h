// A solver child process started by the coupler. The child gets PR_SET_PDEATHSIG (it dies if the
// coupler dies), its own process group, and POROSPH_ENDPOINT in its environment. The destructor
// terminates and reaps it, so no solver outlives the coupler. Start solvers from a thread that
// lives as long as the run (the main thread): PR_SET_PDEATHSIG fires when the *thread* that forked
// exits, not only when the coupler process does.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace porosph::coupler {

class SolverProcess {
 public:
  /// fork + execvp(executable, args...). Throws std::runtime_error if the executable cannot be
  /// found or started (checked before forking, and via a close-on-exec pipe after).
  SolverProcess(const std::string& executable, const std::vector<std::string>& args,
                const std::vector<std::pair<std::string, std::string>>& extra_env);
  ~SolverProcess();
  SolverProcess(const SolverProcess&) = delete;
  SolverProcess& operator=(const SolverProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// Non-blocking check; once it has exited, exit_description() says how.
  bool running();
  /// e.g. "exited with code 3" or "killed by signal 9 (Killed)".
  std::string exit_description() const;
  /// Waits up to `seconds` for a voluntary exit; returns true if it exited.
  bool wait_for_exit(double seconds);
  /// SIGTERM, wait up to `grace_seconds`, then SIGKILL; always reaps.
  void terminate(double grace_seconds = 2.0);

 private:
  /// Reaps the child if it has exited (waiting for that if `block`), after killing whatever is left
  /// in its process group. True if this call saw it exit.
  bool reap_if_exited(bool block);

  pid_t pid_ = -1;
  bool exited_ = false;
  int status_ = 0;
};

/// The solver of `phase` among `processes` that has exited, waiting up to `grace_seconds` for one
/// to be reaped (a lost connection is noticed before the exit status); nullptr if none did.
template <class ProcessMap>
SolverProcess* exited_solver(ProcessMap& processes, std::string* phase, double grace_seconds) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::microseconds(static_cast<long long>(grace_seconds * 1e6));
  for (;;) {
    for (auto& [name, process] : processes) {
      if (!process->running()) {
        *phase = name;
        return process.get();
      }
    }
    if (std::chrono::steady_clock::now() >= deadline) return nullptr;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

/// Finds a solver executable: an absolute/relative path with a slash is used as is; a bare name is
/// looked up next to the running coupler executable first, then on PATH. Returns "" if not found.
std::string find_solver_executable(const std::string& name_or_path);

}  // namespace porosph::coupler
