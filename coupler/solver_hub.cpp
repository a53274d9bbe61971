// The coupler's ROUTER socket. A DEALER's message arrives as two frames: [peer routing
// id][Envelope].
#include "coupler/solver_hub.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <functional>
#include <map>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <zmq.hpp>

#include "coupler/coupled_step_clock.h"
#include "coupler/dropped_messages.h"
#include "coupler/run_token.h"
#include "proto/porosph.pb.h"
#include "proto/wire_convert.h"
#include "proto/wire_frames.h"
#include "proto/wire_message.h"
#include "proto/wire_token.h"

namespace porosph::coupler {
namespace {

/// On shutdown the coupler waits at most this long to deliver its last messages.
constexpr int kLingerMilliseconds = 1000;
/// A send blocks only if a solver stopped reading with many messages queued; give up after this.
constexpr int kSendTimeoutMilliseconds = 10000;

std::string_view view(const zmq::message_t& frame) {
  return {static_cast<const char*>(frame.data()), frame.size()};
}

}  // namespace

struct SolverHub::Impl {
  zmq::context_t context;  // declared first: destroyed after the socket
  zmq::socket_t socket{context, zmq::socket_type::router};
  std::string connect_endpoint;
  std::string ipc_path;  // socket file of an ipc:// endpoint; libzmq 4.3 leaves it behind
  // Peers are ZeroMQ routing ids. phase_of_peer: every solver that said Hello and was not refused.
  // Per phase: the solver that got a Setup (active) and one whose Hello awaits an answer (pending),
  // so a stray second Hello for a running phase can be refused without losing the running solver.
  std::map<std::string, std::string, std::less<>> phase_of_peer;
  std::map<std::string, std::string> active_peer;
  std::map<std::string, std::string> pending_peer;
  // Reused for every message: repeated fields, vectors and strings keep their capacity.
  wire::Envelope incoming;                // any body except states
  wire::StepState state_message;          // states: parsed here, keeping the arrays' capacity
  wire::Diagnostics diagnostics_scratch;  // a state's diagnostics on the direct path
  wire::CommandFrame command_frame;
  wire::Envelope outgoing;
  zmq::message_t peer_frame;
  zmq::message_t payload_frame;
  double codec_seconds = 0;
  std::uint64_t bytes_received = 0, bytes_sent = 0;
  std::string run_token = fresh_run_token();
  DroppedMessages dropped;
  bool listens_everywhere = false;

  /// Waits until a message is readable or the deadline passes (signals do not cut the wait short).
  bool wait_readable(Clock::time_point deadline) {
    for (;;) {
      zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      try {
        return zmq::poll(&item, 1, std::max(left, std::chrono::milliseconds(0))) > 0;
      } catch (const zmq::error_t& e) {
        if (e.num() != EINTR) throw std::runtime_error(std::string("zmq poll failed: ") + e.what());
      }
    }
  }

  ~Impl() {
    socket.close();
    if (!ipc_path.empty()) ::unlink(ipc_path.c_str());
  }

  enum class Frames { None, WellFormed, Malformed };
  /// Reads one [peer][payload] message into peer_frame / payload_frame.
  Frames read_frames() {
    if (!socket.recv(peer_frame, zmq::recv_flags::dontwait) || !peer_frame.more()) {
      return Frames::None;
    }
    (void)socket.recv(payload_frame, zmq::recv_flags::none);
    bytes_received += payload_frame.size();
    Frames result = Frames::WellFormed;
    while (payload_frame.more()) {  // our DEALERs send one frame; drain anything longer
      result = Frames::Malformed;
      (void)socket.recv(payload_frame, zmq::recv_flags::none);
    }
    return result;
  }

  void register_hello(std::string_view peer, const std::string& phase) {
    phase_of_peer[std::string(peer)] = phase;
    pending_peer[phase] = std::string(peer);
  }

