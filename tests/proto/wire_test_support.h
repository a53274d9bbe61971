// Helpers shared by the client <-> hub tests: both ends run in the test process, the hub in the
// test thread and each client in a ClientThread. Every wait has a timeout.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "coupler/solver_hub.h"
#include "proto/coupling_client.h"

namespace porosph::wire_test {

using coupler::Incoming;
using coupler::SolverHub;
using coupling::CouplingClient;
using coupling::CouplingError;

constexpr double kWait = 10.0;  // [s] generous: only reached when something is broken

inline std::string unique_ipc_endpoint() {
  static std::atomic<int> counter{0};
  return "ipc:///tmp/porosph-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

/// A solver identity that carries `hub`'s run token (as POROSPH_RUN_TOKEN would).
inline coupling::SolverIdentity identity_for(const SolverHub& hub, const std::string& phase,
                                             const std::string& name = "t",
                                             const std::string& version = "1") {
  coupling::SolverIdentity identity{phase, name, version};
  identity.run_token = hub.run_token();
  return identity;
}

/// Runs a client body in a thread; the destructor joins, so a failed assertion cannot leave it
/// running. error() joins and returns the exception message ("" if none).
class ClientThread {
 public:
  explicit ClientThread(std::function<void()> body)
      : thread_([this, body = std::move(body)] {
          try {
            body();
          } catch (const CouplingError& e) {
            error_ = e.what();
            coupling_error_ = true;
          } catch (const std::exception& e) {
            error_ = std::string("unexpected exception: ") + e.what();
          }
        }) {}
  ~ClientThread() {
    if (thread_.joinable()) thread_.join();
  }
  const std::string& error() {
    if (thread_.joinable()) thread_.join();
    return error_;
  }
  bool threw_coupling_error() {
    error();
    return coupling_error_;
  }

 private:
  std::string error_;
  bool coupling_error_ = false;
  std::thread thread_;  // last: starts after the members above exist
};

inline coupling::SetupData make_setup(const std::string& phase, double timeout_seconds = kWait) {
  coupling::SetupData setup;
  setup.phase = phase;
  setup.scene_toml = "[run]\nend_time = 0.5\n";
  setup.scene_name = "roundtrip";
  setup.output_dir = "/tmp/porosph-roundtrip";
  setup.dimension = 2;
  setup.dp = 0.01;
  setup.h = 0.013;
  setup.dt0 = 1e-4;
  setup.end_time = 0.5;
  setup.gravity = {0, -9.81};
  setup.timeout_seconds = timeout_seconds;
  return setup;
}

/// Receives one message or fails the test.
inline Incoming receive_or_fail(SolverHub& hub, double timeout = kWait) {
  Incoming in;
  EXPECT_TRUE(hub.receive(in, timeout)) << "no message within " << timeout << " s";
  return in;
}

}  // namespace porosph::wire_test
