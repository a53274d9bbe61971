// Solver side of the coupling: one DEALER socket, one serialised Envelope per ZeroMQ message.
#include "proto/coupling_client.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <zmq.hpp>

#include "proto/porosph.pb.h"
#include "proto/state_delta.h"
#include "proto/wire_convert.h"
#include "proto/wire_frames.h"
#include "proto/wire_message.h"
#include "proto/wire_token.h"

namespace porosph::coupling {
namespace {

using Clock = std::chrono::steady_clock;

/// A solver exits shortly after its last message; it waits at most this long to deliver it.
constexpr int kLingerMilliseconds = 1000;

std::string format_seconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

std::chrono::milliseconds to_milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<long>(seconds * 1000.0 + 0.5));
}

}  // namespace

struct CouplingClient::Impl {
  zmq::context_t context;  // declared first: destroyed after the socket
  zmq::socket_t socket{context, zmq::socket_type::dealer};
  std::string endpoint;
  SolverIdentity identity;
  SetupData setup;
  StepCommand command;
  // Reused for every message: repeated fields and strings keep their capacity.
  wire::Envelope outgoing;
  wire::Envelope incoming;            // any body except commands
  wire::StepCommand command_message;  // commands: parsed here, keeping the arrays' capacity
  wire::Envelope::BodyCase received = wire::Envelope::BODY_NOT_SET;
  wire::StateFrame state_frame;
  zmq::message_t reply;
  StateDeltaEncoder state_delta;  ///< what each state may leave out (proto/state_delta.h)
  double communication_seconds = 0;
  std::uint64_t last_sent_step = 0;  ///< step of the last state sent (for messages)
  std::string run_token;             ///< sent with every message (Envelope.run_token)

  /// Queues one frame (the DEALER queues while the coupler is not yet reachable).
  void send_frame(zmq::message_t frame, zmq::send_flags flags) {
    if (!socket.send(frame, flags)) {
      throw CouplingError("cannot send to the coupler at " + endpoint + ": send queue is full");
    }
  }

  /// Serialises `outgoing` and queues it.
  void send_outgoing(zmq::send_flags flags) { send_frame(wire::to_frame(outgoing), flags); }

  /// Waits up to `seconds` for one message and parses it (a command into `command`, anything
  /// else into `incoming`; `received` says which). False on timeout.
  bool receive_incoming(double seconds) {
    const auto deadline = Clock::now() + to_milliseconds(seconds);
    for (;;) {
      zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      try {
        if (zmq::poll(&item, 1, std::max(left, std::chrono::milliseconds(0))) == 0) return false;
      } catch (const zmq::error_t& e) {
        if (e.num() == EINTR) continue;  // a signal arrived; keep waiting until the deadline
        throw CouplingError(std::string("waiting for the coupler failed: ") + e.what());
      }
      if (!socket.recv(reply, zmq::recv_flags::dontwait)) continue;
      while (reply.more()) {  // a well-behaved coupler sends one frame; drop any extras
        zmq::message_t extra;
        (void)socket.recv(extra, zmq::recv_flags::none);
        if (!extra.more()) break;
      }
      // A command as our coupler writes it goes straight into `command`; anything else through
      // the generated code.
      const std::uint8_t* body = nullptr;
      std::size_t body_size = 0;
      if (wire::envelope_body(reply.data(), reply.size(), wire::Envelope::kCommandFieldNumber,
                              &body, &body_size) &&
          wire::read_command_body(body, body_size, command)) {
        received = wire::Envelope::kCommand;
        return true;
      }
      if (!wire::parse_envelope(reply.data(), reply.size(), command_message, incoming, received)) {
        throw CouplingError("malformed message from the coupler at " + endpoint);
      }
      if (received == wire::Envelope::kCommand) wire::from_wire(command_message, command);
      return true;
    }
  }

  /// Turns an Error or Shutdown from the coupler (instead of `expected`) into an exception.
  [[noreturn]] void throw_unexpected(const char* expected) {
    switch (received) {
      case wire::Envelope::kError:
        throw CouplingError("the coupler reported an error: " + incoming.error().message());
      case wire::Envelope::kShutdown:
        throw CouplingError("the coupler shut down the run: " + incoming.shutdown().reason());
      default:
        throw CouplingError(std::string("protocol violation: expected ") + expected +
                            " from the coupler, got message type " +
                            std::to_string(static_cast<int>(received)));
    }
  }
};

