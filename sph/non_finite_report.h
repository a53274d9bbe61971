// The message a solver sends when a particle's state turns non-finite (NaN / Inf): which field,
// which particle, where, when. Shared by the water and soil solvers.
#pragma once

#include <cstddef>
#include <sstream>
#include <string>

#include "sph/vector.h"

namespace porosph::sph {

/// True when all `count` values are finite. One branch-free pass that vectorises (0 x is 0 for a
/// finite x, NaN for NaN or Inf; the reduction order does not matter for that): the solvers'
/// per-step checks run it first and search for the bad particle only when it fails.
inline bool all_finite(const double* values, std::size_t count) {
  double probe = 0.0;
#pragma omp simd reduction(+ : probe)
  for (std::size_t k = 0; k < count; ++k) probe += 0.0 * values[k];
  return probe == 0.0;
}

/// "non-finite <field> of <kind> particle <id> (x = ...; v = ...; rho = ...) at step N, t = T s".
template <int D>
std::string non_finite_message(const char* field, const char* kind, long long id, const Vec<D>& x,
                               const Vec<D>& v, double rho, unsigned long long step, double time) {
  std::ostringstream msg;
  msg << "non-finite " << field << " of " << kind << " particle " << id << " (x = ";
  for (int k = 0; k < D; ++k) msg << (k ? ", " : "") << x[k];
  msg << "; v = ";
  for (int k = 0; k < D; ++k) msg << (k ? ", " : "") << v[k];
  msg << "; rho = " << rho << ") at step " << step << ", t = " << time << " s";
  return msg.str();
}

}  // namespace porosph::sph
