// The coupler's end of the wire: one ROUTER socket that all solvers connect to. This (with
// solver_hub.cpp) is the only coupler code that sees ZeroMQ or Protobuf; the rest of the coupler
// works with the plain structs of proto/coupling_client.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "coupler/hub_endpoint.h"
#include "proto/coupling_client.h"

namespace porosph::coupler {

/// A message that arrived from one solver.
/// A send to a solver failed because its connection is gone (it disconnected or stopped
/// reading): usually the sign of a solver that died, which the caller can then look for.
class SolverUnreachable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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
  /// Without a scene to size it from: 64 MiB (a state of ~400,000 overlap particles in 3D).
  static constexpr std::size_t kDefaultMaxFrameBytes = std::size_t{64} << 20;

  /// Binds a ROUTER socket to `endpoint` (hub_endpoint.h: "ipc://PATH", "tcp://HOST:PORT"; an
  /// ipc socket file gets mode 0600 whatever the umask) and draws a fresh run token. A frame
  /// longer than `max_frame_bytes` closes its sender's connection unread (ZMQ_MAXMSGSIZE).
  /// Throws BadEndpoint for an endpoint it cannot listen on, std::runtime_error otherwise.
  explicit SolverHub(const std::string& endpoint,
                     std::size_t max_frame_bytes = kDefaultMaxFrameBytes);
  ~SolverHub();
  SolverHub(const SolverHub&) = delete;
  SolverHub& operator=(const SolverHub&) = delete;

  /// The endpoint solvers should connect to (for tcp://*:0 the port actually bound).
  std::string connect_endpoint() const;

  /// The secret of this run (64 hex digits): a solver's messages must carry it
  /// (Envelope.run_token).
  const std::string& run_token() const;

  /// Waits up to `timeout_seconds` for one message from any solver. Returns false on timeout.
  /// Every message without this hub's run token is dropped and counted (dropped_messages());
  /// a Hello without it is also answered with an Error and never registers. A Hello with it
  /// registers the sender's phase; messages from a peer that never said Hello (or whose Hello
  /// was refused with send_error) are dropped and counted. A frame with the token that does not
  /// parse as an Envelope from a registered peer arrives as an Error ("protocol violation by
  /// the <phase> solver: ...").
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
  /// Messages dropped so far (see receive()); logged rate-limited on stderr.
  std::uint64_t dropped_messages() const;
  /// The endpoint listens on every interface (tcp://*:P, 0.0.0.0, [::]).
  bool listens_everywhere() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace porosph::coupler
