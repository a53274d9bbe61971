// "No allocation per step": once the first message of a shape has been handled, converting and
// (de)serialising further messages of that shape must not touch the heap. Counted by replacing
// the global operator new for this test program; only the counting thread's calls are counted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <new>
#include <string>
#include <thread>

#include "coupler/solver_hub.h"
#include "proto/coupling_client.h"
#include "proto/wire_convert.h"

namespace {
thread_local bool counting = false;
thread_local long allocations = 0;

void* counted_allocation(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted_allocation(size); }
void* operator new[](std::size_t size) { return counted_allocation(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_allocation(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace porosph::wire {
namespace {

/// Heap allocations made by `body` in this thread.
template <typename Body>
long allocations_in(Body&& body) {
  allocations = 0;
  counting = true;
  body();
  counting = false;
  return allocations;
}

coupling::StepState overlap_state(double shift) {
  coupling::StepState s;
  s.step = 4;
  s.overlap_id.assign(50, 1);
  s.overlap_position.assign(100, 0.5 + shift);
  s.overlap_velocity.assign(100, -0.5);
  s.overlap_density.assign(50, 1000);
  s.overlap_mass.assign(50, 0.1);
  s.overlap_porosity.assign(50, 0.4);
  s.overlap_material.assign(50, 1);
  s.region_min = {0, 0};
  s.region_max = {1, 1};
  s.diagnostics.momentum = {1, 2};
  s.diagnostics.external_impulse.assign(14, shift);  // 7 sources x 2: no allocation either
  s.diagnostics.balance_momentum = {shift, 2};
  return s;
}

TEST(WireAllocation, StateSendAndReceiveAllocateNothingInSteadyState) {
  // Sender side (the client): struct -> Envelope -> bytes, both reused.
  Envelope outgoing;
  std::string bytes;
  // Receiver side (the hub): bytes -> reused StepState message -> reused struct.
  Envelope incoming;
  StepState state_message;
  coupling::StepState received;
  Envelope::BodyCase body = Envelope::BODY_NOT_SET;
  const auto one_step = [&](const coupling::StepState& sent) {
    to_wire(sent, *outgoing.mutable_state());
    outgoing.SerializeToString(&bytes);
    ASSERT_TRUE(parse_envelope(bytes.data(), bytes.size(), state_message, incoming, body));
    ASSERT_EQ(body, Envelope::kState);
    from_wire(state_message, received);
  };
  one_step(overlap_state(0.0));  // first message of this shape: allocations expected
  const coupling::StepState next = overlap_state(1.0);
  EXPECT_EQ(allocations_in([&] {
              for (int step = 0; step < 5; ++step) one_step(next);
            }),
            0);
  EXPECT_EQ(received.overlap_position, next.overlap_position);
  EXPECT_EQ(received.overlap_material, next.overlap_material);
}

TEST(WireAllocation, CommandSendAndReceiveAllocateNothingInSteadyState) {
  Envelope outgoing, incoming;
  std::string bytes;
  StepCommand command_message;
  coupling::StepCommand sent, received;
  sent.dt = 1e-4;
  sent.interaction_acceleration.assign(100, 0.25);
  sent.saturation.assign(50, 1.0);
  Envelope::BodyCase body = Envelope::BODY_NOT_SET;
  const auto one_step = [&] {
    to_wire(sent, *outgoing.mutable_command());
    outgoing.SerializeToString(&bytes);
    ASSERT_TRUE(parse_envelope(bytes.data(), bytes.size(), command_message, incoming, body));
    ASSERT_EQ(body, Envelope::kCommand);
    from_wire(command_message, received);
  };
  one_step();
  sent.dt = 2e-4;
  EXPECT_EQ(allocations_in([&] {
              for (int step = 0; step < 5; ++step) one_step();
            }),
            0);
  EXPECT_EQ(received.dt, 2e-4);
  EXPECT_EQ(received.interaction_acceleration, sent.interaction_acceleration);
}

TEST(WireAllocation, OtherBodiesAndExtraFieldsTakeTheGeneralPath) {
  Envelope envelope, incoming;
  StepCommand command_message;
  Envelope::BodyCase body = Envelope::BODY_NOT_SET;
  envelope.mutable_shutdown()->set_reason("bye");
  std::string bytes = envelope.SerializeAsString();
  ASSERT_TRUE(parse_envelope(bytes.data(), bytes.size(), command_message, incoming, body));
  EXPECT_EQ(body, Envelope::kShutdown);
  EXPECT_EQ(incoming.shutdown().reason(), "bye");

  // A command followed by a second copy of the field (legal protobuf: the copies merge).
  envelope.mutable_command()->set_dt(0.5);
  Envelope second;
  second.mutable_command()->set_stop(true);
  bytes = envelope.SerializeAsString() + second.SerializeAsString();
  ASSERT_TRUE(parse_envelope(bytes.data(), bytes.size(), command_message, incoming, body));
  EXPECT_EQ(body, Envelope::kCommand);
  EXPECT_EQ(command_message.dt(), 0.5);
  EXPECT_TRUE(command_message.stop());

  const std::string garbage = "\xff\xff\xff\xff";
  EXPECT_FALSE(parse_envelope(garbage.data(), garbage.size(), command_message, incoming, body));
}

TEST(WireAllocation, ExchangeThroughZeroMqAllocatesNothingInSteadyState) {
  // Both ends, through real sockets. ZeroMQ's own message buffers come from malloc (not counted);
  // what is counted is every operator new in our code and in Protobuf, on each side's thread.
  coupler::SolverHub hub("ipc:///tmp/porosph-test-" + std::to_string(::getpid()) + "-alloc");
  constexpr int kWarmUp = 2, kSteps = 20;
  long client_allocations = -1;
  std::thread client([&] {
    coupling::SolverIdentity identity{"water", "t", "1"};
    identity.run_token = hub.run_token();
    coupling::CouplingClient c(hub.connect_endpoint(), identity, 10.0);
    const coupling::StepState state = overlap_state(0.0);
    for (int step = 0; step < kWarmUp; ++step) c.exchange(state);
    client_allocations = allocations_in([&] {
      for (int step = 0; step < kSteps; ++step) c.exchange(state);
    });
    c.finalize({});
  });
  coupler::Incoming in;
  ASSERT_TRUE(hub.receive(in, 10.0));
  coupling::SetupData setup;
  setup.timeout_seconds = 10;
  hub.send_setup("water", setup);
  coupling::StepCommand command;
  command.interaction_acceleration.assign(100, 0.5);
  const auto answer = [&] {
    if (hub.receive(in, 10.0)) hub.send_command("water", command);
  };
  for (int step = 0; step < kWarmUp; ++step) answer();
  const long hub_allocations = allocations_in([&] {
    for (int step = 0; step < kSteps; ++step) answer();
  });
  ASSERT_TRUE(hub.receive(in, 10.0));
  EXPECT_EQ(in.kind, coupler::Incoming::Kind::Goodbye);
  client.join();
  EXPECT_EQ(client_allocations, 0);
  EXPECT_EQ(hub_allocations, 0);
}

}  // namespace
}  // namespace porosph::wire
