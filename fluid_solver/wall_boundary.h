// Fixed wall particles of Adami, Hu & Adams (2012), "A generalized wall boundary condition for
// smoothed particle hydrodynamics", J. Comput. Phys. 231, 7057-7075, eq. 22-23 and 27-28.
// Each step, every wall particle w takes the state extrapolated from its water neighbours f:
//   p_w   = (sum_f p_f W_wf + (g - a_w) . sum_f rho_f x_wf W_wf) / sum_f W_wf   (a_w = 0: fixed)
//   rho_w = inverse of eq. 4 at p_w
//   v~_w  = 2 v_w - sum_f v_f W_wf / sum_f W_wf   (no-slip: velocity seen by the viscous terms)
//   m_w   = rho_w dp^D   (a wall particle keeps the volume of its lattice site, V_w = m_w / rho_w
//                         = dp^D, so the wall's pressure force is not under-estimated where rho_w
//                         > rho0; with a constant m_w = rho0 dp^D a 0.6 m still tank settled to
//                         pressures 2 % too high at the bottom)
// A wall particle with no water neighbour keeps p = 0, rho = rho0, v~ = v_w.
#pragma once

#include <cstdint>

#include "fluid_solver/viscous_level.h"
#include "fluid_solver/water_params.h"
#include "fluid_solver/water_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::water {

/// Updates pressure, density, mass, sound speed and wall_velocity of the wall particles of P;
/// wall_velocity from the water velocities at `level`, those the viscous terms act on
/// (viscous_level.h).
template <int D, class Kernel>
void update_wall_state(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                       const WaterParams<D>& params, WaterParticles<D>& P,
                       ViscousLevel level = ViscousLevel::Current) {
  using Vec = sph::Vec<D>;
  const std::int64_t n0 = static_cast<std::int64_t>(P.n_free);
  const std::int64_t n1 = static_cast<std::int64_t>(P.size());
  const Vec wall_acceleration = Vec::Zero();  // fixed walls
  const Vec body = params.gravity - wall_acceleration;
  const TaitEos& eos = params.eos;
  const Vec* water_v =
      level == ViscousLevel::Previous ? P.velocity_previous.data() : P.velocity.data();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t w = n0; w < n1; ++w) {
    double sum_w = 0.0, sum_pw = 0.0;
    Vec sum_rho_x_w = Vec::Zero(), sum_v_w = Vec::Zero();
    for (auto it = neighbours.begin(w); it != neighbours.mid(w); ++it) {  // water neighbours only
      const double kw = kernel.w(it->r);
      sum_w += kw;
      sum_pw += P.pressure[it->b] * kw;
      sum_rho_x_w += (P.density[it->b] * kw) * it->x_ab;
      sum_v_w += kw * water_v[it->b];
    }
    if (sum_w > 0.0) {
      P.pressure[w] = (sum_pw + body.dot(sum_rho_x_w)) / sum_w;
      P.density[w] = eos.density(P.pressure[w]);
      P.wall_velocity[w] = 2.0 * P.velocity[w] - sum_v_w / sum_w;
    } else {
      P.pressure[w] = 0.0;
      P.density[w] = eos.rho0();
      P.wall_velocity[w] = P.velocity[w];
    }
    P.sound_speed[w] = eos.sound_speed(P.density[w]);
    P.mass[w] = P.density[w] * params.volume;  // fixed volume dp^D
  }
}

}  // namespace porosph::water
