// The soil phase's right-hand side, in two neighbour passes (gather form, one OpenMP task per
// particle, no atomics). Pass 1, the accelerations, sums over the neighbours j of particle i
//   eq. 5 / 16  stress divergence (sigma_i + sigma_j)/(rho_i rho_j)   stress_divergence.h
//   eq. 16      Monaghan artificial viscosity (dissipative sign)       soil_artificial_viscosity.h
//   eq. 16      Gray-Monaghan artificial stress (R_i + R_j) f^n        artificial_stress.h
// plus gravity. Pass 2, the kinematics, run after the velocity update of the step (so that the
// stress is updated with the new velocities: the symplectic ordering that keeps the explicit
// velocity-stress system stable; with both from the old state the elastic waves grow), sums
//   eq. 7-8     velocity gradient L (strain rate and spin)             velocity_gradient.h
//   continuity  drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij
// Fixed neighbours enter with their extrapolated stress and density (soil_walls.h), and with their
// mirrored velocity (all of it for no-slip, its normal part for free-slip) in L and the viscosity;
// against a straight wall, eq. 5, L and the continuity equation sum over mirror images of the soil
// instead (soil.wall_stress = "images", wall_mirror.h).
// Terms that are off are compiled out of the pair loop (template flags).
#pragma once

#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {

struct SoilRateSummary {
  double max_speed = 0.0;               ///< max |v_i| over free soil particles
  double max_total_acceleration = 0.0;  ///< max |dv_i/dt + interaction_i| (for eq. 21)
};

/// R of every particle whose material asks for artificial stress (zero elsewhere); walls take the
/// R of their extrapolated stress. Call after update_soil_wall_state.
template <int D>
void update_artificial_stress(const SoilParams<D>& params, SoilParticles<D>& P);

/// Pass 1: fills acceleration of the free soil particles, its fixed neighbours' share
/// wall_acceleration and submergence_acceleration (soil_particles.h). Fixed particles must be up to
/// date (update_soil_wall_state, then update_artificial_stress when on).
template <int D, class Kernel>
SoilRateSummary compute_soil_rates(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                                   const SoilParams<D>& params, SoilParticles<D>& P);

/// Pass 2: fills velocity_gradient and density_rate of the free soil particles from the current
/// velocities (positions unchanged since the neighbour search).
template <int D, class Kernel>
void compute_soil_kinematics(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                             const SoilParams<D>& params, SoilParticles<D>& P);

}  // namespace porosph::soil
