// The water solver's particles at t = 0, from the scene's water blocks, inflow zones and walls.
#pragma once

#include "fluid_solver/flow_zones.h"
#include "fluid_solver/open_reservoirs.h"
#include "fluid_solver/water_params.h"
#include "fluid_solver/water_particles.h"
#include "scene/scene.h"
#include "sph/domain_box.h"
#include "sph/wall_occluders.h"

namespace porosph::water {

template <int D>
struct InitialParticles {
  WaterParticles<D> particles;
  double next_wall_removal = -1.0;  ///< earliest wall removal time [s] (< 0: none)
  /// The thin walls filled on both sides (sph/wall_occluders.h; water.thin_walls = "separating"),
  /// indexed as the particles' wall_side tags.
  sph::WallOccluders<D> occluders;
};

/// Water from scene.water.blocks (lattice points inside a wall acting on water or inside an inflow
/// zone skipped, points outside the domain or beyond a periodic face dropped), then the lattice of
/// every inflow zone (zone particles, filled like a block, velocity zones.velocity(z, 0)), then the
/// wall particles of the walls acting on water (points beyond a periodic axis' range dropped).
/// Densities: hydrostatic per connected water body, zones included, the walls covering the water
/// beneath them (hydrostatic_initial.h), when
/// params.hydrostatic_initial, else rho0; with water.initial_velocity = "taylor_green" the
/// Taylor-Green velocity and pressure on top (taylor_green_initial.h); masses m = rho(t=0) dp^D;
/// ids 0..n-1. The arrays are reserved one zone-load ahead for the particles the zones will emit.
template <int D>
InitialParticles<D> initial_particles(const scene::Scene& s, const WaterParams<D>& params,
                                      const sph::DomainBox<D>& box, const FlowZones<D>& zones,
                                      const OpenReservoirs<D>& open);

}  // namespace porosph::water
