// State deltas (docs/solver-protocol.md, "State deltas"): a StepState message may leave out what
// the coupler already has from the same solver's previous state, to cut the bytes every step
// serialises, sends and parses:
//   - same_set: the overlap set holds the same particles in the same order with the same masses
//     and materials; overlap_id, overlap_mass and overlap_material are then left out;
//   - unchanged_tail = K (only with same_set): the last K overlap particles have bitwise the same
//     position, velocity, density and porosity as before (fixed particles, particles at rest);
//     the per-step arrays then hold the first n - K particles only.
// The solver-side client computes the delta (StateDeltaEncoder): solvers always fill full arrays.
// The coupler completes each received state from the previous one (apply_state_delta). A solver
// that speaks the wire format itself may always send full states (both fields default to "none
// left out").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "proto/coupling_client.h"

namespace porosph::coupling {

/// What of each per-step array a state with a delta carries: the values of its first n - K
/// particles (K the unchanged tail), every value without a tail. The one rule every writer of
/// states (wire_convert.h, wire_frames.h) applies.
struct SentParticles {
  SentParticles(const StepState& state, const StateDelta& delta)
      : whole(delta.unchanged_tail == 0),
        moved(state.overlap_id.size() -
              std::min<std::size_t>(state.overlap_id.size(), delta.unchanged_tail)),
        dimension(state.overlap_id.empty()
                      ? 0
                      : state.overlap_position.size() / state.overlap_id.size()) {}

  /// How many of `values` (`per_particle` values per particle: D or 1) go.
  std::size_t count(const std::vector<double>& values, std::size_t per_particle) const {
    return whole || values.empty() ? values.size() : moved * per_particle;
  }

  bool whole;             ///< no tail: the arrays go as they are
  std::size_t moved;      ///< particles whose per-step values go
  std::size_t dimension;  ///< D of the vector arrays (0 without particles)
};

/// Remembers the arrays of the last state sent and finds what the next one may leave out.
class StateDeltaEncoder {
 public:
  /// The delta of `state` against the last state passed here (none for the first), then
  /// remembers `state` (copying only what changed: no allocation once the sizes settle).
  StateDelta next(const StepState& state);

 private:
  StepState last_;
  bool have_last_ = false;
};

/// Completes `received` (a state of `phase` with `received.delta`) from `full`, the same solver's
/// previous complete state, and leaves the complete new state in `full` (arrays sent whole are
/// swapped in, partial ones copied over the prefix; `received` is left with unspecified
/// contents). `dimension` is D of the flattened vectors. Throws std::runtime_error naming the
/// phase when the received sizes do not fit the delta.
void apply_state_delta(StepState& full, StepState& received, int dimension,
                       const std::string& phase);

}  // namespace porosph::coupling
