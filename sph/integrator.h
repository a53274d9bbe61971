// Modified Verlet time integration (Verlet 1967 as modified for SPH by Monaghan 1989 and used by
// the seed paper and DualSPHysics, Dominguez et al. 2022 eq. 28-31), for one particle:
//   x^{n+1}   = x^n + dt v^n + dt^2/2 a^n
//   v^{n+1}   = v^{n-1} + 2 dt a^n        (Verlet step)
//   v^{n+1}   = v^n     + dt a^n          (Euler step: the first step and every euler_every steps,
//                                          which re-couples the odd and even time levels)
//   rho^{n+1} likewise from drho/dt.
// After the step the "previous" value holds the old level n.
#pragma once

#include <cstdint>

#include "sph/vector.h"

namespace porosph::sph {

/// True for the Euler steps of the modified Verlet scheme: the first step (step == 0) and every
/// euler_every-th step (euler_every <= 0: only the first).
inline bool is_euler_step(std::uint64_t step, int euler_every) {
  if (step == 0) return true;
  return euler_every > 0 && step % static_cast<std::uint64_t>(euler_every) == 0;
}

/// One modified-Verlet step of a vector quantity pair (position x, velocity v) with acceleration a.
template <int D>
inline void verlet_step(Vec<D>& x, Vec<D>& v, Vec<D>& v_previous, const Vec<D>& a, double dt,
                        bool euler) {
  x += dt * v + (0.5 * dt * dt) * a;
  const Vec<D> v_next = euler ? Vec<D>(v + dt * a) : Vec<D>(v_previous + (2.0 * dt) * a);
  v_previous = v;
  v = v_next;
}

/// One modified-Verlet step of a scalar (e.g. density) with rate dq/dt.
inline void verlet_step_scalar(double& q, double& q_previous, double rate, double dt, bool euler) {
  const double next = euler ? q + dt * rate : q_previous + 2.0 * dt * rate;
  q_previous = q;
  q = next;
}

}  // namespace porosph::sph
