// State deltas (proto/state_delta.h): what the client leaves out of a state, and that the coupler
// completes every state exactly (bitwise) from the previous one, through the real wire format.
#include "proto/state_delta.h"

#include <gtest/gtest.h>

#include <string>

#include "proto/wire_convert.h"

namespace porosph::coupling {
namespace {

/// n soil-like particles in 2D, all fields distinct.
StepState soil_state(std::size_t n, double shift) {
  StepState s;
  s.step = 3;
  s.time = 0.5 + shift;
  s.dt_limit = 1e-5;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    s.overlap_id.push_back(static_cast<std::int64_t>(100 + i));
    s.overlap_position.insert(s.overlap_position.end(), {0.01 * x + shift, 0.02 * x});
    s.overlap_velocity.insert(s.overlap_velocity.end(), {shift, -0.5 * x});
    s.overlap_density.push_back(1800.0 + x);
    s.overlap_mass.push_back(1e-3 * (1.0 + x));
    s.overlap_porosity.push_back(0.4 + 1e-3 * x);
    s.overlap_material.push_back(static_cast<std::int32_t>(i % 3));
  }
  s.region_min = {-1.0, -2.0};
  s.region_max = {1.0 + shift, 2.0};
  s.diagnostics.mass = 2.5;
  s.diagnostics.kinetic_energy = shift;
  s.diagnostics.momentum = {shift, 0.0};
  return s;
}

/// The particles from `first` on keep the values of `base` (fixed / at rest); the others moved.
StepState moved_prefix(const StepState& base, std::size_t first, double shift) {
  StepState s = base;
  for (std::size_t i = 0; i < first; ++i) {
    s.overlap_position[2 * i] += shift;
    s.overlap_velocity[2 * i + 1] += shift;
    s.overlap_density[i] += shift;
    s.overlap_porosity[i] += 1e-3 * shift;
  }
  s.time += shift;
  s.diagnostics.kinetic_energy += shift;
  return s;
}

void expect_same_state(const StepState& a, const StepState& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.dt_limit, b.dt_limit);
  EXPECT_EQ(a.overlap_id, b.overlap_id);
  EXPECT_EQ(a.overlap_position, b.overlap_position);  // bitwise: doubles travel as 8 bytes
  EXPECT_EQ(a.overlap_velocity, b.overlap_velocity);
  EXPECT_EQ(a.overlap_density, b.overlap_density);
  EXPECT_EQ(a.overlap_mass, b.overlap_mass);
  EXPECT_EQ(a.overlap_porosity, b.overlap_porosity);
  EXPECT_EQ(a.overlap_material, b.overlap_material);
  EXPECT_EQ(a.region_max, b.region_max);
  EXPECT_EQ(a.diagnostics.kinetic_energy, b.diagnostics.kinetic_energy);
  EXPECT_EQ(a.diagnostics.momentum, b.diagnostics.momentum);
}

/// Sends `state` as the client does and completes it as the coupler does: returns the delta used.
StateDelta send_and_complete(StateDeltaEncoder& encoder, const StepState& state,
                             StepState& coupler_view, std::size_t* values_sent = nullptr) {
  const StateDelta delta = encoder.next(state);
  wire::StepState message;
  wire::to_wire(state, delta, message);
  wire::StepState parsed;
  EXPECT_TRUE(parsed.ParseFromString(message.SerializeAsString()));
  StepState received;
  wire::from_wire(parsed, received);
  if (values_sent != nullptr) {
    *values_sent = received.overlap_id.size() + received.overlap_position.size() +
                   received.overlap_velocity.size() + received.overlap_density.size() +
                   received.overlap_mass.size() + received.overlap_porosity.size() +
                   received.overlap_material.size();
  }
  apply_state_delta(coupler_view, received, 2, "soil");
  return delta;
}

TEST(StateDelta, FirstStateGoesWhole) {
  StateDeltaEncoder encoder;
  const StateDelta delta = encoder.next(soil_state(5, 0.0));
  EXPECT_FALSE(delta.same_set);
  EXPECT_EQ(delta.unchanged_tail, 0u);
}

