// The per-step totals a solver reports of its free particles (docs/design.md section 1,
// diagnostics): mass, momentum, kinetic energy, largest speed and bounding box, in one parallel
// pass. Shared by the water and soil solvers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "sph/vector.h"

namespace porosph::sph {

template <int D>
struct FreeParticleTotals {
  double mass = 0.0, kinetic_energy = 0.0, max_speed = 0.0;
  double momentum[D] = {};
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());  ///< +inf: none
  Vec<D> hi = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
};

/// Totals over particles [0, n) of the arrays (position, velocity, mass).
template <int D>
FreeParticleTotals<D> free_particle_totals(const Vec<D>* position, const Vec<D>* velocity,
                                           const double* mass, std::size_t n) {
  const std::int64_t count = static_cast<std::int64_t>(n);
  double m_sum = 0.0, energy = 0.0, max_v2 = 0.0;
  double momentum[D] = {}, lo[D], hi[D];
  std::fill(lo, lo + D, std::numeric_limits<double>::infinity());
  std::fill(hi, hi + D, -std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static) reduction(+ : m_sum, energy, momentum[:D]) \
    reduction(max : max_v2, hi[:D]) reduction(min : lo[:D])
  for (std::int64_t i = 0; i < count; ++i) {
    const double v2 = velocity[i].squaredNorm();
    m_sum += mass[i];
    energy += 0.5 * mass[i] * v2;
    max_v2 = std::max(max_v2, v2);
    for (int k = 0; k < D; ++k) {
      momentum[k] += mass[i] * velocity[i][k];
      lo[k] = std::min(lo[k], position[i][k]);
      hi[k] = std::max(hi[k], position[i][k]);
    }
  }
  FreeParticleTotals<D> t;
  t.mass = m_sum;
  t.kinetic_energy = energy;
  t.max_speed = std::sqrt(max_v2);
  for (int k = 0; k < D; ++k) {
    t.momentum[k] = momentum[k];
    t.lo[k] = lo[k];
    t.hi[k] = hi[k];
  }
  return t;
}

}  // namespace porosph::sph