  /// The peer a message for `phase` goes to: the pending one first if `answer_to_hello`, else the
  /// active one first. Throws if the phase has neither.
  std::string peer_for(const std::string& phase, bool answer_to_hello) const {
    const auto& first = answer_to_hello ? pending_peer : active_peer;
    const auto& second = answer_to_hello ? active_peer : pending_peer;
    if (auto it = first.find(phase); it != first.end()) return it->second;
    if (auto it = second.find(phase); it != second.end()) return it->second;
    throw std::runtime_error("cannot send to the " + phase + " solver: none has said Hello");
  }

  /// After the pending Hello of `phase` was answered: accepted (Setup) or refused (Error).
  void settle_pending(const std::string& phase, const std::string& peer, bool accepted) {
    if (auto it = pending_peer.find(phase); it != pending_peer.end() && it->second == peer) {
      pending_peer.erase(it);
    }
    const auto active = active_peer.find(phase);
    if (accepted) {
      if (active != active_peer.end() && active->second != peer) {
        phase_of_peer.erase(active->second);  // replaced: the old solver's messages are dropped
      }
      active_peer[phase] = peer;
    } else if (active == active_peer.end() || active->second != peer) {
      phase_of_peer.erase(peer);  // refused: its further messages are dropped
    }
  }

  /// Parses payload_frame: a state into `state`, any other body into `incoming`; `body` says
  /// which. A state as our client writes it goes straight into `state` (wire_frames.h), anything
  /// else through the generated code. False when malformed.
  bool parse_payload(const std::uint8_t* data, std::size_t size, coupling::StepState& state,
                     wire::Envelope::BodyCase& body) {
    const std::uint8_t* state_body = nullptr;
    std::size_t state_size = 0;
    if (wire::envelope_body(data, size, wire::Envelope::kStateFieldNumber, &state_body,
                            &state_size) &&
        wire::read_state_body(state_body, state_size, state, diagnostics_scratch)) {
      body = wire::Envelope::kState;
      return true;
    }
    if (!wire::parse_envelope(data, size, state_message, incoming, body)) return false;
    if (body == wire::Envelope::kState) wire::from_wire(state_message, state);
    return true;
  }

  /// Sends [peer][payload] to the phase's solver.
  void send_frames(const std::string& peer, const std::string& phase, zmq::message_t payload) {
    bytes_sent += payload.size();
    try {
      if (!socket.send(zmq::buffer(peer), zmq::send_flags::sndmore) ||
          !socket.send(payload, zmq::send_flags::none)) {
        throw SolverUnreachable("cannot send to the " + phase + " solver: it stopped reading");
      }
    } catch (const zmq::error_t& e) {
      if (e.num() == EHOSTUNREACH) {
        throw SolverUnreachable("cannot send to the " + phase + " solver: it disconnected");
      }
      throw std::runtime_error("cannot send to the " + phase + " solver: " + e.what());
    }
  }

  /// The run token of payload_frame (and the rest of it), if it carries this run's.
  bool has_run_token(const std::uint8_t** rest, std::size_t* rest_size) const {
    std::string_view token;
    return wire::split_run_token(payload_frame.data(), payload_frame.size(), &token, rest,
                                 rest_size) &&
           wire::same_token(token, run_token);
  }

  /// A message without this run's token: counted and logged; a Hello is refused (without
  /// waiting: a stranger that does not read cannot block the coupler).
  void drop_without_token(std::string_view peer, bool well_formed) {
    wire::Envelope::BodyCase body = wire::Envelope::BODY_NOT_SET;
    const bool parsed =
        well_formed && wire::parse_envelope(payload_frame.data(), payload_frame.size(),
                                            state_message, incoming, body);
    if (!parsed || body != wire::Envelope::kHello) {
      const auto known = phase_of_peer.find(peer);
      dropped.add(std::string("a message without the run token from ") +
                  (known != phase_of_peer.end()
                       ? "the connection of the " + known->second + " solver"
                       : "an unknown peer"));
      return;
    }
    const wire::Hello& hello = incoming.hello();
    dropped.add("refused a Hello with no or a wrong run token (claims: " +
                printable(hello.phase()) + " solver '" + printable(hello.solver_name()) +
                "', pid " + std::to_string(hello.pid()) + ")");
    outgoing.mutable_error()->set_phase("coupler");
    outgoing.mutable_error()->set_message(
        "refused: this Hello carries no or a wrong run token (a solver started by the coupler "
        "finds "
        "it in $POROSPH_RUN_TOKEN; for `coupler run --attach`, set POROSPH_RUN_TOKEN to the "
        "token the coupler printed)");
    try {
      zmq::message_t reply = wire::to_frame(outgoing);
      if (socket.send(zmq::buffer(peer), zmq::send_flags::sndmore | zmq::send_flags::dontwait)) {
        (void)socket.send(reply, zmq::send_flags::dontwait);
      }
    } catch (const zmq::error_t&) {
      // Gone already: nothing to refuse.
    }
  }

