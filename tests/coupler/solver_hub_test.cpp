// SolverHub against real dummy_solver processes (tests/dummies): the handshake, the lock-step
// exchange, and each injected failure as the coupler will see it.
#include "coupler/solver_hub.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

#include "coupler/solver_process.h"
#include "proto/state_delta.h"

namespace porosph::coupler {
namespace {

constexpr double kWait = 10.0;  // [s] generous: only reached when something is broken
constexpr double kDt = 1e-3;    // the dt the test coupler hands out
constexpr double kDp = 0.01;    // particle spacing in the Setup; the dummy lays particles on it

std::string unique_ipc_endpoint() {
  static int counter = 0;
  return "ipc:///tmp/porosph-test-" + std::to_string(::getpid()) + "-dummy-" +
         std::to_string(counter++);
}

/// A hub and one dummy solver started against it (endpoint passed through POROSPH_ENDPOINT).
struct DummyRun {
  SolverHub hub;
  SolverProcess process;  // after the hub: terminated before the hub closes

  DummyRun(const std::string& phase, const std::vector<std::string>& extra_args)
      : hub(unique_ipc_endpoint()),
        process(POROSPH_BIN_DIR "/dummy_solver", arguments(phase, extra_args),
                {{"POROSPH_ENDPOINT", hub.connect_endpoint()},
                 {"POROSPH_RUN_TOKEN", hub.run_token()}}) {}

