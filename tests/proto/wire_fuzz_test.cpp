// The coupler's endpoint fed mutated messages (issue 24, hardening): a solver that said Hello sends
// a few hundred copies of a real state message with random damage - bytes overwritten, bits
// flipped, the message cut short, bytes inserted or appended, a length prefix set to garbage; four
// in five to the body only, one in five to the whole message with its run token - each followed
// by an intact state with a sentinel step. Every damaged message must come back from
// SolverHub::receive as a state, a "malformed message" protocol error or a counted drop (a damaged
// run token), the sentinel must always arrive next, and nothing may crash or hang. The decoding
// is the hub's own (the fast frame reader, then the generated code). A nightly run raises the
// count with POROSPH_WIRE_FUZZ_MESSAGES (e.g. 10000).
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>
#include <zmq.hpp>

#include "proto/porosph.pb.h"
#include "wire_test_support.h"

namespace porosph::wire_test {
namespace {

constexpr std::uint64_t kSentinel = 1'000'000'000ULL;

/// A state message as a water solver sends it: 40 overlap particles in 2D and diagnostics.
std::string realistic_state(const std::string& token, std::uint64_t step) {
  wire::Envelope envelope;
  envelope.set_run_token(token);
  wire::StepState& s = *envelope.mutable_state();
  s.set_step(step);
  s.set_time(1e-4 * static_cast<double>(step));
  s.set_dt_limit(1e-4);
  for (int i = 0; i < 40; ++i) {
    s.add_overlap_id(i);
    for (int k = 0; k < 2; ++k) {
      s.add_overlap_position(0.01 * i + 0.001 * k);
      s.add_overlap_velocity(0.1 * k);
    }
    s.add_overlap_density(1000.0 + i);
    s.add_overlap_mass(0.1);
  }
  s.mutable_diagnostics()->set_mass(4.0);
  s.mutable_diagnostics()->add_momentum(0.5);
  s.mutable_diagnostics()->add_momentum(-0.5);
  s.add_region_min(0.0);
  s.add_region_min(0.0);
  s.add_region_max(0.4);
  s.add_region_max(0.01);
  return envelope.SerializeAsString();
}

/// One random kind of damage to `bytes`.
std::string damaged(std::string bytes, std::mt19937& rng) {
  const auto at = [&rng](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  std::uniform_int_distribution<int> byte(0, 255);
  switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0:  // a few bytes overwritten
      for (int i = 0; i < 4; ++i) bytes[at(bytes.size())] = static_cast<char>(byte(rng));
      break;
    case 1:  // one bit flipped
      bytes[at(bytes.size())] ^= static_cast<char>(1 << (rng() % 8));
      break;
    case 2:  // cut short
      bytes.resize(at(bytes.size()));
      break;
    case 3:  // bytes inserted
      bytes.insert(at(bytes.size()), std::string(1 + rng() % 16, static_cast<char>(byte(rng))));
      break;
    case 4:  // garbage appended
      for (int i = 0; i < 64; ++i) bytes.push_back(static_cast<char>(byte(rng)));
      break;
    default:  // a varint length or tag set to its largest value
      bytes.replace(at(bytes.size()), 0, std::string("\xff\xff\xff\xff\x0f", 5));
      break;
  }
  return bytes;
}

TEST(WireFuzz, DamagedStatesAreReadOrRefusedNeverCrashOrHang) {
  const char* env = std::getenv("POROSPH_WIRE_FUZZ_MESSAGES");
  const int messages = env != nullptr ? std::max(1, std::atoi(env)) : 300;
  SolverHub hub(unique_ipc_endpoint());
  zmq::context_t context;
  zmq::socket_t solver{context, zmq::socket_type::dealer};
  solver.set(zmq::sockopt::linger, 0);
  solver.connect(hub.connect_endpoint());
  {
    wire::Envelope hello_message;
    hello_message.set_run_token(hub.run_token());
    wire::Hello& hello = *hello_message.mutable_hello();
    hello.set_protocol_version(coupling::kProtocolVersion);
    hello.set_phase("water");
    hello.set_solver_name("fuzz");
    solver.send(zmq::buffer(hello_message.SerializeAsString()));
  }
  ASSERT_EQ(receive_or_fail(hub).kind, Incoming::Kind::Hello);
  hub.send_setup("water", make_setup("water"));

  std::mt19937 rng(20261205);
  int states = 0, malformed = 0, other_errors = 0;
  for (int i = 0; i < messages; ++i) {
    // Mostly the body (the token field, serialised apart, appended after it: Protobuf merges
    // concatenated messages), one in five the whole message, token included.
    wire::Envelope token_only;
    token_only.set_run_token(hub.run_token());
    const std::string message =
        rng() % 5 == 0 ? damaged(realistic_state(hub.run_token(), i + 1), rng)
                       : damaged(realistic_state("", i + 1), rng) + token_only.SerializeAsString();
    solver.send(zmq::buffer(message));
    solver.send(zmq::buffer(realistic_state(hub.run_token(), kSentinel + i)));
    bool sentinel = false;
    for (int answers = 0; answers < 2 && !sentinel; ++answers) {
      const Incoming in = receive_or_fail(hub);
      if (in.kind == Incoming::Kind::State && in.state.step == kSentinel + i) {
        sentinel = true;
      } else if (in.kind == Incoming::Kind::State) {
        ++states;
      } else if (in.kind == Incoming::Kind::Error &&
                 in.error_message.find("malformed message") != std::string::npos) {
        ++malformed;
      } else {
        ++other_errors;  // e.g. a damaged body tag read as another message type
        EXPECT_EQ(in.kind, Incoming::Kind::Error) << "message " << i;
      }
    }
    ASSERT_TRUE(sentinel) << "the intact state after damaged message " << i << " never arrived";
  }
  const std::size_t dropped = hub.dropped_messages();
  std::printf(
      "wire fuzz: %d damaged states: %d read as states, %d malformed, %d other errors, "
      "%zu dropped (no readable run token)\n",
      messages, states, malformed, other_errors, dropped);
  EXPECT_EQ(static_cast<std::size_t>(states + malformed + other_errors) + dropped,
            static_cast<std::size_t>(messages));
  EXPECT_GT(malformed, 0);  // the damage reached the decoder
  EXPECT_GT(dropped, 0u);   // and the token check
}

}  // namespace
}  // namespace porosph::wire_test
