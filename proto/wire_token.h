// The run token on the wire: the Envelope field run_token (porosph.proto) that every message from
// a solver carries. The client appends it to each frame it writes; the coupler's SolverHub splits
// it off before it parses the rest, so the direct paths of wire_frames.h see a plain Envelope.
// Only the coupling client and the coupler's SolverHub include this header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace porosph::wire {

/// Bytes of the Envelope field run_token holding `token` (0 for an empty token: proto3 leaves an
/// empty string out).
std::size_t token_field_bytes(std::string_view token);
/// Writes that field (as the generated serialiser does); returns the end.
std::uint8_t* write_token_field(std::string_view token, std::uint8_t* out);

/// Splits a serialised Envelope into its run_token and the bytes of its other fields. The token
/// must come last (where every serialiser writes it: fields go in number order) or first; the
/// rest is then one contiguous range. False when the frame has no token, more than one, one in
/// the middle, or top-level fields that do not parse.
bool split_run_token(const void* data, std::size_t size, std::string_view* token,
                     const std::uint8_t** rest, std::size_t* rest_size);

/// Compares two tokens in time that does not depend on where they differ.
bool same_token(std::string_view a, std::string_view b);

}  // namespace porosph::wire
