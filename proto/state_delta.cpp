#include "proto/state_delta.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace porosph::coupling {
namespace {

template <class T>
bool same_bits(const T* a, const T* b, std::size_t count) {
  return count == 0 || std::memcmp(a, b, count * sizeof(T)) == 0;
}

template <class T>
bool same_vector(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && same_bits(a.data(), b.data(), a.size());
}

/// Copies the first `count` values of `from` over those of `to` (same sizes).
template <class T>
void copy_prefix(const std::vector<T>& from, std::vector<T>& to, std::size_t count) {
  std::copy(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(count), to.begin());
}

/// D of a state whose per-particle arrays fit n particles (position and velocity n x D, density
/// n, porosity n or none); 0 when they do not (or n = 0).
std::size_t consistent_dimension(const StepState& s) {
  const std::size_t n = s.overlap_id.size();
  if (n == 0 || s.overlap_position.size() % n != 0) return 0;
  const std::size_t d = s.overlap_position.size() / n;
  const bool fits = d > 0 && s.overlap_velocity.size() == n * d && s.overlap_density.size() == n &&
                    s.overlap_mass.size() == n &&
                    (s.overlap_porosity.empty() || s.overlap_porosity.size() == n) &&
                    (s.overlap_material.empty() || s.overlap_material.size() == n) &&
                    (s.overlap_update_base.empty() || s.overlap_update_base.size() == n * d) &&
                    s.overlap_update_rate.size() == s.overlap_update_base.size();
  return fits ? d : 0;
}

/// True when particle i has bitwise the same per-step values in `a` and `b`.
bool same_particle(const StepState& a, const StepState& b, std::size_t i, std::size_t d) {
  return same_bits(a.overlap_position.data() + i * d, b.overlap_position.data() + i * d, d) &&
         same_bits(a.overlap_velocity.data() + i * d, b.overlap_velocity.data() + i * d, d) &&
         same_bits(a.overlap_density.data() + i, b.overlap_density.data() + i, 1) &&
         (a.overlap_porosity.empty() ||
          same_bits(a.overlap_porosity.data() + i, b.overlap_porosity.data() + i, 1)) &&
         (a.overlap_update_base.empty() || (same_bits(a.overlap_update_base.data() + i * d,
                                                      b.overlap_update_base.data() + i * d, d) &&
                                            same_bits(a.overlap_update_rate.data() + i * d,
                                                      b.overlap_update_rate.data() + i * d, d)));
}

[[noreturn]] void throw_misfit(const std::string& phase, const std::string& what) {
  throw std::runtime_error(
      "the " + phase + " solver sent a state that does not fit its previous " +
      "one (protocol violation, docs/solver-protocol.md \"State deltas\"): " + what);
}

}  // namespace

StateDelta StateDeltaEncoder::next(const StepState& state) {
  StateDelta delta;
  const std::size_t n = state.overlap_id.size();
  const std::size_t d = consistent_dimension(state);
  delta.same_set = have_last_ && d > 0 && consistent_dimension(last_) == d &&
                   same_vector(state.overlap_id, last_.overlap_id) &&
                   same_vector(state.overlap_mass, last_.overlap_mass) &&
                   same_vector(state.overlap_material, last_.overlap_material) &&
                   state.overlap_porosity.size() == last_.overlap_porosity.size() &&
                   state.overlap_update_base.size() == last_.overlap_update_base.size();
  if (delta.same_set) {
    std::size_t tail = 0;
    while (tail < n && same_particle(state, last_, n - 1 - tail, d)) ++tail;
    delta.unchanged_tail = static_cast<std::uint32_t>(tail);
    const std::size_t moved = n - tail;
    copy_prefix(state.overlap_position, last_.overlap_position, moved * d);
    copy_prefix(state.overlap_velocity, last_.overlap_velocity, moved * d);
    copy_prefix(state.overlap_density, last_.overlap_density, moved);
    if (!state.overlap_porosity.empty()) {
      copy_prefix(state.overlap_porosity, last_.overlap_porosity, moved);
    }
    if (!state.overlap_update_base.empty()) {
      copy_prefix(state.overlap_update_base, last_.overlap_update_base, moved * d);
      copy_prefix(state.overlap_update_rate, last_.overlap_update_rate, moved * d);
    }
  } else {
    last_.overlap_id = state.overlap_id;
    last_.overlap_position = state.overlap_position;
    last_.overlap_velocity = state.overlap_velocity;
    last_.overlap_density = state.overlap_density;
    last_.overlap_mass = state.overlap_mass;
    last_.overlap_porosity = state.overlap_porosity;
    last_.overlap_material = state.overlap_material;
    last_.overlap_update_base = state.overlap_update_base;
    last_.overlap_update_rate = state.overlap_update_rate;
  }
  have_last_ = true;
  return delta;
}

