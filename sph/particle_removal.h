// Removing particles from a phase's structure of arrays, shared by the water and soil solvers:
// free particles that leave (the domain, an outflow zone) and fixed particles whose wall is taken
// away at a given time (a gate). Works on any structure of arrays with n_free, size(), mass,
// remove_at and for_each_array(fn) (fluid_solver/water_particles.h, soil_solver/soil_particles.h).
// `keep` is the caller's scratch buffer (no allocation once it has grown).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace porosph::sph {

/// Keeps the particles with keep[i] != 0, in order, in every array; n_free follows. Returns the
/// number removed.
template <class Particles>
std::size_t compact_particles(Particles& P, const std::vector<std::uint8_t>& keep) {
  std::size_t kept_free = 0;
  for (std::size_t i = 0; i < P.n_free; ++i) kept_free += keep[i] != 0;
  const std::size_t n = P.size();
  P.for_each_array([&](auto& array) {
    std::size_t w = 0;
    for (std::size_t r = 0; r < n; ++r)
      if (keep[r]) array[w++] = array[r];
    array.resize(w);
  });
  P.n_free = kept_free;
  return n - P.size();
}

/// Removes the free particles i in [0, n_free) with leaves(i), adding their mass to
/// `removed_mass` and calling removing(i) for each before it goes (to book what it carried away,
/// e.g. its momentum). Returns how many were removed. A parallel count first: nothing is touched
/// in the common step where no particle leaves.
template <class Particles, class Leaves, class Removing>
std::size_t remove_free_particles(Particles& P, const Leaves& leaves,
                                  std::vector<std::uint8_t>& keep, double& removed_mass,
                                  const Removing& removing) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  std::int64_t leaving = 0;
#pragma omp parallel for schedule(static) reduction(+ : leaving)
  for (std::int64_t i = 0; i < n; ++i) leaving += leaves(static_cast<std::size_t>(i)) ? 1 : 0;
  if (leaving == 0) return 0;
  keep.assign(P.size(), 1);
  for (std::int64_t i = 0; i < n; ++i) {
    if (!leaves(static_cast<std::size_t>(i))) continue;
    keep[i] = 0;
    removed_mass += P.mass[i];
    removing(static_cast<std::size_t>(i));
  }
  return compact_particles(P, keep);
}

/// remove_free_particles() without a per-particle hook.
template <class Particles, class Leaves>
std::size_t remove_free_particles(Particles& P, const Leaves& leaves,
                                  std::vector<std::uint8_t>& keep, double& removed_mass) {
  return remove_free_particles(P, leaves, keep, removed_mass, [](std::size_t) {});
}

/// Removes the fixed particles whose remove_at time (>= 0) is <= `time`. Returns the earliest
/// removal time still pending (< 0: none).
template <class Particles>
double remove_expired_fixed_particles(Particles& P, double time, std::vector<std::uint8_t>& keep) {
  keep.assign(P.size(), 1);
  double next = -1.0;
  for (std::size_t w = P.n_free; w < P.size(); ++w) {
    const double t = P.remove_at[w];
    if (t < 0.0) continue;
    if (t <= time) {
      keep[w] = 0;
    } else if (next < 0.0 || t < next) {
      next = t;
    }
  }
  compact_particles(P, keep);
  return next;
}

}  // namespace porosph::sph
