// CouplingClient <-> SolverHub over real ZeroMQ sockets in one process: the handshake, lock-step
// exchanges with arrays, two solvers routed by phase, errors from a solver.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "wire_test_support.h"

namespace porosph::wire_test {
namespace {

/// The state a test client sends at step k (all arrays filled, values depending on k).
void fill_state(std::uint64_t k, coupling::StepState& s) {
  const double x = static_cast<double>(k);
  s.step = k;
  s.time = 0.01 * x;
  s.dt_limit = 1e-3 + x;
  s.overlap_id = {static_cast<std::int64_t>(k), static_cast<std::int64_t>(k + 1)};
  s.overlap_position = {x, 2 * x, 3 * x, 4 * x};
  s.overlap_velocity = {-x, 0.5, 0.25, x};
  s.overlap_density = {1000 + x, 1001 + x};
  s.overlap_mass = {0.1, 0.2};
  s.region_min = {-x, -1};
  s.region_max = {x, 1};
  s.diagnostics.particle_count = 10 + k;
  s.diagnostics.momentum = {x, -x};
  s.diagnostics.observables["front"] = 0.1 * x;
}

coupling::StepCommand make_command(std::uint64_t k, bool stop) {
  coupling::StepCommand c;
  c.step = k;
  c.time = 0.01 * static_cast<double>(k);
  c.dt = 1e-3 * static_cast<double>(k + 1);
  c.write_output = k % 2 == 0;
  c.output_index = static_cast<std::uint32_t>(k);
  c.stop = stop;
  c.interaction_acceleration = {k + 0.5, -1.0 * k, 2.0, -2.0};
  c.other_region_min = {0, 0};
  c.other_region_max = {1, 1};
  return c;
}

TEST(CouplingWire, HandshakeExchangesAndGoodbye) {
  SolverHub hub(unique_ipc_endpoint());
  coupling::SetupData client_setup;
  std::vector<coupling::StepCommand> received;
  std::vector<const double*> acceleration_storage;
  double client_communication = -1;
  ClientThread client([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water", "test-solver", "9.9"),
                     kWait);
    client_setup = c.setup();
    coupling::StepState state;
    for (std::uint64_t k = 0;; ++k) {
      fill_state(k, state);
      const coupling::StepCommand& command = c.exchange(state);
      received.push_back(command);
      acceleration_storage.push_back(command.interaction_acceleration.data());
      if (command.stop) break;
    }
    c.finalize({2.0, 1.5, 0.0});  // communication 0: the client fills in its own figure
    client_communication = c.communication_seconds();
  });

  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  EXPECT_EQ(in.phase, "water");
  EXPECT_EQ(in.solver_name, "test-solver");
  EXPECT_EQ(in.solver_version, "9.9");
  EXPECT_EQ(in.protocol_version, coupling::kProtocolVersion);
  EXPECT_EQ(in.pid, ::getpid());
  hub.send_setup("water", make_setup("water"));

  constexpr std::uint64_t kSteps = 4;  // the last command says stop
  coupling::StepState expected;
  for (std::uint64_t k = 0; k < kSteps; ++k) {
    ASSERT_TRUE(hub.receive(in, kWait));
    ASSERT_EQ(in.kind, Incoming::Kind::State);
    EXPECT_EQ(in.phase, "water");
    fill_state(k, expected);
    EXPECT_EQ(in.state.step, k);
    EXPECT_EQ(in.state.time, expected.time);
    EXPECT_EQ(in.state.dt_limit, expected.dt_limit);
    EXPECT_EQ(in.state.overlap_id, expected.overlap_id);
    EXPECT_EQ(in.state.overlap_position, expected.overlap_position);
    EXPECT_EQ(in.state.overlap_velocity, expected.overlap_velocity);
    EXPECT_EQ(in.state.overlap_density, expected.overlap_density);
    EXPECT_EQ(in.state.overlap_mass, expected.overlap_mass);
    EXPECT_EQ(in.state.region_min, expected.region_min);
    EXPECT_EQ(in.state.region_max, expected.region_max);
    EXPECT_EQ(in.state.diagnostics.particle_count, 10 + k);
    EXPECT_EQ(in.state.diagnostics.momentum, expected.diagnostics.momentum);
    EXPECT_EQ(in.state.diagnostics.observables, expected.diagnostics.observables);
    hub.send_command("water", make_command(k, k + 1 == kSteps));
  }
  ASSERT_TRUE(hub.receive(in, kWait));
  ASSERT_EQ(in.kind, Incoming::Kind::Goodbye);
  EXPECT_EQ(in.timing.wall_seconds, 2.0);
  EXPECT_EQ(in.timing.physics_seconds, 1.5);

