// A solver child process started by the coupler. The child gets PR_SET_PDEATHSIG (it dies if the
// coupler dies), its own process group, and POROSPH_ENDPOINT in its environment. The destructor
// terminates and reaps it, so no solver outlives the coupler. Start solvers from a thread that
// lives as long as the run (the main thread): PR_SET_PDEATHSIG fires when the *thread* that forked
// exits, not only when the coupler process does.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
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

using SolverProcesses = std::map<std::string, std::unique_ptr<SolverProcess>>;

/// The first of `processes` (by phase) that has exited, waiting up to `grace_seconds` for one to
/// be reaped (a lost connection can be noticed before the exit status); its phase in `phase`, or
/// nullptr if none did.
SolverProcess* exited_solver(SolverProcesses& processes, std::string* phase, double grace_seconds);

/// Waits up to `seconds` for each solver to exit, and terminates (SIGTERM, then SIGKILL after 2 s)
/// any that does not.
void stop_solvers(SolverProcesses& processes, double seconds);

/// "the PHASE solver (pid N) killed by signal 9 (Killed) at step S, t = T s".
std::string dead_solver_message(const std::string& phase, const SolverProcess& process,
                                std::uint64_t step, double time);

/// Finds a solver executable: an absolute/relative path with a slash is used as is; a bare name is
/// looked up next to the running coupler executable first, then on PATH. Returns "" if not found.
std::string find_solver_executable(const std::string& name_or_path);

}  // namespace porosph::coupler
