// In-process check of a solver's write_checkpoint / restore_checkpoint: a solver restored from a
// checkpoint taken after k steps continues exactly as the solver that wrote it (every particle
// array bit for bit), for the water and soil solver tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/checkpoint_file.h"
#include "proto/coupling_client.h"

namespace porosph::testing {

/// One coupled-loop step without a coupler: rates, state (no overlap), advance by the solver's own
/// limit capped at dt0.
template <class Solver>
void step_alone(Solver& solver, coupling::StepState& state, double dt0) {
  static const std::vector<double> none;
  solver.compute_rates();
  solver.fill_state(state, none, none);
  solver.advance(std::min(dt0, state.dt_limit));
}

/// Every per-particle array of a and b is identical (element by element, bit for bit).
template <class Particles>
void expect_identical_particles(Particles& a, Particles& b) {
  std::vector<const void*> arrays_b;
  std::vector<std::size_t> bytes_b;
  b.for_each_array([&](const auto& array) {
    arrays_b.push_back(array.data());
    bytes_b.push_back(array.size() * sizeof(array[0]));
  });
  std::size_t k = 0;
  ASSERT_EQ(a.n_free, b.n_free);
  a.for_each_array([&](const auto& array) {
    const std::size_t bytes = array.size() * sizeof(array[0]);
    ASSERT_EQ(bytes, bytes_b[k]) << "array " << k;
    // memcmp: NaN placeholders (e.g. unknown wall normals) compare equal bit for bit.
    EXPECT_EQ(bytes == 0 ? 0 : std::memcmp(array.data(), arrays_b[k], bytes), 0) << "array " << k;
    ++k;
  });
}

/// Runs `first` for `before` steps, checkpoints it into a fresh `second` (built from the same
/// scene), then runs both for `after` steps and compares them.
template <class Solver>
void expect_checkpoint_continues_exactly(Solver& first, Solver& second, int before, int after,
                                         double dt0) {
  coupling::StepState state;
  for (int i = 0; i < before; ++i) step_alone(first, state, dt0);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("porosph-solver-checkpoint-" + std::to_string(getpid()) + ".h5"))
                               .string();
  {
    io::CheckpointWriter out(path);
    first.write_checkpoint(out);
    out.commit();
  }
  second.restore_checkpoint(io::CheckpointReader(path));
  std::filesystem::remove(path);
  EXPECT_EQ(second.time(), first.time());
  EXPECT_EQ(second.step(), first.step());
  for (int i = 0; i < after; ++i) {
    step_alone(first, state, dt0);
    step_alone(second, state, dt0);
  }
  EXPECT_EQ(second.time(), first.time());
  expect_identical_particles(
      const_cast<std::decay_t<decltype(first.particles())>&>(first.particles()),
      const_cast<std::decay_t<decltype(second.particles())>&>(second.particles()));
}

}  // namespace porosph::testing