void apply_state_delta(StepState& full, StepState& received, int dimension,
                       const std::string& phase) {
  const StateDelta delta = received.delta;
  if (!delta.same_set) {
    if (delta.unchanged_tail != 0) throw_misfit(phase, "an unchanged tail without the same set");
    std::swap(full, received);
    return;
  }
  const std::size_t n = full.overlap_id.size();
  const std::size_t d = static_cast<std::size_t>(dimension);
  if (n > 0 && consistent_dimension(full) != d) throw_misfit(phase, "no complete previous state");
  if (delta.unchanged_tail > n) {
    throw_misfit(phase, "an unchanged tail of " + std::to_string(delta.unchanged_tail) +
                            " particles, " + std::to_string(n) + " before");
  }
  const std::size_t moved = n - delta.unchanged_tail;
  const bool porosity = !full.overlap_porosity.empty();
  const bool update = !full.overlap_update_base.empty();
  if (!received.overlap_id.empty() || !received.overlap_mass.empty() ||
      !received.overlap_material.empty()) {
    throw_misfit(phase, "ids, masses or materials sent with the same set");
  }
  if (received.overlap_position.size() != moved * d ||
      received.overlap_velocity.size() != moved * d || received.overlap_density.size() != moved ||
      received.overlap_porosity.size() != (porosity ? moved : 0) ||
      received.overlap_update_base.size() != (update ? moved * d : 0) ||
      received.overlap_update_rate.size() != (update ? moved * d : 0)) {
    throw_misfit(phase, "per-particle arrays for other than the " + std::to_string(moved) +
                            " particles that may have changed");
  }
  if (delta.unchanged_tail == 0) {
    std::swap(full.overlap_position, received.overlap_position);
    std::swap(full.overlap_velocity, received.overlap_velocity);
    std::swap(full.overlap_density, received.overlap_density);
    std::swap(full.overlap_porosity, received.overlap_porosity);
    std::swap(full.overlap_update_base, received.overlap_update_base);
    std::swap(full.overlap_update_rate, received.overlap_update_rate);
  } else {
    copy_prefix(received.overlap_position, full.overlap_position, moved * d);
    copy_prefix(received.overlap_velocity, full.overlap_velocity, moved * d);
    copy_prefix(received.overlap_density, full.overlap_density, moved);
    if (porosity) copy_prefix(received.overlap_porosity, full.overlap_porosity, moved);
    if (update) {
      copy_prefix(received.overlap_update_base, full.overlap_update_base, moved * d);
      copy_prefix(received.overlap_update_rate, full.overlap_update_rate, moved * d);
    }
  }
  full.step = received.step;
  full.time = received.time;
  full.dt_limit = received.dt_limit;
  full.dt_cfl = received.dt_cfl;
  full.dt_viscous = received.dt_viscous;
  full.dt_force = received.dt_force;
  std::swap(full.region_min, received.region_min);
  std::swap(full.region_max, received.region_max);
  std::swap(full.diagnostics, received.diagnostics);
  full.checkpoint_written = received.checkpoint_written;
  full.delta = delta;
}

}  // namespace porosph::coupling
