// A phase's external-impulse book of one step (docs/coupling.md, "The external-impulse ledger"):
// for each source s the impulse J_s [N s] (per metre in 2D) by which the solver's own step changed
// the momentum it reports, so that over the step
//   P^{n+1} - P^n = sum_s J_s + dt sum m a_interaction + (internal pair forces: 0 to round-off)
// with the coupler's ledger booking the interaction term. Each solver defines its sources (an enum
// of indices and their names); the book goes to the coupler with the next state
// (Diagnostics.external_impulse, N x D row-major) and into the solver's checkpoint, so that a
// resumed solver reports the step it made before the checkpoint.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "io/checkpoint_file.h"
#include "sph/vector.h"

namespace porosph::sph {

template <int D, std::size_t N>
struct ImpulseBook {
  std::array<Vec<D>, N> impulse;

  ImpulseBook() { clear(); }
  void clear() { impulse.fill(Vec<D>::Zero()); }
  Vec<D>& operator[](std::size_t source) { return impulse[source]; }
  const Vec<D>& operator[](std::size_t source) const { return impulse[source]; }

  /// N x D values, row-major, into `out` (resized; no allocation once it has grown).
  void flatten(std::vector<double>& out) const {
    out.resize(N * D);
    for (std::size_t s = 0; s < N; ++s)
      for (int k = 0; k < D; ++k) out[s * D + k] = impulse[s][k];
  }

  /// Stores the book as the dataset "external_impulse" (N x D).
  void write(io::CheckpointWriter& out) const {
    std::vector<double> values;
    flatten(values);
    out.write("external_impulse", values.data(), N, D);
  }
  /// Restores it; a checkpoint written before the books existed (or with another set of sources)
  /// leaves it empty: the first state after the resume then books nothing for its last step.
  void read(const io::CheckpointReader& in) {
    clear();
    if (!in.has("external_impulse") || in.rows("external_impulse", D) != N) return;
    std::vector<double> values(N * D);
    in.read("external_impulse", values.data(), D);
    for (std::size_t s = 0; s < N; ++s)
      for (int k = 0; k < D; ++k) impulse[s][k] = values[s * D + k];
  }
};

}  // namespace porosph::sph
