// Only the solvers of this run take part in it (issue 29, "Security"): every message carries the
// run token; the hub drops and counts what does not, refuses a Hello without it, and never lets a
// stranger take a phase; frames longer than the hub's limit are not read.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <string_view>
#include <zmq.hpp>

#include "proto/porosph.pb.h"
#include "proto/wire_token.h"
#include "wire_test_support.h"

namespace porosph::wire_test {
namespace {

/// A raw DEALER, as a stranger (or a hand-written solver) would open one.
struct RawPeer {
  zmq::context_t context;
  zmq::socket_t socket{context, zmq::socket_type::dealer};
  explicit RawPeer(const std::string& endpoint) {
    socket.set(zmq::sockopt::linger, 0);
    socket.connect(endpoint);
  }
  void send_hello(const std::string& phase, const std::string& token) {
    wire::Envelope envelope;
    envelope.set_run_token(token);
    wire::Hello& hello = *envelope.mutable_hello();
    hello.set_protocol_version(coupling::kProtocolVersion);
    hello.set_phase(phase);
    hello.set_solver_name("stranger");
    hello.set_pid(4242);
    socket.send(zmq::buffer(envelope.SerializeAsString()));
  }
  void send_state(std::uint64_t step, const std::string& token) {
    wire::Envelope envelope;
    envelope.set_run_token(token);
    envelope.mutable_state()->set_step(step);
    socket.send(zmq::buffer(envelope.SerializeAsString()));
  }
  /// The next message from the hub, parsed (false after `seconds`).
  bool receive(wire::Envelope& envelope, double seconds) {
    zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
    if (zmq::poll(&item, 1, std::chrono::milliseconds(static_cast<long>(seconds * 1000))) == 0) {
      return false;
    }
    zmq::message_t reply;
    (void)socket.recv(reply);
    return envelope.ParseFromArray(reply.data(), static_cast<int>(reply.size()));
  }
};

TEST(RunToken, SplitFindsTheTokenLastOrFirstAndNothingElse) {
  wire::Envelope envelope;
  envelope.mutable_state()->set_step(7);
  const std::string body = envelope.SerializeAsString();
  envelope.set_run_token("secret");
  const std::string last = envelope.SerializeAsString();  // the serialiser puts it last
  ASSERT_EQ(last.substr(0, body.size()), body);
  std::string_view token;
  const std::uint8_t* rest = nullptr;
  std::size_t rest_size = 0;
  ASSERT_TRUE(wire::split_run_token(last.data(), last.size(), &token, &rest, &rest_size));
  EXPECT_EQ(token, "secret");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(rest), rest_size), body);

  const std::string token_field = last.substr(body.size());
  const std::string first = token_field + body;
  ASSERT_TRUE(wire::split_run_token(first.data(), first.size(), &token, &rest, &rest_size));
  EXPECT_EQ(token, "secret");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(rest), rest_size), body);

  for (const std::string& bad : {body, token_field + token_field + body, body + token_field + body,
                                 std::string("\xff\xff\xff not protobuf"), last.substr(0, 5)}) {
    EXPECT_FALSE(wire::split_run_token(bad.data(), bad.size(), &token, &rest, &rest_size));
  }
  EXPECT_TRUE(wire::same_token("abc", "abc"));
  EXPECT_FALSE(wire::same_token("abc", "abd"));
  EXPECT_FALSE(wire::same_token("abc", "abcd"));
}

TEST(RunToken, EachHubDrawsItsOwn) {
  SolverHub a(unique_ipc_endpoint()), b(unique_ipc_endpoint());
  EXPECT_EQ(a.run_token().size(), 64u);
  EXPECT_EQ(a.run_token().find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a.run_token(), b.run_token());
}