CouplingClient::CouplingClient(const std::string& endpoint, const SolverIdentity& identity,
                               double connect_timeout_seconds)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.endpoint = endpoint;
  d.identity = identity;
  d.run_token = identity.run_token.empty() ? resolve_run_token() : identity.run_token;
  d.outgoing.set_run_token(d.run_token);  // kept: only the body changes between messages
  try {
    d.socket.set(zmq::sockopt::linger, kLingerMilliseconds);
    d.socket.set(zmq::sockopt::ipv6, true);  // tcp://[::1]:P and host names with IPv6 addresses
    d.socket.connect(endpoint);
  } catch (const zmq::error_t& e) {
    throw CouplingError("cannot connect to the coupler at '" + endpoint + "': " + e.what());
  }

  wire::Hello& hello = *d.outgoing.mutable_hello();
  hello.set_protocol_version(identity.protocol_version);
  hello.set_phase(identity.phase);
  hello.set_solver_name(identity.name);
  hello.set_solver_version(identity.version);
  hello.set_pid(static_cast<std::int64_t>(::getpid()));
  d.send_outgoing(zmq::send_flags::dontwait);

  if (!d.receive_incoming(connect_timeout_seconds)) {
    throw CouplingError("no answer from the coupler at " + endpoint + " within " +
                        format_seconds(connect_timeout_seconds) +
                        " s after Hello (is the coupler running and listening there?)");
  }
  if (d.received == wire::Envelope::kError) {
    throw CouplingError("the coupler refused this " + identity.phase +
                        " solver: " + d.incoming.error().message());
  }
  if (d.received != wire::Envelope::kSetup) d.throw_unexpected("Setup");
  const wire::Setup& setup = d.incoming.setup();
  if (setup.protocol_version() != identity.protocol_version) {
    throw CouplingError("the coupler speaks protocol version " +
                        std::to_string(setup.protocol_version()) + ", this solver " +
                        std::to_string(identity.protocol_version));
  }
  wire::from_wire(setup, d.setup);
  if (!(d.setup.timeout_seconds > 0)) d.setup.timeout_seconds = 60.0;
}

CouplingClient::~CouplingClient() = default;

const SetupData& CouplingClient::setup() const { return impl_->setup; }

const StepCommand& CouplingClient::exchange(const StepState& state) {
  send_state(state);
  return receive_command();
}

void CouplingClient::send_state(const StepState& state) {
  Impl& d = *impl_;
  const auto start = Clock::now();
  const std::size_t state_bytes = d.state_frame.prepare(state, d.state_delta.next(state));
  zmq::message_t frame(state_bytes + wire::token_field_bytes(d.run_token));
  auto* bytes = static_cast<std::uint8_t*>(frame.data());
  d.state_frame.write(bytes);
  wire::write_token_field(d.run_token, bytes + state_bytes);  // last, as the serialiser puts it
  d.send_frame(std::move(frame), zmq::send_flags::dontwait);
  d.last_sent_step = state.step;
  d.communication_seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

const StepCommand& CouplingClient::receive_command() {
  Impl& d = *impl_;
  const auto start = Clock::now();
  const bool answered = d.receive_incoming(d.setup.timeout_seconds);
  d.communication_seconds += std::chrono::duration<double>(Clock::now() - start).count();
  if (!answered) {
    throw CouplingError("no answer from the coupler within " +
                        format_seconds(d.setup.timeout_seconds) + " s (step " +
                        std::to_string(d.last_sent_step) + ")");
  }
  if (d.received != wire::Envelope::kCommand) d.throw_unexpected("StepCommand");
  return d.command;
}

void CouplingClient::report_error(const std::string& message, std::uint64_t step, double time,
                                  std::int64_t particle_id) noexcept {
  try {
    Impl& d = *impl_;
    wire::Error& error = *d.outgoing.mutable_error();
    error.set_phase(d.identity.phase);
    error.set_message(message);
    error.set_step(step);
    error.set_time(time);
    error.set_particle_id(particle_id);
    d.send_outgoing(zmq::send_flags::dontwait);  // delivered within the linger period on exit
  } catch (...) {
    // The solver is failing anyway; it reports the error on stderr and exits non-zero.
  }
}

void CouplingClient::finalize(const Timing& timing) {
  Impl& d = *impl_;
  Timing sent = timing;
  if (sent.communication_seconds == 0) sent.communication_seconds = d.communication_seconds;
  wire::to_wire(sent, *d.outgoing.mutable_goodbye());
  d.send_outgoing(zmq::send_flags::dontwait);
}

double CouplingClient::communication_seconds() const { return impl_->communication_seconds; }

std::string resolve_endpoint(const std::string& cli_value) {
  if (!cli_value.empty()) return cli_value;
  const char* from_env = std::getenv("POROSPH_ENDPOINT");
  if (from_env != nullptr && *from_env != '\0') return from_env;
  throw CouplingError(
      "no coupler endpoint: a solver is normally started by the coupler (`coupler run "
      "scene.toml`), "
      "which sets POROSPH_ENDPOINT; to attach by hand, pass --endpoint tcp://HOST:PORT (see "
      "`coupler run --attach`)");
}

std::string resolve_run_token() {
  const char* from_env = std::getenv(kRunTokenVariable);
  return from_env != nullptr ? from_env : "";
}

}  // namespace porosph::coupling