  static std::vector<std::string> arguments(const std::string& phase,
                                            const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--phase", phase, "--connect-timeout", "10"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }

  /// Receives the Hello and answers with a Setup; returns the Hello.
  Incoming handshake() {
    Incoming hello;
    EXPECT_TRUE(hub.receive(hello, kWait));
    EXPECT_EQ(hello.kind, Incoming::Kind::Hello);
    if (hello.kind == Incoming::Kind::Hello &&
        hello.protocol_version == coupling::kProtocolVersion) {
      coupling::SetupData setup;
      setup.phase = hello.phase;
      setup.dimension = 2;
      setup.dp = kDp;
      setup.h = 1.3 * kDp;
      setup.dt0 = kDt;
      setup.end_time = 1;
      setup.timeout_seconds = kWait;
      hub.send_setup(hello.phase, setup);
    }
    return hello;
  }

  /// Answers every state with dt = kDt until the dummy stops talking and has exited.
  /// Returns the steps seen and the last non-state message (kind Error if any).
  std::vector<std::uint64_t> answer_until_exit(const std::string& phase, Incoming& last) {
    std::vector<std::uint64_t> steps;
    Incoming in;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
      if (hub.receive(in, 0.1)) {
        if (in.kind != Incoming::Kind::State) {
          last = in;
          continue;
        }
        steps.push_back(in.state.step);
        coupling::StepCommand command;
        command.step = in.state.step;
        command.dt = kDt;
        hub.send_command(phase, command);
      } else if (!process.running()) {
        break;
      }
    }
    return steps;
  }
};

TEST(SolverHubWithDummy, HandshakeThreeStepsStopAndGoodbye) {
  DummyRun run("soil", {"--overlap", "4"});
  const Incoming hello = run.handshake();
  EXPECT_EQ(hello.phase, "soil");
  EXPECT_EQ(hello.solver_name, "porosph-dummy");
  EXPECT_EQ(hello.pid, run.process.pid());

  // The dummy moves soil particles at (0, -0.05) m/s and adds the interaction acceleration a
  // before moving (v += a dt; x += v dt). With a = (2, 0) on the overlap particles, after k steps:
  // v_x = k a dt, x = x0 + a dt^2 k (k + 1) / 2, y = -0.05 k dt. The few additions of O(1e-3)
  // numbers round off at ~1e-18, so 1e-12 is a loose but still exact-enough bound.
  constexpr double kA = 2.0, kTolerance = 1e-12;
  constexpr std::uint64_t kSteps = 3;
  // The client leaves out what the hub already has (state deltas): from the second state on the
  // set is the same, so ids, masses and materials stay home; the coupler completes each state.
  Incoming in;
  coupling::StepState s;
  for (std::uint64_t k = 0; k <= kSteps; ++k) {
    ASSERT_TRUE(run.hub.receive(in, kWait));
    ASSERT_EQ(in.kind, Incoming::Kind::State) << in.error_message;
    EXPECT_EQ(in.state.delta.same_set, k > 0);
    EXPECT_EQ(in.state.overlap_id.empty(), k > 0);
    coupling::apply_state_delta(s, in.state, 2, "soil");
    const double kd = static_cast<double>(k);
    EXPECT_EQ(s.step, k);
    EXPECT_NEAR(s.time, kd * kDt, kTolerance);
    EXPECT_EQ(s.dt_limit, 10 * kDt);  // the dummy's default: never the active limit
    ASSERT_EQ(s.overlap_id, (std::vector<std::int64_t>{0, 1, 2, 3}));
    ASSERT_EQ(s.overlap_position.size(), 8u);
    ASSERT_EQ(s.overlap_velocity.size(), 8u);
    EXPECT_EQ(s.overlap_porosity, std::vector<double>(4, 0.4));
    EXPECT_EQ(s.overlap_material, std::vector<std::int32_t>(4, 0));
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(s.overlap_position[2 * i], i * kDp + kA * kDt * kDt * kd * (kd + 1) / 2,
                  kTolerance);
      EXPECT_NEAR(s.overlap_position[2 * i + 1], -0.05 * kd * kDt, kTolerance);
      EXPECT_NEAR(s.overlap_velocity[2 * i], kd * kA * kDt, kTolerance);
      EXPECT_NEAR(s.overlap_velocity[2 * i + 1], -0.05, kTolerance);
      EXPECT_EQ(s.overlap_density[i], 2000.0);
      EXPECT_NEAR(s.overlap_mass[i], 2000.0 * kDp * kDp, kTolerance);
    }
    EXPECT_EQ(s.diagnostics.particle_count, 10u);
    EXPECT_NEAR(s.diagnostics.mass, 10 * 2000.0 * kDp * kDp, kTolerance);
    coupling::StepCommand command;
    command.step = k;
    command.time = s.time;
    command.dt = kDt;
    command.stop = k == kSteps;
    command.interaction_acceleration.assign(8, 0.0);
    for (int i = 0; i < 4; ++i) command.interaction_acceleration[2 * i] = kA;
    run.hub.send_command("soil", command);
  }
  ASSERT_TRUE(run.hub.receive(in, kWait));
  EXPECT_EQ(in.kind, Incoming::Kind::Goodbye);
  EXPECT_EQ(in.phase, "soil");
  ASSERT_TRUE(run.process.wait_for_exit(kWait));
  EXPECT_EQ(run.process.exit_description(), "exited with code 0");
}

TEST(SolverHubWithDummy, CrashIsSeenAsSignal6AndTheDeadPeerRefusesMessages) {
  DummyRun run("water", {"--crash-at-step", "2"});
  run.handshake();
  Incoming last;
  const std::vector<std::uint64_t> steps = run.answer_until_exit("water", last);
  EXPECT_EQ(steps, (std::vector<std::uint64_t>{0, 1}));  // crashed instead of sending step 2
  EXPECT_FALSE(run.process.running());
  EXPECT_NE(run.process.exit_description().find("killed by signal 6"), std::string::npos)
      << run.process.exit_description();

  // ROUTER_MANDATORY: once ZeroMQ has noticed the disconnect, sending fails instead of vanishing.
  bool refused = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!refused && std::chrono::steady_clock::now() < deadline) {
    try {
      run.hub.send_command("water", coupling::StepCommand{});
      Incoming ignored;
      run.hub.receive(ignored, 0.01);  // let the I/O thread process the disconnect
    } catch (const std::runtime_error& e) {
      refused = true;
      EXPECT_NE(std::string(e.what()).find("water"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(refused);
}

TEST(SolverHubWithDummy, NanIsReportedWithParticleId) {
  DummyRun run("water", {"--nan-at-step", "1"});
  run.handshake();
  Incoming last;
  const std::vector<std::uint64_t> steps = run.answer_until_exit("water", last);
  EXPECT_EQ(steps, std::vector<std::uint64_t>{0});
  ASSERT_EQ(last.kind, Incoming::Kind::Error);
  EXPECT_EQ(last.phase, "water");
  EXPECT_EQ(last.error_message, "non-finite velocity of particle 7 at step 1, t=0.001");
  EXPECT_EQ(last.error_step, 1u);
  EXPECT_EQ(last.error_particle_id, 7);
  EXPECT_EQ(run.process.exit_description(), "exited with code 3");
}

TEST(SolverHubWithDummy, InjectedFailureIsReported) {
  DummyRun run("soil", {"--fail-at-step", "0"});
  run.handshake();
  Incoming last;
  EXPECT_TRUE(run.answer_until_exit("soil", last).empty());
  ASSERT_EQ(last.kind, Incoming::Kind::Error);
  EXPECT_EQ(last.error_message, "injected failure at step 0");
  EXPECT_EQ(last.error_particle_id, -1);
  EXPECT_EQ(run.process.exit_description(), "exited with code 3");
}

TEST(SolverHubWithDummy, ProtocolMismatchRefusalEndsTheSolver) {
  DummyRun run("soil", {"--protocol-version", "7"});
  const Incoming hello = run.handshake();  // no Setup for a foreign version
  ASSERT_EQ(hello.protocol_version, 7u);
  run.hub.send_error("soil", "protocol version 7 is not supported; this coupler speaks 1");
  ASSERT_TRUE(run.process.wait_for_exit(kWait));
  EXPECT_EQ(run.process.exit_description(), "exited with code 1");  // the dummy's CouplingError
}

TEST(SolverHubWithDummy, HangingSolverIsSilentUntilTerminated) {
  DummyRun run("water", {"--hang-at-step", "1"});
  run.handshake();
  Incoming in;
  ASSERT_TRUE(run.hub.receive(in, kWait));
  ASSERT_EQ(in.kind, Incoming::Kind::State);
  coupling::StepCommand command;
  command.dt = kDt;
  run.hub.send_command("water", command);
  EXPECT_FALSE(run.hub.receive(in, 0.3));  // hangs instead of sending step 1
  EXPECT_TRUE(run.process.running());
  run.process.terminate(kWait);
  EXPECT_EQ(run.process.exit_description(), "killed by signal 15 (Terminated)");
}

}  // namespace
}  // namespace porosph::coupler
