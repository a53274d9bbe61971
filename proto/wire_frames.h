// The two messages of every step - Envelope{state} and Envelope{command} - written straight from
// the plain structs into a frame and read straight from a frame into them, with Protobuf's own
// wire primitives (google/protobuf/io/coded_stream.h, wire_format_lite.h). The same bytes as
// to_wire() + the generated serialiser (fields in number order, proto3 defaults left out: the
// tests compare byte for byte), without the copy of every array into a message and back. Any
// other message, and a state or command encoded otherwise (a foreign sender's unpacked arrays,
// extra Envelope fields), takes the generated code (wire_convert.h).
// Only the coupling client and the coupler's SolverHub include this header.
#pragma once

#include <cstddef>
#include <cstdint>

#include "proto/coupling_client.h"
#include "proto/porosph.pb.h"
#include "proto/state_delta.h"

namespace porosph::wire {

/// Envelope{state = the state with what `delta` leaves out} (proto/state_delta.h).
class StateFrame {
 public:
  /// Sizes the frame of `state` (kept by reference until write()); returns its bytes.
  std::size_t prepare(const coupling::StepState& state, const coupling::StateDelta& delta);
  /// Writes the prepared frame: exactly prepare()'s bytes.
  void write(std::uint8_t* out) const;

 private:
  const coupling::StepState* state_ = nullptr;
  coupling::StateDelta delta_;
  coupling::SentParticles sent_{coupling::StepState{}, coupling::StateDelta{}};
  std::size_t id_bytes_ = 0, material_bytes_ = 0, body_bytes_ = 0;
  Diagnostics diagnostics_;  ///< the nested message (small): the generated code writes it
  std::size_t diagnostics_bytes_ = 0;
};

/// Envelope{command}.
class CommandFrame {
 public:
  std::size_t prepare(const coupling::StepCommand& command);
  void write(std::uint8_t* out) const;

 private:
  const coupling::StepCommand* command_ = nullptr;
  std::size_t body_bytes_ = 0;
};

/// The body of an Envelope that holds only field `field` (length-delimited): true and its bytes,
/// or false.
bool envelope_body(const void* data, std::size_t size, int field, const std::uint8_t** body,
                   std::size_t* body_size);

/// Reads a StepState body into `out` (every field: absent ones get their defaults). False when
/// the bytes use an encoding this path does not read (the caller then takes the generated code);
/// `out` is then unspecified. `scratch` holds the nested Diagnostics while it is converted.
bool read_state_body(const std::uint8_t* data, std::size_t size, coupling::StepState& out,
                     Diagnostics& scratch);

/// Reads a StepCommand body into `out`, as read_state_body.
bool read_command_body(const std::uint8_t* data, std::size_t size, coupling::StepCommand& out);

}  // namespace porosph::wire
