// Solver child processes: fork + execve with a close-on-exec pipe that reports exec failures.
#include "coupler/solver_process.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace porosph::coupler {
namespace {

bool is_executable_file(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

/// `name` looked up on PATH like execvp does; "" if not found.
std::string search_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > begin ? dirs.substr(begin, end - begin) : ".";
    const std::string candidate = dir + "/" + name;
    if (is_executable_file(candidate)) return candidate;
    begin = end + 1;
  }
  return "";
}

std::string start_error(const std::string& executable, int error_number) {
  return "cannot start solver '" + executable + "': " + std::strerror(error_number);
}

/// The parent's environment with `extra` set (replacing variables of the same name).
std::vector<std::string> child_environment(
    const std::vector<std::pair<std::string, std::string>>& extra) {
  std::vector<std::string> result;
  for (char** entry = environ; entry != nullptr && *entry != nullptr; ++entry) {
    const std::string variable = *entry;
    bool replaced = false;
    for (const auto& [name, value] : extra) {
      replaced = replaced || variable.compare(0, name.size() + 1, name + "=") == 0;
    }
    if (!replaced) result.push_back(variable);
  }
  for (const auto& [name, value] : extra) result.push_back(name + "=" + value);
  return result;
}

std::vector<char*> pointers_to(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (auto& s : strings) result.push_back(s.data());
  result.push_back(nullptr);
  return result;
}

/// Runs in the forked child: only async-signal-safe calls until execve. Never returns.
[[noreturn]] void exec_child(const char* path, char* const* argv, char* const* envp, pid_t parent,
                             int report_fd) {
  ::setpgid(0, 0);  // own process group: terminate() signals the solver and all its children
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(126);  // the coupler died before prctl took effect
  // Signals the coupler ignores or blocks would stay ignored/blocked across exec: reset them.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (int signal_number : {SIGTERM, SIGINT, SIGHUP, SIGPIPE, SIGQUIT}) {
    ::sigaction(signal_number, &default_action, nullptr);
  }
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::execve(path, argv, envp);
  const int error_number = errno;
  ssize_t ignored = ::write(report_fd, &error_number, sizeof error_number);
  (void)ignored;
  ::_exit(127);
}

}  // namespace

SolverProcess::SolverProcess(const std::string& executable, const std::vector<std::string>& args,
                             const std::vector<std::pair<std::string, std::string>>& extra_env) {
  // Resolve and check before forking, so the common errors need no child at all.
  std::string path = executable;
  if (executable.find('/') == std::string::npos) {
    path = search_path(executable);
    if (path.empty()) throw std::runtime_error(start_error(executable, ENOENT));
  } else if (::access(path.c_str(), X_OK) != 0) {
    throw std::runtime_error(start_error(executable, errno));
  }
  // Everything the child needs is built here: after fork it may not allocate.
  std::vector<std::string> argv_strings{executable};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<std::string> env_strings = child_environment(extra_env);
  std::vector<char*> argv = pointers_to(argv_strings);
  std::vector<char*> envp = pointers_to(env_strings);

  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) throw std::runtime_error(start_error(executable, errno));
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0) {
    const int error_number = errno;
    ::close(report[0]);
    ::close(report[1]);
    throw std::runtime_error(start_error(executable, error_number));
  }
  if (child == 0) {
    ::close(report[0]);
    exec_child(path.c_str(), argv.data(), envp.data(), parent, report[1]);
  }
  ::close(report[1]);
  ::setpgid(child, child);  // also from this side, so the group exists before we ever signal it
  pid_ = child;

  // EOF: execve succeeded (the pipe closed on exec). An int: execve's errno.
  int exec_errno = 0;
  ssize_t got;
  do {
    got = ::read(report[0], &exec_errno, sizeof exec_errno);
  } while (got < 0 && errno == EINTR);
  ::close(report[0]);
  if (got == static_cast<ssize_t>(sizeof exec_errno)) {
    while (::waitpid(child, &status_, 0) < 0 && errno == EINTR) {
    }
    exited_ = true;
    throw std::runtime_error(start_error(executable, exec_errno));
  }
}

SolverProcess::~SolverProcess() {
  try {
    terminate();
  } catch (...) {
  }
}

bool SolverProcess::reap_if_exited(bool block) {
  if (exited_ || pid_ <= 0) return false;
  // Look without reaping first: while the leader is a zombie its pid (= the group id) cannot be
  // reused, so the group may still be swept of any children the solver left behind.
  siginfo_t info{};
  const int options = WEXITED | WNOWAIT | (block ? 0 : WNOHANG);
  int rc;
  do {
    rc = ::waitid(P_PID, static_cast<id_t>(pid_), &info, options);
  } while (rc < 0 && errno == EINTR);
  if (rc < 0) {  // ECHILD: reaped elsewhere; nothing more can be learned
    exited_ = true;
    return true;
  }
  if (info.si_pid == 0) return false;  // still running
  ::kill(-pid_, SIGKILL);
  while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
  }
  exited_ = true;
  return true;
}

bool SolverProcess::running() {
  reap_if_exited(false);
  return !exited_;
}

std::string SolverProcess::exit_description() const {
  if (!exited_) return "still running";
  if (WIFEXITED(status_)) return "exited with code " + std::to_string(WEXITSTATUS(status_));
  if (WIFSIGNALED(status_)) {
    const int signal_number = WTERMSIG(status_);
    const char* name = ::strsignal(signal_number);
    return "killed by signal " + std::to_string(signal_number) + " (" +
           (name != nullptr ? name : "unknown") + ")";
  }
  return "ended with wait status " + std::to_string(status_);
}

bool SolverProcess::wait_for_exit(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::microseconds(static_cast<long long>(seconds * 1e6));
  for (;;) {
    if (exited_ || reap_if_exited(false)) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void SolverProcess::terminate(double grace_seconds) {
  if (exited_ || pid_ <= 0) return;
  if (::kill(-pid_, SIGTERM) != 0) ::kill(pid_, SIGTERM);
  if (wait_for_exit(grace_seconds)) return;
  if (::kill(-pid_, SIGKILL) != 0) ::kill(pid_, SIGKILL);
  reap_if_exited(true);
}

std::string find_solver_executable(const std::string& name_or_path) {
  if (name_or_path.empty()) return "";
  if (name_or_path.find('/') != std::string::npos) {
    return is_executable_file(name_or_path) ? name_or_path : "";
  }
  char self[PATH_MAX];
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    std::string own_dir(self, static_cast<std::size_t>(length));
    own_dir.erase(own_dir.find_last_of('/'));
    const std::string beside = own_dir + "/" + name_or_path;
    if (is_executable_file(beside)) return beside;
  }
  return search_path(name_or_path);
}

void stop_solvers(SolverProcesses& processes, double seconds) {
  for (auto& [phase, process] : processes)
    if (!process->wait_for_exit(seconds)) process->terminate(2.0);
}

SolverProcess* exited_solver(SolverProcesses& processes, std::string* phase, double grace_seconds) {
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

std::string dead_solver_message(const std::string& phase, const SolverProcess& process,
                                std::uint64_t step, double time) {
  return "the " + phase + " solver (pid " + std::to_string(process.pid()) + ") " +
         process.exit_description() + " at step " + std::to_string(step) +
         ", t = " + std::to_string(time) + " s";
}

}  // namespace porosph::coupler
