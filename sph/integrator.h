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

/// One modified-Verlet step where the acceleration a = a_rest + a_drag has a drag part that is
/// linear in the particle's own velocity with rate lambda >= 0 [1/s] (d a_drag / d v = -lambda,
/// a_drag evaluated at v^n): the drag is taken implicitly at the new level, so that lambda dt >> 1
/// (a drag relaxation time far below dt) stays stable and strongly damped, and a steady state
/// (a = 0) is kept exactly:
///   Euler:  v^{n+1} = v^n + dt a / (1 + lambda dt)
///   Verlet: v^{n+1} = v^{n-1} + 2 dt [a - lambda (v^{n+1} - v^n)]
///           = [v^{n-1} + 2 dt (a + lambda v^n)] / (1 + 2 lambda dt)
/// (toward a partner at rest the velocity falls by 1 / (1 + lambda dt) per Euler step and by
/// 1 / (1 + 2 lambda dt) per two Verlet steps, where the explicit scheme grows). The position uses
/// the acceleration the velocity update implies. lambda = 0 is verlet_step().
template <int D>
inline void verlet_step_implicit_drag(Vec<D>& x, Vec<D>& v, Vec<D>& v_previous, const Vec<D>& a,
                                      double lambda, double dt, bool euler) {
  if (!(lambda > 0.0)) {
    verlet_step<D>(x, v, v_previous, a, dt, euler);
    return;
  }
  const double l_dt = lambda * dt;
  Vec<D> v_next, a_used;
  if (euler) {
    v_next = v + (dt / (1.0 + l_dt)) * a;
    a_used = a / (1.0 + l_dt);
  } else {
    v_next = (v_previous + (2.0 * dt) * (a + lambda * v)) / (1.0 + 2.0 * l_dt);
    a_used = a - lambda * (v_next - v);
  }
  x += dt * v + (0.5 * dt * dt) * a_used;
  v_previous = v;
  v = v_next;
}

/// One modified-Verlet step with the particle's own acceleration `a_own` and a coupling
/// acceleration `a_coupling` whose impulse over the step must be exactly dt a_coupling (a partner
/// solver books and receives its opposite: the coupler's soil-water drag). The Verlet chain
/// carries the own forces over the span dt_previous + dt from t^{n-1} to t^{n+1} (2 dt at a
/// constant step; the centred difference of a variable step) and the coupling over dt:
///   Euler:  v^{n+1} = v^n + dt (a_own + a_coupling)
///   Verlet: v^{n+1} = q^n + (dt_previous + dt) a_own + dt a_coupling
///   q^{n+1} = v^n + dt a_coupling        (the stored previous velocity, "folded")
/// With v = u + w, u the Verlet chain of the own forces and w the running sum of the coupling
/// impulses, q^n = u^{n-1} + w^n: the own forces conserve momentum on each chain, and the
/// momentum changes by exactly dt sum m a_coupling per step, on Euler and Verlet steps alike.
/// A steady state in which a stiff coupling balances the own force is kept whatever dt does
/// (the variable span is what makes that hold when dt changes, e.g. the short last step).
/// a_coupling = 0 at a constant step is verlet_step(). The position uses a_own + a_coupling.
template <int D>
inline void verlet_step_coupled(Vec<D>& x, Vec<D>& v, Vec<D>& v_previous, const Vec<D>& a_own,
                                const Vec<D>& a_coupling, double dt, double dt_previous,
                                bool euler) {
  x += dt * v + (0.5 * dt * dt) * (a_own + a_coupling);
  const Vec<D> v_next = euler ? Vec<D>(v + dt * (a_own + a_coupling))
                              : Vec<D>(v_previous + (dt_previous + dt) * a_own + dt * a_coupling);
  v_previous = v + dt * a_coupling;
  v = v_next;
}

/// One modified-Verlet step of a scalar (e.g. density) with rate dq/dt.
inline void verlet_step_scalar(double& q, double& q_previous, double rate, double dt, bool euler) {
  const double next = euler ? q + dt * rate : q_previous + 2.0 * dt * rate;
  q_previous = q;
  q = next;
}

}  // namespace porosph::sph
