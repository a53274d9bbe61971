// `coupler run` as a process (issue 29, "Security"): only the solvers of this run take part in it.
// With --attach the coupler prints the token; a solver without it is refused and counted in
// run.json while the run goes on with the right one. A bad --endpoint is bad input (exit 2);
// host names and IPv6 addresses listen.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <regex>

#include "tests/support/dummy_scene.h"
#include "tests/support/process_support.h"

namespace porosph::testing {
namespace {

const std::string kScene = dummy_water_scene("security_run",
                                             "end_time = 0.02\n"
                                             "output_interval = 0.01\n"
                                             "dp = 0.01\n"
                                             "dt0 = 0.001\n"
                                             "solver_timeout = 5.0\n");

std::vector<std::string> run_argv(const std::string& dir, std::vector<std::string> extra,
                                  const std::string& solver = bin("dummy_solver") +
                                                              " --phase water") {
  std::vector<std::string> argv = {
      bin("coupler"), "run",          write_text(dir + "/scene.toml", kScene),
      "--out",        dir + "/out",   "--water-solver",
      solver,         "--no-progress"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

/// Waits until `pattern` matches the log (at most 10 s); returns the match.
std::smatch wait_for_log(const std::string& log, const std::regex& pattern, std::string& text) {
  std::smatch match;
  for (int k = 0; k < 500; ++k) {
    text = read_text(log);
    if (std::regex_search(text, match, pattern)) return match;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ADD_FAILURE() << "no match in " << log << ":\n" << text;
  return match;
}

/// Starts the dummy water solver with this environment (inherited from the test process).
pid_t start_dummy(const std::string& endpoint, const char* token, const std::string& log) {
  ::setenv("POROSPH_ENDPOINT", endpoint.c_str(), 1);
  if (token != nullptr) {
    ::setenv("POROSPH_RUN_TOKEN", token, 1);
  } else {
    ::unsetenv("POROSPH_RUN_TOKEN");
  }
  const pid_t pid =
      start_process({bin("dummy_solver"), "--phase", "water", "--connect-timeout", "5"}, log);
  ::unsetenv("POROSPH_ENDPOINT");
  ::unsetenv("POROSPH_RUN_TOKEN");
  return pid;
}

// The start-up hijack of issue 29, in --attach mode: a stranger connects first and is refused;
// the solver the user started with the printed token runs the scene.
TEST(CouplerRunSecurity, AttachPrintsTheTokenAndRefusesSolversWithoutIt) {
  const std::string dir = fresh_dir("attach-token");
  const std::string log = dir + "/coupler.txt";
  const pid_t coupler =
      start_process(run_argv(dir, {"--attach", "--endpoint", "tcp://127.0.0.1:0"}), log);
  std::string text;
  const std::smatch where = wait_for_log(
      log,
      std::regex(
          R"(POROSPH_ENDPOINT=(tcp://127\.0\.0\.1:\d+) and POROSPH_RUN_TOKEN=([0-9a-f]{64}))"),
      text);
  ASSERT_EQ(where.size(), 3u) << text;
  const std::string endpoint = where[1], token = where[2];

  const int stranger = wait_process(start_dummy(endpoint, nullptr, dir + "/stranger.txt"), 10);
  EXPECT_NE(stranger, 0);
  EXPECT_NE(read_text(dir + "/stranger.txt").find("refused"), std::string::npos)
      << read_text(dir + "/stranger.txt");
  const int guesser =
      wait_process(start_dummy(endpoint, std::string(64, 'a').c_str(), dir + "/guess.txt"), 10);
  EXPECT_NE(guesser, 0);

  const pid_t solver = start_dummy(endpoint, token.c_str(), dir + "/solver.txt");
  EXPECT_EQ(wait_process(coupler, 30), 0) << read_text(log);
  EXPECT_EQ(wait_process(solver, 10), 0) << read_text(dir + "/solver.txt");
  const auto run_json = read_json(dir + "/out/run.json");
  EXPECT_EQ(run_json.at("status"), "completed");
  EXPECT_EQ(run_json.at("phases").at("water").at("pid").get<pid_t>(), solver);
  EXPECT_EQ(run_json.at("transport").at("dropped_messages").get<int>(), 2);
  EXPECT_NE(read_text(log).find("refused a Hello with no or a wrong run token"), std::string::npos)
      << read_text(log);
}

// Issue 29: the endpoint was not treated as the user's input.
TEST(CouplerRunSecurity, BadEndpointIsBadInput) {
  for (const std::string endpoint :
       {"bogus://nowhere", "tcp://no-such-host.invalid:5555", "tcp://localhost:99999"}) {
    const std::string dir = fresh_dir("bad-endpoint");
    const auto result = run_process(run_argv(dir, {"--endpoint", endpoint}), dir + "/log.txt", 30);
    EXPECT_EQ(result.exit_code, 2) << endpoint << "\n" << result.output;
    EXPECT_NE(result.output.find(endpoint), std::string::npos) << result.output;
  }
}

// Issue 29: tcp://localhost:P and tcp://[::1]:P failed with "No such device".
TEST(CouplerRunSecurity, HostNamesAndIpv6Listen) {
  for (const std::string endpoint : {"tcp://localhost:0", "tcp://[::1]:0"}) {
    const std::string dir = fresh_dir("host-endpoint");
    const auto result = run_process(run_argv(dir, {"--endpoint", endpoint}), dir + "/log.txt", 30);
    if (endpoint == "tcp://[::1]:0" && result.exit_code == 2 &&
        result.output.find("not available") != std::string::npos) {
      GTEST_SKIP() << "no IPv6 loopback here";
    }
    EXPECT_EQ(result.exit_code, 0) << endpoint << "\n" << result.output;
    const auto run_json = read_json(dir + "/out/run.json");
    EXPECT_EQ(run_json.at("transport").at("dropped_messages").get<int>(), 0);
  }
}

// Issue 29: the coupler's own solver exited and was ignored while another process, holding the
// token, went on speaking for its phase. Here the started process hands the phase to a child and
// exits 1 during the run: that fails the run at once, though states keep coming.
TEST(CouplerRunSecurity, StartedSolverThatExitsFailsTheRunWhileMessagesFlow) {
  const std::string dir = fresh_dir("started-exits");
  const std::string script =
      write_text(dir + "/solver.sh",
                 "#!/bin/sh\n" + bin("dummy_solver") + " --phase water &\nsleep 0.3\nexit 1\n");
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  const auto result =
      run_process(run_argv(dir, {"--set", "run.end_time=20"}, script), dir + "/log.txt", 60);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("exited with code 1"), std::string::npos) << result.output;
  EXPECT_LT(result.seconds, 15.0) << result.output;
}

// The default socket: in a private directory, gone after the run.
TEST(CouplerRunSecurity, DefaultSocketDirectoryIsPrivateAndRemoved) {
  const std::string dir = fresh_dir("private-dir");
  const std::string tmp = dir + "/tmp";
  std::filesystem::create_directories(tmp);
  ::setenv("TMPDIR", tmp.c_str(), 1);
  const pid_t coupler = start_process(run_argv(dir, {}), dir + "/log.txt");
  ::unsetenv("TMPDIR");
  EXPECT_EQ(wait_process(coupler, 30), 0) << read_text(dir + "/log.txt");
  EXPECT_TRUE(std::filesystem::is_empty(tmp));
}

}  // namespace
}  // namespace porosph::testing
