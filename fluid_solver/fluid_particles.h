// Particles of the water solver, structure of arrays. Indices [0, n_free) are water particles,
// [n_free, size()) fixed wall particles. Ids are stable across removal and re-ordering.
#pragma once

#include <cstdint>
#include <vector>

#include "sph/vector.h"

namespace porosph::fluid {

template <int D>
struct FluidParticles {
  using Vec = sph::Vec<D>;
  std::size_t n_free = 0;

  std::vector<Vec> position, velocity;
  std::vector<Vec> velocity_previous;  ///< v^{n-1} of the modified Verlet scheme
  std::vector<Vec> acceleration;       ///< internal dv/dt of this step (incl. gravity)
  std::vector<Vec> interaction;        ///< acceleration added by the coupler (last step)
  std::vector<Vec> wall_velocity;      ///< walls: velocity seen by viscous terms (Adami 2012)
  std::vector<double> density, density_previous, density_rate;
  std::vector<double> pressure, sound_speed, mass;
  std::vector<double> remove_at;  ///< walls: removal time [s] (< 0: never); water: -1
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> fixed;  ///< 1 for wall particles (snapshot field "fixed")

  std::size_t size() const { return position.size(); }
  std::size_t wall_count() const { return size() - n_free; }

  /// Calls fn(array) on every per-particle array (to resize, permute or compact them together).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(position), fn(velocity), fn(velocity_previous), fn(acceleration), fn(interaction);
    fn(wall_velocity), fn(density), fn(density_previous), fn(density_rate), fn(pressure);
    fn(sound_speed), fn(mass), fn(remove_at), fn(id), fn(fixed);
  }

  /// Keeps the particles with keep[i] != 0, in order; n_free follows. Returns the number removed.
  std::size_t compact(const std::vector<std::uint8_t>& keep) {
    std::size_t kept_free = 0;
    for (std::size_t i = 0; i < n_free; ++i) kept_free += keep[i] != 0;
    const std::size_t n = size();
    for_each_array([&](auto& array) {
      std::size_t w = 0;
      for (std::size_t r = 0; r < n; ++r)
        if (keep[r]) array[w++] = array[r];
      array.resize(w);
    });
    const std::size_t removed = n - size();
    n_free = kept_free;
    return removed;
  }

  /// Re-orders every array: new[i] = old[order[i]]; `order` must keep water before walls.
  void permute(const std::vector<std::int32_t>& order) {
    permute_array(position, order, scratch_vec_), permute_array(velocity, order, scratch_vec_);
    permute_array(velocity_previous, order, scratch_vec_);
    permute_array(acceleration, order, scratch_vec_);
    permute_array(interaction, order, scratch_vec_);
    permute_array(wall_velocity, order, scratch_vec_);
    permute_array(density, order, scratch_f64_),
        permute_array(density_previous, order, scratch_f64_);
    permute_array(density_rate, order, scratch_f64_), permute_array(pressure, order, scratch_f64_);
    permute_array(sound_speed, order, scratch_f64_), permute_array(mass, order, scratch_f64_);
    permute_array(remove_at, order, scratch_f64_), permute_array(id, order, scratch_i64_);
    permute_array(fixed, order, scratch_u8_);
  }

 private:
  template <class T>
  static void permute_array(std::vector<T>& array, const std::vector<std::int32_t>& order,
                            std::vector<T>& scratch) {
    scratch.resize(order.size());
    const std::int64_t n = static_cast<std::int64_t>(order.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) scratch[i] = array[order[i]];
    array.swap(scratch);
  }

  std::vector<Vec> scratch_vec_;
  std::vector<double> scratch_f64_;
  std::vector<std::int64_t> scratch_i64_;
  std::vector<std::uint8_t> scratch_u8_;
};

}  // namespace porosph::fluid
