// Conversions between the plain structs of coupling_client.h and the generated Protobuf messages.
// Shared by the solver-side client (proto/coupling_client.cpp) and the coupler's SolverHub; no
// other code should include this header (it pulls in the generated Protobuf code).
//
// Every function overwrites all fields of its output and reuses its storage: repeated fields and
// std::vectors keep their capacity, so converting a message of the same shape again allocates
// nothing (except for observables with names longer than the small-string buffer, once).
#pragma once

#include "proto/coupling_client.h"
#include "proto/porosph.pb.h"

namespace porosph::wire {

/// Parses one serialised Envelope. A body of the hot type (states on the coupler's side, commands
/// on a solver's side) is parsed into `hot`, a message the caller keeps for the whole run:
/// Envelope::ParseFromArray would delete and re-create its oneof member, and Message::Clear its
/// sub-messages, on every message; parsing into `hot` keeps all arrays' capacity. Any other body
/// is parsed into `envelope`. Sets `body` to the body case; returns false if malformed.
bool parse_envelope(const void* data, std::size_t size, StepState& hot, Envelope& envelope,
                    Envelope::BodyCase& body);
bool parse_envelope(const void* data, std::size_t size, StepCommand& hot, Envelope& envelope,
                    Envelope::BodyCase& body);

/// A state with what `delta` says the coupler already has left out (proto/state_delta.h).
void to_wire(const coupling::StepState& in, const coupling::StateDelta& delta, StepState& out);
/// A whole state (no delta).
void to_wire(const coupling::StepState& in, StepState& out);
void from_wire(const StepState& in, coupling::StepState& out);

void to_wire(const coupling::StepCommand& in, StepCommand& out);
void from_wire(const StepCommand& in, coupling::StepCommand& out);

void to_wire(const coupling::Diagnostics& in, Diagnostics& out);
void from_wire(const Diagnostics& in, coupling::Diagnostics& out);

/// `protocol_version` is not part of SetupData; the coupler fills it in the message separately.
void to_wire(const coupling::SetupData& in, Setup& out);
void from_wire(const Setup& in, coupling::SetupData& out);

void to_wire(const coupling::Timing& in, Goodbye& out);
void from_wire(const Goodbye& in, coupling::Timing& out);

}  // namespace porosph::wire
