// The coupler's end of the wire: one ROUTER socket that all solvers connect to. This (with
// solver_hub.cpp) is the only coupler code that sees ZeroMQ or Protobuf; the rest of the coupler
// works with the plain structs of proto/coupling_client.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "proto/coupling_client.h"

namespace porosph::coupler {

/// A message that arrived from one solver.
struct Incoming {
  enum class Kind { Hello, State, Error, Goodbye };
  Kind kind = Kind::State;
  std::string phase;  ///< the phase the sender announced in its Hello
  // Hello
  std::string solver_name, solver_version;
  std::uint32_t protocol_version = 0;
  std::int64_t pid = 0;
  // State (vectors reused between calls: no allocation in steady state)
  coupling::StepState state;
  // Error
  std::string error_message;
  std::uint64_t error_step = 0;
  double error_time = 0;
  std::int64_t error_particle_id = -1;
  // Goodbye
  coupling::Timing timing;
};

class SolverHub {
 public:
  /// Binds a ROUTER socket to `endpoint` ("ipc://..." or "tcp://*:port"). Throws
  /// std::runtime_error.
  explicit SolverHub(const std::string& endpoint);
  ~SolverHub();
  SolverHub(const SolverHub&) = delete;
  SolverHub& operator=(const SolverHub&) = delete;

  /// The endpoint solvers should connect to (for tcp://*:0 the port actually bound).
  std::string connect_endpoint() const;

  /// Waits up to `timeout_seconds` for one message from any solver. Returns false on timeout.
  /// A Hello registers the sender's phase; messages from a peer that never said Hello (or whose
  /// Hello was refused with send_error) are dropped. A frame that does not parse as an Envelope
  /// from a registered peer arrives as an Error ("protocol violation by the <phase> solver: ...").
  bool receive(Incoming& out, double timeout_seconds);

  /// Answers the latest Hello of `phase` with the Setup; that solver becomes the phase's solver
  /// (replacing an earlier one, whose messages are dropped from then on).
  void send_setup(const std::string& phase, const coupling::SetupData& setup);
  /// To the phase's solver (the one that got the Setup). Throws std::runtime_error if there is
  /// none, or if the solver has disconnected (ROUTER_MANDATORY: nothing is dropped silently).
  void send_command(const std::string& phase, const coupling::StepCommand& command);
  /// Refuses a Hello (e.g. protocol version mismatch) or reports a coupler-side failure. Goes to
  /// the unanswered Hello of `phase` if there is one (so a stray second solver is refused without
  /// disturbing the running one), else to the phase's solver.
  void send_error(const std::string& phase, const std::string& message);
  /// To the phase's solver, or to a solver whose Hello was not answered yet.
  void send_shutdown(const std::string& phase, const std::string& reason);

  /// Seconds spent serialising, sending and parsing (excluding waiting).
  double codec_seconds() const;
  /// Payload bytes (serialised Envelopes, without ZeroMQ's framing) received / sent so far.
  std::uint64_t bytes_received() const;
  std::uint64_t bytes_sent() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace porosph::coupler
