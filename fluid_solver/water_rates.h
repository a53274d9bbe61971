// The water phase's right-hand side: for every water particle a (gather form, one OpenMP task per
// particle, no atomics), the sum over its neighbours b of
//   eq. 2   continuity                        continuity.h
//   eq. 3   pressure gradient                 pressure_force.h    (symmetric; difference form
//                                                                   with particle shifting)
//   eq. 3   laminar viscosity (Morris 1997,   laminar_viscosity.h     (mu > 0)
//           or water.laminar_viscosity's law)
//           Monaghan 1992 artificial visc.    artificial_viscosity.h  (alpha or beta > 0)
//   eq. 2+  delta-SPH density diffusion       density_diffusion.h     (delta > 0; water pairs only)
// plus gravity: dv_a/dt = g + sum_b (...). Wall neighbours enter with their Adami-interpolated
// pressure and density; in the viscous terms with the mirrored velocity (no-slip) or not at all
// (free-slip). Terms that are off are compiled out of the pair loop (template flags; the laminar
// law a template type).
#pragma once

#include "fluid_solver/viscous_level.h"
#include "fluid_solver/water_params.h"
#include "fluid_solver/water_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::water {

struct RateSummary {
  double max_speed = 0.0;  ///< max |v_a| over water particles
  /// max |dv_a/dt + interaction_a| over the water particles outside inflow zones (for eq. 21)
  double max_total_acceleration = 0.0;
};

/// Pressure and sound speed of the water particles from their density (eq. 4).
template <int D>
void update_water_pressure(const WaterParams<D>& params, WaterParticles<D>& P);

/// P.inverse_density = 1 / rho and P.volume = m / rho of every particle (water and walls).
template <int D>
void update_inverse_density_and_volume(WaterParticles<D>& P);

/// Fills P.inverse_density, P.volume (update_inverse_density_and_volume), P.acceleration, its
/// walls' share P.wall_acceleration and P.density_rate of the water particles. Walls must be up to
/// date (update_wall_state, at the same `level`) and water pressures too (update_water_pressure).
/// `level`: the velocities the viscous terms act on (viscous_level.h).
template <int D, class Kernel>
RateSummary compute_water_rates(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                                const WaterParams<D>& params, WaterParticles<D>& P,
                                ViscousLevel level = ViscousLevel::Current);

}  // namespace porosph::water
