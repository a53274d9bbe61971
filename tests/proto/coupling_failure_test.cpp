// CouplingClient <-> SolverHub when something goes wrong: refusals, timeouts, shutdowns, strangers,
// bad endpoints; plus endpoint resolution and tcp port 0.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <functional>
#include <regex>
#include <string>
#include <vector>
#include <zmq.hpp>

#include "proto/porosph.pb.h"
#include "wire_test_support.h"

namespace porosph::wire_test {
namespace {

TEST(CouplingWire, ProtocolMismatchRefusedWithTheCouplersMessage) {
  SolverHub hub(unique_ipc_endpoint());
  ClientThread client([&] {
    coupling::SolverIdentity identity = identity_for(hub, "water", "old-solver", "0.1");
    identity.protocol_version = 99;
    CouplingClient c(hub.connect_endpoint(), identity, kWait);
  });
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  EXPECT_EQ(in.protocol_version, 99u);
  const std::string refusal = "protocol version 99 is not supported; this coupler speaks 1";
  hub.send_error(in.phase, refusal);
  EXPECT_TRUE(client.threw_coupling_error());
  EXPECT_NE(client.error().find(refusal), std::string::npos) << client.error();
}

TEST(CouplingWire, ClientGivesUpWhenNoSetupArrives) {
  SolverHub hub(unique_ipc_endpoint());
  ClientThread client(
      [&] { CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water"), 0.2); });
  Incoming in = receive_or_fail(hub);  // the Hello arrives; the hub never answers it
  EXPECT_EQ(in.kind, Incoming::Kind::Hello);
  EXPECT_TRUE(client.threw_coupling_error());
  EXPECT_NE(client.error().find("no answer from the coupler"), std::string::npos) << client.error();
  EXPECT_NE(client.error().find("within 0.2 s"), std::string::npos) << client.error();
}

TEST(CouplingWire, ExchangeTimesOutAfterTheSetupTimeout) {
  SolverHub hub(unique_ipc_endpoint());
  ClientThread client([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water"), kWait);
    c.exchange(coupling::StepState{});
  });
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water", 0.2));
  ASSERT_TRUE(hub.receive(in, kWait));
  EXPECT_EQ(in.kind, Incoming::Kind::State);  // received, never answered
  EXPECT_TRUE(client.threw_coupling_error());
  EXPECT_NE(client.error().find("no answer from the coupler within 0.2 s"), std::string::npos)
      << client.error();
}

TEST(CouplingWire, ShutdownEndsTheExchangeWithTheReason) {
  SolverHub hub(unique_ipc_endpoint());
  ClientThread client([&] {
    CouplingClient c(hub.connect_endpoint(), identity_for(hub, "water"), kWait);
    c.exchange(coupling::StepState{});
  });
  Incoming in = receive_or_fail(hub);
  ASSERT_EQ(in.kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));
  ASSERT_TRUE(hub.receive(in, kWait));
  hub.send_shutdown("water", "the soil solver failed at step 12");
  EXPECT_TRUE(client.threw_coupling_error());
  EXPECT_NE(client.error().find("the soil solver failed at step 12"), std::string::npos)
      << client.error();
}

TEST(CouplingWire, TcpPortZeroReportsTheRealPort) {
  for (const std::string bind : {"tcp://127.0.0.1:0", "tcp://*:0"}) {
    SolverHub hub(bind);
    const std::string endpoint = hub.connect_endpoint();
    std::smatch match;
    ASSERT_TRUE(std::regex_match(endpoint, match, std::regex(R"(tcp://127\.0\.0\.1:(\d+))")))
        << bind << " -> " << endpoint;
    const int port = std::stoi(match[1]);
    EXPECT_GT(port, 0);
    EXPECT_LT(port, 65536);
    ClientThread client([&] {
      CouplingClient c(endpoint, identity_for(hub, "soil"), kWait);
      EXPECT_EQ(c.setup().scene_name, "roundtrip");
    });
    Incoming in = receive_or_fail(hub);
    EXPECT_EQ(in.kind, Incoming::Kind::Hello);
    hub.send_setup("soil", make_setup("soil"));
    EXPECT_EQ(client.error(), "");
  }
}

TEST(CouplingWire, HubDropsPeersWithoutHelloAndFlagsGarbage) {
  SolverHub hub(unique_ipc_endpoint());
  zmq::context_t context;
  zmq::socket_t raw(context, zmq::socket_type::dealer);
  raw.set(zmq::sockopt::linger, 0);
  raw.connect(hub.connect_endpoint());
  wire::Envelope envelope;
  envelope.set_run_token(hub.run_token());
  envelope.mutable_state()->set_step(3);
  raw.send(zmq::buffer(envelope.SerializeAsString()));
  Incoming in;
  EXPECT_FALSE(hub.receive(in, 0.3));  // a state from a peer that said no Hello is dropped
  EXPECT_EQ(hub.dropped_messages(), 1u);

  envelope.mutable_hello()->set_phase("water");
  envelope.mutable_hello()->set_protocol_version(coupling::kProtocolVersion);
  raw.send(zmq::buffer(envelope.SerializeAsString()));
  ASSERT_TRUE(hub.receive(in, kWait));
  EXPECT_EQ(in.kind, Incoming::Kind::Hello);

  raw.send(zmq::str_buffer("\xff\xff\xff not protobuf"));  // no token: nobody's, dropped
  EXPECT_FALSE(hub.receive(in, 0.3));
  EXPECT_EQ(hub.dropped_messages(), 2u);

  wire::Envelope token_only;  // garbage with the token: the registered solver's protocol error
  token_only.set_run_token(hub.run_token());
  // A state whose step varint breaks off, then the token.
  raw.send(zmq::buffer("\x1a\x02\x08\x80" + token_only.SerializeAsString()));
  ASSERT_TRUE(hub.receive(in, kWait));
  EXPECT_EQ(in.kind, Incoming::Kind::Error);
  EXPECT_EQ(in.phase, "water");
  EXPECT_NE(in.error_message.find("malformed"), std::string::npos) << in.error_message;
  EXPECT_EQ(hub.dropped_messages(), 2u);
}

TEST(CouplingWire, FileOfAnIpcEndpointIsRemovedWithTheHub) {
  const std::string endpoint = unique_ipc_endpoint();
  const std::string path = endpoint.substr(std::string("ipc://").size());
  {
    SolverHub hub(endpoint);
    EXPECT_EQ(::access(path.c_str(), F_OK), 0);
  }
  EXPECT_NE(::access(path.c_str(), F_OK), 0);
}

TEST(CouplingWire, SendingToAPhaseThatNeverSaidHelloThrows) {
  SolverHub hub(unique_ipc_endpoint());
  for (const auto& send : std::vector<std::function<void()>>{
           [&] { hub.send_command("soil", coupling::StepCommand{}); },
           [&] { hub.send_setup("soil", make_setup("soil")); },
           [&] { hub.send_error("soil", "no"); }, [&] { hub.send_shutdown("soil", "no"); }}) {
    try {
      send();
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("soil"), std::string::npos) << e.what();
    }
  }
}

TEST(CouplingWire, BadEndpointsAreReported) {
  EXPECT_THROW(SolverHub("bogus://nowhere"), std::runtime_error);
  EXPECT_THROW(CouplingClient("bogus://nowhere", {"water", "t", "1"}, 0.1), CouplingError);
}

TEST(CouplingWire, ResolveEndpointPrefersCliThenEnvironment) {
  const char* saved = std::getenv("POROSPH_ENDPOINT");
  const std::string saved_value = saved ? saved : "";
  ::setenv("POROSPH_ENDPOINT", "ipc:///tmp/from-env", 1);
  EXPECT_EQ(coupling::resolve_endpoint("tcp://host:5"), "tcp://host:5");
  EXPECT_EQ(coupling::resolve_endpoint(""), "ipc:///tmp/from-env");
  ::unsetenv("POROSPH_ENDPOINT");
  try {
    coupling::resolve_endpoint("");
    ADD_FAILURE() << "no exception without endpoint";
  } catch (const CouplingError& e) {
    EXPECT_NE(std::string(e.what()).find("--endpoint"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("coupler"), std::string::npos) << e.what();
  }
  if (saved) ::setenv("POROSPH_ENDPOINT", saved_value.c_str(), 1);
}

}  // namespace
}  // namespace porosph::wire_test