// The start-up hijack of issue 29: a stranger says Hello for the soil phase before the coupler's
// own solver. It used to win the phase (and the scene); now it is refused, logged and counted,
// and the real solver gets the phase.
TEST(RunToken, StrangerHelloFirstIsRefusedAndTheRealSolverGetsThePhase) {
  SolverHub hub(unique_ipc_endpoint());
  RawPeer stranger(hub.connect_endpoint());
  stranger.send_hello("soil", "");
  RawPeer guesser(hub.connect_endpoint());
  guesser.send_hello("soil", std::string(64, '0'));
  Incoming in;
  EXPECT_FALSE(hub.receive(in, 0.3));  // neither Hello reaches the coupler
  EXPECT_EQ(hub.dropped_messages(), 2u);
  wire::Envelope refusal;
  ASSERT_TRUE(stranger.receive(refusal, kWait));
  ASSERT_TRUE(refusal.has_error());
  EXPECT_NE(refusal.error().message().find("run token"), std::string::npos);
  EXPECT_TRUE(refusal.run_token().empty());  // the coupler never gives the token away

  std::string scene_name;
  ClientThread real([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "soil", "real"), kWait);
    scene_name = c.setup().scene_name;
  });
  in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  EXPECT_EQ(in.solver_name, "real");
  hub.send_setup("soil", make_setup("soil"));
  EXPECT_EQ(real.error(), "");
  EXPECT_EQ(scene_name, "roundtrip");
  stranger.send_state(0, "");  // still nobody's: dropped, never a state of the soil phase
  EXPECT_FALSE(hub.receive(in, 0.3));
  EXPECT_EQ(hub.dropped_messages(), 3u);
}

TEST(RunToken, WrongTokenOnTheSolversOwnConnectionIsDroppedAndCounted) {
  SolverHub hub(unique_ipc_endpoint());
  RawPeer solver(hub.connect_endpoint());
  solver.send_hello("water", hub.run_token());
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));
  solver.send_state(5, "not-the-token");
  solver.send_state(6, "");
  solver.send_state(7, hub.run_token());
  in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::State);
  EXPECT_EQ(in.state.step, 7u);  // the two before it never steered the run
  EXPECT_EQ(hub.dropped_messages(), 2u);
}

TEST(RunToken, ClientWithoutTheTokenIsRefusedWithTheReason) {
  SolverHub hub(unique_ipc_endpoint());
  const char* saved = std::getenv(coupling::kRunTokenVariable);
  const std::string saved_value = saved != nullptr ? saved : "";
  ::unsetenv(coupling::kRunTokenVariable);
  ClientThread client([&] {
    CouplingClient c(hub.connect_endpoint(), {"water", "no-token", "1"}, kWait);
  });
  Incoming in;
  for (int wait = 0; wait < 50 && hub.dropped_messages() == 0; ++wait) {
    EXPECT_FALSE(hub.receive(in, 0.2));  // the hub refuses while it waits for messages
  }
  EXPECT_TRUE(client.threw_coupling_error());
  EXPECT_NE(client.error().find("refused"), std::string::npos) << client.error();
  EXPECT_NE(client.error().find("POROSPH_RUN_TOKEN"), std::string::npos) << client.error();
  EXPECT_EQ(hub.dropped_messages(), 1u);

  ::setenv(coupling::kRunTokenVariable, hub.run_token().c_str(), 1);  // as the coupler hands it
  ClientThread from_env([&] {
    CouplingClient c(hub.connect_endpoint(), {"water", "env", "1"}, kWait);
    c.finalize({});
  });
  in = receive_or_fail(hub);
  EXPECT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));
  in = receive_or_fail(hub);
  EXPECT_EQ(in.kind, Incoming::Kind::Goodbye);
  EXPECT_EQ(from_env.error(), "");
  if (saved != nullptr) {
    ::setenv(coupling::kRunTokenVariable, saved_value.c_str(), 1);
  } else {
    ::unsetenv(coupling::kRunTokenVariable);
  }
}

// Issue 29: one 100 MB frame raised the coupler to 216 MB. A frame over the limit is not read:
// its sender's connection is closed, and the hub goes on serving the others.
TEST(FrameLimit, FrameOverTheLimitIsNotRead) {
  SolverHub hub(unique_ipc_endpoint(), 64 * 1024);
  RawPeer flooder(hub.connect_endpoint());
  flooder.send_hello("water", hub.run_token());
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));
  wire::Envelope big;
  big.set_run_token(hub.run_token());
  big.mutable_state()->mutable_overlap_density()->Resize(200000, 1.0);  // 1.6 MB
  flooder.socket.send(zmq::buffer(big.SerializeAsString()));
  EXPECT_FALSE(hub.receive(in, 0.5));

  ClientThread soil([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "soil"), kWait);
    c.finalize({});
  });
  in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("soil", make_setup("soil"));
  in = receive_or_fail(hub);
  EXPECT_EQ(in.kind, Incoming::Kind::Goodbye);
  EXPECT_EQ(soil.error(), "");
}

}  // namespace
}  // namespace porosph::wire_test
