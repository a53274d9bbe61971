// SolverProcess: start errors, exit descriptions, environment, process groups and termination.
#include "coupler/solver_process.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace porosph::coupler {
namespace {

constexpr double kWait = 10.0;  // [s] generous: only reached when something is broken

/// A fresh path under /tmp for marker files written by child shells.
std::string temp_path(const std::string& what) {
  static int counter = 0;
  return "/tmp/porosph-test-" + std::to_string(::getpid()) + "-" + what + "-" +
         std::to_string(counter++);
}

/// Waits until `path` exists and is non-empty; returns its first line ("" on timeout).
std::string wait_for_file(const std::string& path) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in(path);
    std::string line;
    if (in && std::getline(in, line) && !line.empty()) return line;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return "";
}

/// True once `pid` no longer exists or is only a zombie awaiting its (new) parent.
bool gone_or_zombie(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string content;
  if (!stat || !std::getline(stat, content)) return true;
  const auto close = content.rfind(')');
  return close != std::string::npos && content.compare(close + 2, 1, "Z") == 0;
}

std::string start_error(const std::string& executable) {
  try {
    SolverProcess process(executable, {}, {});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(SolverProcess, ExitCodeIsDescribed) {
  SolverProcess process("/bin/sh", {"-c", "exit 3"}, {});
  EXPECT_GT(process.pid(), 0);
  ASSERT_TRUE(process.wait_for_exit(kWait));
  EXPECT_FALSE(process.running());
  EXPECT_EQ(process.exit_description(), "exited with code 3");
}

TEST(SolverProcess, BareNamesAreFoundOnPath) {
  SolverProcess process("sh", {"-c", "exit 0"}, {});
  ASSERT_TRUE(process.wait_for_exit(kWait));
  EXPECT_EQ(process.exit_description(), "exited with code 0");
}

TEST(SolverProcess, MissingExecutableThrowsNamingIt) {
  const std::string missing = "/nonexistent/porosph-no-such-solver";
  const std::string error = start_error(missing);
  EXPECT_NE(error.find("cannot start solver '" + missing + "'"), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  const std::string bare = start_error("porosph-no-such-solver-on-path");
  EXPECT_NE(bare.find("'porosph-no-such-solver-on-path'"), std::string::npos) << bare;
}

TEST(SolverProcess, ExecFailureInTheChildIsReportedThroughThePipe) {
  // Executable bits but no known format and no #! line: only execve itself can tell.
  const std::string path = temp_path("not-a-program");
  std::ofstream(path) << "\x01\x02 not a program\n";
  ASSERT_EQ(::chmod(path.c_str(), 0755), 0);
  const std::string error = start_error(path);
  std::remove(path.c_str());
  EXPECT_NE(error.find("cannot start solver '" + path + "'"), std::string::npos) << error;
  EXPECT_NE(error.find("Exec format error"), std::string::npos) << error;
}

TEST(SolverProcess, ExtraEnvironmentReachesTheChild) {
  SolverProcess process("/bin/sh", {"-c", "test \"$POROSPH_ENDPOINT\" = ipc:///tmp/x"},
                        {{"POROSPH_ENDPOINT", "ipc:///tmp/x"}});
  ASSERT_TRUE(process.wait_for_exit(kWait));
  EXPECT_EQ(process.exit_description(), "exited with code 0");  // `test` exits 1 on mismatch
  ::setenv("POROSPH_ENDPOINT", "ipc:///tmp/old", 1);            // replaced, not duplicated
  SolverProcess replaced("/bin/sh", {"-c", "test \"$POROSPH_ENDPOINT\" = ipc:///tmp/new"},
                         {{"POROSPH_ENDPOINT", "ipc:///tmp/new"}});
  ::unsetenv("POROSPH_ENDPOINT");
  ASSERT_TRUE(replaced.wait_for_exit(kWait));
  EXPECT_EQ(replaced.exit_description(), "exited with code 0");
}

TEST(SolverProcess, TerminateKillsAndReaps) {
  SolverProcess process("/bin/sleep", {"100"}, {});
  EXPECT_TRUE(process.running());
  EXPECT_EQ(::getpgid(process.pid()), process.pid());  // its own process group
  process.terminate(kWait);
  EXPECT_FALSE(process.running());
  EXPECT_EQ(process.exit_description(), "killed by signal 15 (Terminated)");
  // Reaped: no zombie left, and it is no longer our child.
  errno = 0;
  EXPECT_EQ(::waitpid(process.pid(), nullptr, WNOHANG), -1);
  EXPECT_EQ(errno, ECHILD);
}

TEST(SolverProcess, ChildIgnoringSigtermIsKilled) {
  const std::string ready = temp_path("ready");
  // The marker is written after the trap is set, so SIGTERM is certainly ignored when we send it.
  SolverProcess process("/bin/sh",
                        {"-c", "trap '' TERM; echo ready > " + ready + "; exec sleep 100"}, {});
  ASSERT_EQ(wait_for_file(ready), "ready");
  std::remove(ready.c_str());
  process.terminate(0.2);
  EXPECT_FALSE(process.running());
  EXPECT_EQ(process.exit_description(), "killed by signal 9 (Killed)");
}

TEST(SolverProcess, TerminateAlsoEndsTheSolversOwnChildren) {
  const std::string child_pid_file = temp_path("grandchild");
  SolverProcess process("/bin/sh", {"-c", "sleep 100 & echo $! > " + child_pid_file + "; wait"},
                        {});
  const std::string line = wait_for_file(child_pid_file);
  std::remove(child_pid_file.c_str());
  ASSERT_FALSE(line.empty());
  const pid_t grandchild = std::stoi(line);
  EXPECT_FALSE(gone_or_zombie(grandchild));
  process.terminate(kWait);
  // The grandchild was re-parented (to init or a subreaper), which reaps it at its own pace.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!gone_or_zombie(grandchild) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(gone_or_zombie(grandchild));
}

TEST(SolverProcess, DestructorTerminates) {
  pid_t pid = 0;
  {
    SolverProcess process("/bin/sleep", {"100"}, {});
    pid = process.pid();
  }
  errno = 0;
  EXPECT_EQ(::waitpid(pid, nullptr, WNOHANG), -1);  // already reaped by the destructor
  EXPECT_EQ(errno, ECHILD);
}

TEST(FindSolverExecutable, LooksNextToTheRunningProgramThenOnPath) {
  // Test executables are built into the same bin/ folder as the dummy solver.
  char expected[PATH_MAX], found[PATH_MAX];
  ASSERT_NE(::realpath(POROSPH_BIN_DIR "/dummy_solver", expected), nullptr);
  const std::string beside = find_solver_executable("dummy_solver");
  ASSERT_NE(::realpath(beside.c_str(), found), nullptr) << beside;
  EXPECT_STREQ(found, expected);

  const std::string sh = find_solver_executable("sh");
  ASSERT_GE(sh.size(), 3u);
  EXPECT_EQ(sh.substr(sh.size() - 3), "/sh");
  EXPECT_EQ(find_solver_executable("/bin/sh"), "/bin/sh");
  EXPECT_EQ(find_solver_executable("porosph-no-such-solver-on-path"), "");
  EXPECT_EQ(find_solver_executable("/nonexistent/solver"), "");
}

}  // namespace
}  // namespace porosph::coupler