  void send_outgoing(const std::string& peer, const std::string& phase) {
    const auto start = Clock::now();
    send_frames(peer, phase, wire::to_frame(outgoing));
    codec_seconds += seconds_since(start);
  }
};

SolverHub::SolverHub(const std::string& endpoint, std::size_t max_frame_bytes)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  const BindPlan plan = plan_bind(endpoint);
  d.listens_everywhere = plan.wildcard;
  std::string bound;
  try {
    d.socket.set(zmq::sockopt::linger, kLingerMilliseconds);
    d.socket.set(zmq::sockopt::router_mandatory, true);
    d.socket.set(zmq::sockopt::sndtimeo, kSendTimeoutMilliseconds);
    d.socket.set(zmq::sockopt::maxmsgsize, static_cast<std::int64_t>(max_frame_bytes));
    if (plan.ipv6) d.socket.set(zmq::sockopt::ipv6, true);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("cannot set up the solver socket: " + std::string(e.what()));
  }
  // A host name listens on each of its addresses that this machine has (localhost: 127.0.0.1,
  // and ::1 where there is IPv6); it fails only when none can be bound.
  std::string port;   // of the first bound address, for the others when bound to port 0
  std::string error;  // the first bind failure
  for (std::string address : plan.endpoints) {
    if (!port.empty()) address = address.substr(0, address.rfind(':') + 1) + port;
    // The socket file is created by bind: private from its first moment, whatever the umask.
    const mode_t umask_before = plan.ipc_path.empty() ? 0 : ::umask(0077);
    try {
      d.socket.bind(address);
    } catch (const zmq::error_t& e) {
      if (error.empty()) error = e.what();
      if (!plan.ipc_path.empty()) ::umask(umask_before);
      continue;
    }
    if (!plan.ipc_path.empty()) ::umask(umask_before);
    if (bound.empty()) {
      bound = d.socket.get(zmq::sockopt::last_endpoint);
      if (plan.ipc_path.empty()) port = bound.substr(bound.rfind(':') + 1);
    }
  }
  if (bound.empty()) throw BadEndpoint("cannot listen for solvers on '" + endpoint + "': " + error);
  d.connect_endpoint = connectable(bound);
  if (!plan.ipc_path.empty()) {
    d.ipc_path = plan.ipc_path;
    ::chmod(d.ipc_path.c_str(), 0600);  // belt and braces: umask covered the creation
  }
}

SolverHub::~SolverHub() = default;

std::string SolverHub::connect_endpoint() const { return impl_->connect_endpoint; }