  ASSERT_EQ(client.error(), "");
  EXPECT_EQ(in.timing.communication_seconds, client_communication);
  EXPECT_EQ(client_setup.phase, "water");
  EXPECT_EQ(client_setup.scene_toml, "[run]\nend_time = 0.5\n");
  EXPECT_EQ(client_setup.scene_name, "roundtrip");
  EXPECT_EQ(client_setup.output_dir, "/tmp/porosph-roundtrip");
  EXPECT_EQ(client_setup.dimension, 2);
  EXPECT_EQ(client_setup.h, 0.013);
  EXPECT_EQ(client_setup.gravity, (std::vector<double>{0, -9.81}));
  ASSERT_EQ(received.size(), kSteps);
  for (std::uint64_t k = 0; k < kSteps; ++k) {
    const coupling::StepCommand want = make_command(k, k + 1 == kSteps);
    EXPECT_EQ(received[k].step, k);
    EXPECT_EQ(received[k].dt, want.dt);
    EXPECT_EQ(received[k].write_output, want.write_output);
    EXPECT_EQ(received[k].output_index, want.output_index);
    EXPECT_EQ(received[k].stop, want.stop);
    EXPECT_EQ(received[k].interaction_acceleration, want.interaction_acceleration);
    EXPECT_EQ(received[k].other_region_max, want.other_region_max);
    // The returned command's vectors are reused: same-size exchanges do not reallocate.
    EXPECT_EQ(acceleration_storage[k], acceleration_storage[0]);
  }
}

TEST(CouplingWire, TwoSolversAreRoutedByPhase) {
  SolverHub hub(unique_ipc_endpoint());
  const auto run_solver = [&hub](const std::string& phase, double* dt_seen) {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, phase, "test-" + phase, "1"), kWait);
    coupling::StepState state;
    state.step = 0;
    state.dt_limit = c.setup().dt0;  // echo: proves each solver got its own Setup
    *dt_seen = c.exchange(state).dt;
    c.finalize({});
  };
  double water_dt = 0, soil_dt = 0;
  ClientThread water([&] { run_solver("water", &water_dt); });
  ClientThread soil([&] { run_solver("soil", &soil_dt); });
  // Messages of the two solvers interleave in any order (one may send its state before the other
  // has said Hello), so the hub answers whatever arrives, as the coupler does.
  Incoming in;
  int goodbyes = 0;
  while (goodbyes < 2) {
    ASSERT_TRUE(hub.receive(in, kWait));
    if (in.kind == Incoming::Kind::Hello) {
      coupling::SetupData setup = make_setup(in.phase);
      setup.dt0 = in.phase == "water" ? 1.0 : 2.0;
      hub.send_setup(in.phase, setup);
    } else if (in.kind == Incoming::Kind::State) {
      EXPECT_EQ(in.state.dt_limit, in.phase == "water" ? 1.0 : 2.0);
      coupling::StepCommand command;
      command.stop = true;
      command.dt = in.phase == "water" ? 10.0 : 20.0;
      hub.send_command(in.phase, command);
    } else {
      ASSERT_EQ(in.kind, Incoming::Kind::Goodbye) << in.error_message;
      ++goodbyes;
    }
  }
  EXPECT_EQ(water.error(), "");
  EXPECT_EQ(soil.error(), "");
  EXPECT_EQ(water_dt, 10.0);
  EXPECT_EQ(soil_dt, 20.0);
}

TEST(CouplingWire, ErrorFromSolverCarriesMessageStepAndParticle) {
  SolverHub hub(unique_ipc_endpoint());
  ClientThread client([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "soil", "test-solver", "1"), kWait);
    c.report_error("particle left the domain", 5, 0.25, 42);
  });
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("soil", make_setup("soil"));
  ASSERT_TRUE(hub.receive(in, kWait));
  ASSERT_EQ(in.kind, Incoming::Kind::Error);
  EXPECT_EQ(in.phase, "soil");
  EXPECT_EQ(in.error_message, "particle left the domain");
  EXPECT_EQ(in.error_step, 5u);
  EXPECT_EQ(in.error_time, 0.25);
  EXPECT_EQ(in.error_particle_id, 42);
  EXPECT_EQ(client.error(), "");
}

TEST(CouplingWire, StraySecondHelloIsRefusedWithoutLosingTheRunningSolver) {
  SolverHub hub(unique_ipc_endpoint());
  double first_dt = 0;
  ClientThread first([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water", "first", "1"), kWait);
    first_dt = c.exchange(coupling::StepState{}).dt;
  });
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));
  ASSERT_TRUE(hub.receive(in, kWait));
  ASSERT_EQ(in.kind, Incoming::Kind::State);  // the first solver now waits for its command

  ClientThread second(
      [&] { CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water", "second", "1")); });
  ASSERT_TRUE(hub.receive(in, kWait));
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  EXPECT_EQ(in.solver_name, "second");
  hub.send_error("water", "a water solver is already running");
  EXPECT_NE(second.error().find("a water solver is already running"), std::string::npos)
      << second.error();

  coupling::StepCommand command;
  command.dt = 0.125;
  hub.send_command("water", command);  // still reaches the first solver
  EXPECT_EQ(first.error(), "");
  EXPECT_EQ(first_dt, 0.125);
}

}  // namespace
}  // namespace porosph::wire_test
