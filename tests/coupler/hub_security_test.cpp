// Who can reach the coupler's socket (issue 29, "Security"): endpoints listen only where asked
// (host names, IPv6) and a bad one is refused as such; the default socket lives in a private
// directory whatever the umask, and a SIGKILLed coupler's directory is swept by the next; dropped
// messages are counted and logged rate-limited; the frame limit follows the scene.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "coupler/dropped_messages.h"
#include "coupler/hub_endpoint.h"
#include "coupler/socket_dir.h"
#include "coupler/solver_hub.h"
#include "coupler/solver_launch.h"

namespace porosph::coupler {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("porosph-test-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

mode_t mode_of(const std::string& path) {
  struct stat info {};
  EXPECT_EQ(::lstat(path.c_str(), &info), 0) << path;
  return info.st_mode & 07777;
}

TEST(HubEndpoint, HostNamesResolveAndWildcardsAreFlagged) {
  const BindPlan local = plan_bind("tcp://localhost:5555");
  EXPECT_NE(std::find(local.endpoints.begin(), local.endpoints.end(), "tcp://127.0.0.1:5555"),
            local.endpoints.end());
  EXPECT_FALSE(local.wildcard);
  const BindPlan v6 = plan_bind("tcp://[::1]:0");
  EXPECT_TRUE(v6.ipv6);
  EXPECT_EQ(v6.endpoints, std::vector<std::string>{"tcp://[::1]:0"});
  EXPECT_TRUE(plan_bind("tcp://*:0").wildcard);
  EXPECT_TRUE(plan_bind("tcp://0.0.0.0:7").wildcard);
  EXPECT_FALSE(plan_bind("tcp://127.0.0.1:7").wildcard);
  EXPECT_EQ(plan_bind("ipc:///tmp/x.ipc").ipc_path, "/tmp/x.ipc");
  EXPECT_EQ(connectable("tcp://0.0.0.0:9"), "tcp://127.0.0.1:9");
  EXPECT_EQ(connectable("tcp://[::]:9"), "tcp://[::1]:9");
}

TEST(HubEndpoint, BadEndpointsAreBadEndpoints) {
  for (const std::string endpoint :
       {"bogus://nowhere", "tcp://", "tcp://localhost", "tcp://localhost:99999",
        "tcp://localhost:port", "tcp://no-such-host.invalid:5555", "tcp://::1:5555",
        "tcp://[not-v6]:5555", "ipc://", "inproc://x", "tcp://192.0.2.1:0"}) {
    EXPECT_THROW(SolverHub hub(endpoint), BadEndpoint) << endpoint;  // last: not on this machine
  }
}

/// A client says Hello at `endpoint` and gets its Setup from `hub`.
void expect_handshake(SolverHub& hub, const std::string& endpoint) {
  std::string error;
  std::thread client([&] {
    try {
      coupling::SolverIdentity identity{"water", "t", "1"};
      identity.run_token = hub.run_token();
      coupling::CouplingClient c(endpoint, identity, 10.0);
    } catch (const std::exception& e) {
      error = e.what();
    }
  });
  Incoming in;
  EXPECT_TRUE(hub.receive(in, 10.0)) << endpoint;
  EXPECT_EQ(in.kind, Incoming::Kind::Hello);
  if (in.kind == Incoming::Kind::Hello) hub.send_setup("water", coupling::SetupData{});
  client.join();
  EXPECT_EQ(error, "") << endpoint;
}

// Issue 29: tcp://localhost:P and tcp://[::1]:P failed with "No such device".
TEST(HubEndpoint, LocalhostAndIpv6LoopbackListen) {
  SolverHub local("tcp://localhost:0");
  EXPECT_FALSE(local.listens_everywhere());
  const std::string port = local.connect_endpoint().substr(local.connect_endpoint().rfind(':'));
  expect_handshake(local, "tcp://localhost" + port);
  EXPECT_TRUE(SolverHub("tcp://*:0").listens_everywhere());
  std::unique_ptr<SolverHub> v6;
  try {
    v6 = std::make_unique<SolverHub>("tcp://[::1]:0");
  } catch (const BadEndpoint& e) {
    GTEST_SKIP() << "no IPv6 loopback here: " << e.what();
  }
  EXPECT_EQ(v6->connect_endpoint().rfind("tcp://[::1]:", 0), 0u) << v6->connect_endpoint();
  expect_handshake(*v6, v6->connect_endpoint());
}

// Issue 29: the socket followed the umask (world-writable under umask 000).
TEST(SocketPrivacy, SocketAndDirectoryArePrivateUnderUmaskZero) {
  const std::string base = scratch("umask");
  const mode_t before = ::umask(0);
  {
    PrivateSocketDir dir(base);
    EXPECT_EQ(mode_of(dir.path()), 0700u);
    SolverHub hub(dir.endpoint());
    EXPECT_EQ(mode_of(dir.endpoint().substr(6)) & 0077, 0u);
    const std::string own = base + "/own.ipc";  // a path the user named: the file is private too
    SolverHub named("ipc://" + own);
    EXPECT_EQ(mode_of(own) & 0077, 0u);
  }
  ::umask(before);
  fs::remove_all(base);
}

TEST(SocketDir, DirectoryGoesWithTheCoupler) {
  const std::string base = scratch("dirgone");
  std::string path;
  {
    PrivateSocketDir dir(base);
    path = dir.path();
    EXPECT_EQ(fs::path(path).filename().string().rfind("porosph-" + std::to_string(::getpid()), 0),
              0u);
    EXPECT_TRUE(fs::is_directory(path));
  }
  EXPECT_FALSE(fs::exists(path));
  fs::remove_all(base);
}

// Issue 29: a SIGKILLed coupler left its socket file behind. The next coupler sweeps it; a live
// coupler's directory and directories that are not a coupler's stay.
TEST(SocketDir, SigkilledCouplersDirectoryIsSweptByTheNext) {
  const std::string base = scratch("sweep");
  int report[2];
  ASSERT_EQ(::pipe(report), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    PrivateSocketDir dir(base);
    const std::string path = dir.path() + "\n";
    (void)!::write(report[1], path.data(), path.size());
    ::pause();
    ::_exit(0);
  }
  ::close(report[1]);
  char buffer[512] = {};
  ASSERT_GT(::read(report[0], buffer, sizeof buffer - 1), 0);
  ::close(report[0]);
  const std::string dead = std::string(buffer).substr(0, std::string(buffer).find('\n'));
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ASSERT_TRUE(fs::is_directory(dead));  // left behind

  PrivateSocketDir live(base);
  fs::create_directories(base + "/porosph-not-a-coupler");  // no lock file: not ours to remove
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_EQ(sweep_stale_socket_dirs(base), 0);  // the live one is locked
  EXPECT_TRUE(fs::is_directory(live.path()));
  EXPECT_TRUE(fs::is_directory(base + "/porosph-not-a-coupler"));
  fs::remove_all(base + "/porosph-not-a-coupler");
}

// Issue 29: dropped messages left no trace.
TEST(DroppedMessagesLog, CountsEveryDropAndLogsAFew) {
  std::vector<std::string> lines;
  DroppedMessages dropped([&](const std::string& line) { lines.push_back(line); });
  const auto start = DroppedMessages::Clock::now();
  for (int k = 0; k < 1000; ++k) dropped.add("flood", start + std::chrono::milliseconds(k));
  EXPECT_EQ(dropped.count(), 1000u);
  EXPECT_EQ(lines.size(), DroppedMessages::kLoggedOneByOne);
  dropped.add("late", start + std::chrono::seconds(12));
  ASSERT_EQ(lines.size(), DroppedMessages::kLoggedOneByOne + 1);
  EXPECT_NE(lines.back().find("998 more"), std::string::npos) << lines.back();
  EXPECT_NE(lines.back().find("1001 in all"), std::string::npos) << lines.back();
}

TEST(SolverLaunch, TokenTravelsInTheEnvironmentAndTheFrameLimitFollowsTheScene) {
  const auto env = solver_environment("ipc:///x", "secret", 1);
  EXPECT_NE(std::find(env.begin(), env.end(),
                      std::make_pair(std::string("POROSPH_RUN_TOKEN"), std::string("secret"))),
            env.end());
  scene::Scene scene;
  scene.run.dimension = 2;
  scene.run.dp = 0.01;
  scene.domain.min = {0, 0};
  scene.domain.max = {1, 1};
  const std::size_t small = max_frame_bytes(scene);
  EXPECT_GT(small, std::size_t{2} * 100 * 100 * 100);  // every particle with all its arrays
  EXPECT_LT(small, std::size_t{100} << 20);            // a 100 MB frame is refused
  scene.run.dp = 0.001;
  EXPECT_GT(max_frame_bytes(scene), 50 * small);
  const std::size_t fine = max_frame_bytes(scene);
  scene::Shape wall;  // walls may reach outside the domain
  wall.min = {-10, 0};
  wall.max = {0, 1};
  scene.walls.push_back(wall);
  EXPECT_GT(max_frame_bytes(scene), 5 * fine);
}

}  // namespace
}  // namespace porosph::coupler