bool SolverHub::receive(Incoming& out, double timeout_seconds) {
  Impl& d = *impl_;
  const auto deadline =
      Clock::now() + std::chrono::milliseconds(static_cast<long>(timeout_seconds * 1000.0 + 0.5));
  while (d.wait_readable(deadline)) {
    const Impl::Frames frames = d.read_frames();
    if (frames == Impl::Frames::None) continue;
    const auto start = Clock::now();
    const std::string_view peer = view(d.peer_frame);
    const std::uint8_t* rest = nullptr;
    std::size_t rest_size = 0;
    if (!d.has_run_token(&rest, &rest_size)) {
      d.drop_without_token(peer, frames == Impl::Frames::WellFormed);
      d.codec_seconds += seconds_since(start);
      continue;
    }
    wire::Envelope::BodyCase body = wire::Envelope::BODY_NOT_SET;
    const bool parsed =
        frames == Impl::Frames::WellFormed && d.parse_payload(rest, rest_size, out.state, body);
    if (parsed && body == wire::Envelope::kHello) {
      const wire::Hello& hello = d.incoming.hello();
      d.register_hello(peer, hello.phase());
      out.kind = Incoming::Kind::Hello;
      out.phase = hello.phase();
      out.solver_name = hello.solver_name();
      out.solver_version = hello.solver_version();
      out.protocol_version = hello.protocol_version();
      out.pid = hello.pid();
      d.codec_seconds += seconds_since(start);
      return true;
    }
    const auto known = d.phase_of_peer.find(peer);
    if (known == d.phase_of_peer.end()) {  // never said Hello, refused or replaced: drop
      d.dropped.add(
          "a message from a connection that is no phase's solver (it said no Hello, "
          "or its Hello was refused or replaced)");
      continue;
    }
    out.phase = known->second;
    const auto protocol_error = [&out](const std::string& what) {
      out.kind = Incoming::Kind::Error;
      out.error_message = "protocol violation by the " + out.phase + " solver: " + what;
      out.error_step = 0;
      out.error_time = 0;
      out.error_particle_id = -1;
    };
    if (!parsed) {
      protocol_error("malformed message");
    } else {
      switch (body) {
        case wire::Envelope::kState:
          out.kind = Incoming::Kind::State;
          break;
        case wire::Envelope::kError: {
          const wire::Error& error = d.incoming.error();
          out.kind = Incoming::Kind::Error;
          out.error_message = error.message();
          out.error_step = error.step();
          out.error_time = error.time();
          out.error_particle_id = error.particle_id();
          break;
        }
        case wire::Envelope::kGoodbye:
          out.kind = Incoming::Kind::Goodbye;
          wire::from_wire(d.incoming.goodbye(), out.timing);
          break;
        default:
          protocol_error("unexpected message type " + std::to_string(static_cast<int>(body)));
      }
    }
    d.codec_seconds += seconds_since(start);
    return true;
  }
  return false;
}

void SolverHub::send_setup(const std::string& phase, const coupling::SetupData& setup) {
  const std::string peer = impl_->peer_for(phase, true);
  wire::Setup& message = *impl_->outgoing.mutable_setup();
  message.set_protocol_version(coupling::kProtocolVersion);
  wire::to_wire(setup, message);
  impl_->send_outgoing(peer, phase);
  impl_->settle_pending(phase, peer, true);
}

void SolverHub::send_command(const std::string& phase, const coupling::StepCommand& command) {
  const auto active = impl_->active_peer.find(phase);
  if (active == impl_->active_peer.end()) {
    throw std::runtime_error("cannot send a command to the " + phase + " solver: it has no Setup");
  }
  const auto start = Clock::now();
  zmq::message_t frame(impl_->command_frame.prepare(command));
  impl_->command_frame.write(static_cast<std::uint8_t*>(frame.data()));
  impl_->send_frames(active->second, phase, std::move(frame));
  impl_->codec_seconds += seconds_since(start);
}

void SolverHub::send_error(const std::string& phase, const std::string& message) {
  const std::string peer = impl_->peer_for(phase, true);
  wire::Error& error = *impl_->outgoing.mutable_error();
  error.set_phase("coupler");
  error.set_message(message);
  error.set_step(0);
  error.set_time(0);
  error.set_particle_id(-1);
  impl_->send_outgoing(peer, phase);
  impl_->settle_pending(phase, peer, false);
}

void SolverHub::send_shutdown(const std::string& phase, const std::string& reason) {
  impl_->outgoing.mutable_shutdown()->set_reason(reason);
  impl_->send_outgoing(impl_->peer_for(phase, false), phase);
}

double SolverHub::codec_seconds() const { return impl_->codec_seconds; }
std::uint64_t SolverHub::bytes_received() const { return impl_->bytes_received; }
std::uint64_t SolverHub::bytes_sent() const { return impl_->bytes_sent; }
std::uint64_t SolverHub::dropped_messages() const { return impl_->dropped.count(); }
bool SolverHub::listens_everywhere() const { return impl_->listens_everywhere; }
const std::string& SolverHub::run_token() const { return impl_->run_token; }

}  // namespace porosph::coupler
