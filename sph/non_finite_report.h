// The message a solver sends when a particle's state turns non-finite (NaN / Inf): which field,
// which particle, where, when. Shared by the water and soil solvers.
#pragma once

#include <sstream>
#include <string>

#include "sph/vector.h"

namespace porosph::sph {

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
