// The hot messages' direct frames (proto/wire_frames.h): byte for byte what the generated code
// writes, read back exactly, and other encodings left to the generated code.
#include "proto/wire_frames.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/wire_format_lite.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "proto/wire_convert.h"

namespace porosph::wire {
namespace {

coupling::StepState sample_state() {
  coupling::StepState s;
  s.step = 300;
  s.time = -0.0;  // proto3 writes -0.0 (its bits are not 0)
  s.dt_limit = 1e-5;
  s.dt_cfl = 2e-5;
  s.dt_force = 3e-5;  // dt_viscous stays 0: left out
  s.overlap_id = {4, 90000, -1};
  s.overlap_position = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  s.overlap_velocity = {-1, 1, -2, 2, -3, 3};
  s.overlap_density = {1000, 1001, 1002};
  s.overlap_mass = {0.1, 0.1, 0.2};
  s.overlap_porosity = {0.3, 0.35, 0.4};
  s.overlap_material = {0, 2, -3};
  s.region_min = {-1, -2};
  s.region_max = {3, 4};
  s.diagnostics.particle_count = 100;
  s.diagnostics.mass = 6.5;
  s.diagnostics.momentum = {0.25, -0.5};
  s.diagnostics.observables = {{"front", 0.3}};
  s.diagnostics.terms = {"continuity"};
  s.checkpoint_written = 3;
  return s;
}

coupling::StepCommand sample_command() {
  coupling::StepCommand c;
  c.step = 7;
  c.time = 0.25;
  c.dt = 1e-5;
  c.write_output = true;
  c.output_index = 4;
  c.interaction_acceleration = {1, -2, 3, -4};
  c.interaction_rate = {10, 20};
  c.saturation = {0.5, 1.0};
  c.porosity = {0.4, 1.0};
  c.wall_speed = {0.0, -1e-3, 0.0};
  c.load_force = {42.5};
  c.other_region_min = {0, 0};
  c.other_region_max = {1, 1};
  c.write_checkpoint = true;
  c.checkpoint_index = 2;
  return c;
}

std::string generated_state_bytes(const coupling::StepState& s, const coupling::StateDelta& d) {
  Envelope envelope;
  to_wire(s, d, *envelope.mutable_state());
  return envelope.SerializeAsString();
}

std::string frame_state_bytes(const coupling::StepState& s, const coupling::StateDelta& d) {
  StateFrame frame;
  std::string bytes(frame.prepare(s, d), '\0');
  frame.write(reinterpret_cast<std::uint8_t*>(bytes.data()));
  return bytes;
}

/// The state read back through the direct path from a whole frame.
coupling::StepState read_state(const std::string& bytes) {
  const std::uint8_t* body = nullptr;
  std::size_t size = 0;
  EXPECT_TRUE(envelope_body(bytes.data(), bytes.size(), Envelope::kStateFieldNumber, &body, &size));
  coupling::StepState out = sample_state();  // every field must be overwritten
  Diagnostics scratch;
  EXPECT_TRUE(read_state_body(body, size, out, scratch));
  return out;
}

void expect_same(const coupling::StepState& a, const coupling::StepState& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(std::signbit(a.time), std::signbit(b.time));
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.dt_limit, b.dt_limit);
  EXPECT_EQ(a.dt_cfl, b.dt_cfl);
  EXPECT_EQ(a.dt_viscous, b.dt_viscous);
  EXPECT_EQ(a.dt_force, b.dt_force);
  EXPECT_EQ(a.overlap_id, b.overlap_id);
  EXPECT_EQ(a.overlap_position, b.overlap_position);
  EXPECT_EQ(a.overlap_velocity, b.overlap_velocity);
  EXPECT_EQ(a.overlap_density, b.overlap_density);
  EXPECT_EQ(a.overlap_mass, b.overlap_mass);
  EXPECT_EQ(a.overlap_porosity, b.overlap_porosity);
  EXPECT_EQ(a.overlap_material, b.overlap_material);
  EXPECT_EQ(a.region_min, b.region_min);
  EXPECT_EQ(a.region_max, b.region_max);
  EXPECT_EQ(a.diagnostics.particle_count, b.diagnostics.particle_count);
  EXPECT_EQ(a.diagnostics.mass, b.diagnostics.mass);
  EXPECT_EQ(a.diagnostics.momentum, b.diagnostics.momentum);
  EXPECT_EQ(a.diagnostics.observables, b.diagnostics.observables);
  EXPECT_EQ(a.diagnostics.terms, b.diagnostics.terms);
  EXPECT_EQ(a.checkpoint_written, b.checkpoint_written);
  EXPECT_EQ(a.delta.same_set, b.delta.same_set);
  EXPECT_EQ(a.delta.unchanged_tail, b.delta.unchanged_tail);
}

TEST(WireFrames, StateFramesAreTheGeneratedBytes) {
  const coupling::StepState s = sample_state();
  for (const coupling::StateDelta delta :
       {coupling::StateDelta{}, coupling::StateDelta{true, 0}, coupling::StateDelta{true, 2},
        coupling::StateDelta{true, 3}}) {
    EXPECT_EQ(frame_state_bytes(s, delta), generated_state_bytes(s, delta))
        << "same_set " << delta.same_set << ", tail " << delta.unchanged_tail;
  }
  EXPECT_EQ(frame_state_bytes(coupling::StepState{}, {}),
            generated_state_bytes(coupling::StepState{}, {}));
}

TEST(WireFrames, StatesReadBackExactly) {
  const coupling::StepState s = sample_state();
  for (const coupling::StateDelta delta : {coupling::StateDelta{}, coupling::StateDelta{true, 2}}) {
    const std::string bytes = frame_state_bytes(s, delta);
    // The reference: the generated parser and from_wire.
    Envelope parsed;
    ASSERT_TRUE(parsed.ParseFromString(bytes));
    coupling::StepState expected;
    from_wire(parsed.state(), expected);
    expect_same(read_state(bytes), expected);
  }
  expect_same(read_state(frame_state_bytes(coupling::StepState{}, {})), coupling::StepState{});
}

TEST(WireFrames, CommandFramesAreTheGeneratedBytesAndReadBack) {
  for (const coupling::StepCommand& c : {sample_command(), coupling::StepCommand{}}) {
    Envelope envelope;
    to_wire(c, *envelope.mutable_command());
    CommandFrame frame;
    std::string bytes(frame.prepare(c), '\0');
    frame.write(reinterpret_cast<std::uint8_t*>(bytes.data()));
    EXPECT_EQ(bytes, envelope.SerializeAsString());
    const std::uint8_t* body = nullptr;
    std::size_t size = 0;
    ASSERT_TRUE(
        envelope_body(bytes.data(), bytes.size(), Envelope::kCommandFieldNumber, &body, &size));
    coupling::StepCommand out = sample_command();  // every field must be overwritten
    ASSERT_TRUE(read_command_body(body, size, out));
    EXPECT_EQ(out.step, c.step);
    EXPECT_EQ(out.time, c.time);
    EXPECT_EQ(out.dt, c.dt);
    EXPECT_EQ(out.write_output, c.write_output);
    EXPECT_EQ(out.output_index, c.output_index);
    EXPECT_EQ(out.stop, c.stop);
    EXPECT_EQ(out.interaction_acceleration, c.interaction_acceleration);
    EXPECT_EQ(out.interaction_rate, c.interaction_rate);
    EXPECT_EQ(out.saturation, c.saturation);
    EXPECT_EQ(out.porosity, c.porosity);
    EXPECT_EQ(out.wall_speed, c.wall_speed);
    EXPECT_EQ(out.load_force, c.load_force);
    EXPECT_EQ(out.other_region_min, c.other_region_min);
    EXPECT_EQ(out.other_region_max, c.other_region_max);
    EXPECT_EQ(out.write_checkpoint, c.write_checkpoint);
    EXPECT_EQ(out.checkpoint_index, c.checkpoint_index);
  }
}

TEST(WireFrames, OtherEncodingsAreLeftToTheGeneratedCode) {
  using google::protobuf::internal::WireFormatLite;
  // An unpacked position array (legal protobuf, not what our senders write) and an unknown field.
  std::string body;
  {
    google::protobuf::io::StringOutputStream stream(&body);
    google::protobuf::io::CodedOutputStream out(&stream);
    WireFormatLite::WriteUInt64(1, 5, &out);
    WireFormatLite::WriteDouble(8, 0.5, &out);
    WireFormatLite::WriteDouble(8, 0.25, &out);
  }
  coupling::StepState state;
  Diagnostics scratch;
  EXPECT_FALSE(read_state_body(reinterpret_cast<const std::uint8_t*>(body.data()), body.size(),
                               state, scratch));
  StepState generated;
  ASSERT_TRUE(generated.ParseFromString(body));  // the fallback reads it
  EXPECT_EQ(generated.overlap_position_size(), 2);

  std::string unknown;
  {
    google::protobuf::io::StringOutputStream stream(&unknown);
    google::protobuf::io::CodedOutputStream out(&stream);
    WireFormatLite::WriteUInt64(1, 5, &out);
    WireFormatLite::WriteUInt64(99, 7, &out);  // a field of a newer sender: skipped
  }
  ASSERT_TRUE(read_state_body(reinterpret_cast<const std::uint8_t*>(unknown.data()), unknown.size(),
                              state, scratch));
  EXPECT_EQ(state.step, 5u);
  // A corrupt array length (2 GB claimed in a 10-byte body) is refused before anything is
  // allocated for it.
  std::string corrupt;
  {
    google::protobuf::io::StringOutputStream stream(&corrupt);
    google::protobuf::io::CodedOutputStream out(&stream);
    WireFormatLite::WriteTag(8, WireFormatLite::WIRETYPE_LENGTH_DELIMITED, &out);
    out.WriteVarint32(0x7ffffff8u);
    out.WriteLittleEndian64(0);
  }
  EXPECT_FALSE(read_state_body(reinterpret_cast<const std::uint8_t*>(corrupt.data()),
                               corrupt.size(), state, scratch));
  EXPECT_LT(state.overlap_position.capacity(), 1000u);
  // A truncated frame is refused, not read past its end.
  const std::string bytes = frame_state_bytes(sample_state(), {});
  const std::uint8_t* b = nullptr;
  std::size_t size = 0;
  EXPECT_FALSE(
      envelope_body(bytes.data(), bytes.size() - 1, Envelope::kStateFieldNumber, &b, &size));
  ASSERT_TRUE(envelope_body(bytes.data(), bytes.size(), Envelope::kStateFieldNumber, &b, &size));
  EXPECT_FALSE(read_state_body(b, size - 5, state, scratch));  // into region_max
}

}  // namespace
}  // namespace porosph::wire