TEST(StateDelta, FindsTheSameSetAndTheUnchangedTail) {
  StateDeltaEncoder encoder;
  const StepState first = soil_state(6, 0.0);
  encoder.next(first);
  // Particles 0-3 moved, 4-5 kept every per-step value: the tail is 2.
  StateDelta delta = encoder.next(moved_prefix(first, 4, 0.25));
  EXPECT_TRUE(delta.same_set);
  EXPECT_EQ(delta.unchanged_tail, 2u);
  // Nothing changed since: the whole set is the tail.
  delta = encoder.next(moved_prefix(first, 4, 0.25));
  EXPECT_TRUE(delta.same_set);
  EXPECT_EQ(delta.unchanged_tail, 6u);
  // Only the last particle's porosity changed: no tail.
  StepState porosity_changed = moved_prefix(first, 4, 0.25);
  porosity_changed.overlap_porosity[5] += 1e-6;
  delta = encoder.next(porosity_changed);
  EXPECT_TRUE(delta.same_set);
  EXPECT_EQ(delta.unchanged_tail, 0u);
}

TEST(StateDelta, AChangedSetGoesWhole) {
  StateDeltaEncoder encoder;
  const StepState first = soil_state(4, 0.0);
  encoder.next(first);
  StepState reordered = first;
  std::swap(reordered.overlap_id[0], reordered.overlap_id[1]);
  EXPECT_FALSE(encoder.next(reordered).same_set);
  StepState new_mass = reordered;
  new_mass.overlap_mass[2] *= 2.0;
  EXPECT_FALSE(encoder.next(new_mass).same_set);
  StepState new_material = new_mass;
  new_material.overlap_material[3] = 7;
  EXPECT_FALSE(encoder.next(new_material).same_set);
  EXPECT_FALSE(encoder.next(soil_state(5, 0.0)).same_set);  // one particle more
  EXPECT_FALSE(encoder.next(StepState{}).same_set);         // none: nothing to leave out
}

TEST(StateDelta, TheCouplerSeesEveryStateExactlyAndFewerValuesTravel) {
  // A run of states: a fixed tail of 3, a set change at step 3, then a tail again. After every
  // message the coupler's completed state must equal the solver's.
  StateDeltaEncoder encoder;
  StepState coupler_view;
  StepState state = soil_state(8, 0.0);
  std::size_t sent = 0;
  send_and_complete(encoder, state, coupler_view, &sent);
  const std::size_t whole = sent;  // 8 x (id, 2 + 2 vector values, density, mass, porosity, mat)
  EXPECT_EQ(whole, 8u * 9u);
  expect_same_state(coupler_view, state);
  for (int k = 1; k <= 5; ++k) {
    state = k == 3 ? soil_state(7, 0.1 * k) : moved_prefix(state, 5, 0.1 * k);
    const StateDelta delta = send_and_complete(encoder, state, coupler_view, &sent);
    expect_same_state(coupler_view, state);
    if (k == 3) {
      EXPECT_FALSE(delta.same_set);
      EXPECT_EQ(sent, 7u * 9u);
    } else {
      EXPECT_TRUE(delta.same_set);
      const std::size_t n = state.overlap_id.size();
      EXPECT_EQ(delta.unchanged_tail, n - 5);
      EXPECT_EQ(sent, 5u * 6u);  // position, velocity, density, porosity of 5 particles
    }
  }
}

TEST(StateDelta, AStateThatDoesNotFitIsAProtocolError) {
  StepState full = soil_state(4, 0.0);
  const auto expect_misfit = [&](StepState received) {
    StepState copy = full;
    try {
      apply_state_delta(copy, received, 2, "soil");
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("the soil solver sent a state that does not fit"),
                std::string::npos)
          << e.what();
    }
  };
  StepState tail_without_set;
  tail_without_set.delta.unchanged_tail = 1;
  expect_misfit(tail_without_set);
  StepState too_long_tail;
  too_long_tail.delta = {true, 5};
  expect_misfit(too_long_tail);
  StepState wrong_prefix = soil_state(3, 0.0);  // 3 particles' values for a tail of 2 of 4
  wrong_prefix.overlap_id.clear();
  wrong_prefix.overlap_mass.clear();
  wrong_prefix.overlap_material.clear();
  wrong_prefix.delta = {true, 2};
  expect_misfit(wrong_prefix);
  StepState ids_again = soil_state(4, 0.0);  // the same set must leave the ids out
  ids_again.delta = {true, 0};
  expect_misfit(ids_again);
}

}  // namespace
}  // namespace porosph::coupling
