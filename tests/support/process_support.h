// Test helpers to run the real executables (coupler, solvers, dummies) as processes.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace porosph::testing {

struct CommandResult {
  int exit_code = -1;  ///< -1 when killed by a signal or timed out
  std::string output;  ///< stdout and stderr together
  double seconds = 0;  ///< wall time
};

/// Path of a built executable (build/bin/NAME).
inline std::string bin(const std::string& name) {
  return std::string(POROSPH_BIN_DIR) + "/" + name;
}
/// Path inside the source tree.
inline std::string source(const std::string& relative) {
  return std::string(POROSPH_SOURCE_DIR) + "/" + relative;
}

/// A fresh empty directory under the system temp dir, unique per test process and name.
inline std::string fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("porosph-test-" + std::to_string(getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

inline std::string read_text(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

inline nlohmann::json read_json(const std::string& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

/// Starts argv with stdout+stderr redirected to `log_path`; returns the pid.
inline pid_t start_process(const std::vector<std::string>& argv, const std::string& log_path) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

/// Waits for `pid` up to `timeout_seconds`; kills it on timeout. Returns the exit code or -1.
inline int wait_process(pid_t pid, double timeout_seconds) {
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        timeout_seconds) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Runs argv to completion (at most `timeout_seconds`) and captures its output.
inline CommandResult run_process(const std::vector<std::string>& argv, const std::string& log_path,
                                 double timeout_seconds = 300) {
  const auto start = std::chrono::steady_clock::now();
  CommandResult result;
  result.exit_code = wait_process(start_process(argv, log_path), timeout_seconds);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.output = read_text(log_path);
  return result;
}

/// True while a process with this pid exists (and is not a zombie of ours).
inline bool process_exists(pid_t pid) {
  if (pid <= 0) return false;
  if (kill(pid, 0) != 0) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string skip, state;
  stat >> skip >> skip >> state;
  return state != "Z";
}

/// Waits up to `seconds` for the process to disappear.
inline bool wait_gone(pid_t pid, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (process_exists(pid)) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

}  // namespace porosph::testing
