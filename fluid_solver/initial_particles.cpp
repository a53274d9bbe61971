#include "fluid_solver/initial_particles.h"

#include <vector>

#include "fluid_solver/hydrostatic_initial.h"
#include "fluid_solver/moving_walls.h"
#include "fluid_solver/taylor_green_initial.h"
#include "sph/geometry.h"
#include "sph/wall_occluders.h"

namespace porosph::water {

template <int D>
InitialParticles<D> initial_particles(const scene::Scene& s, const WaterParams<D>& params,
                                      const sph::DomainBox<D>& box, const FlowZones<D>& zones,
                                      const OpenReservoirs<D>& open) {
  using Vec = sph::Vec<D>;
  const double dp = params.dp;
  const std::vector<scene::Shape> water_walls = s.walls_acting_on("water");
  auto inside_domain = [&box](const Vec& x) {
    Vec wrapped = x;
    box.wrap(wrapped);
    return !box.outside(x) && wrapped == x;
  };
  std::vector<Vec> water, walls;
  std::vector<std::int32_t> zone;
  for (const auto& block : s.water->blocks) {
    for (const Vec& x : sph::fill_block_outside_walls<D>(block, water_walls, dp)) {
      if (!inside_domain(x) || zones.inflow_at(x) >= 0) continue;
      if (open.zone_below_level(x) >= 0 || open.above_level(x)) continue;
      water.push_back(x);
      zone.push_back(-1);
    }
  }
  std::size_t zone_particles = 0;
  for (int z = 0; z < static_cast<int>(zones.inflow_count()); ++z) {
    for (const Vec& x : sph::fill_block_outside_walls<D>(zones.inflow_box(z), water_walls, dp)) {
      if (!inside_domain(x)) continue;
      water.push_back(x);
      zone.push_back(z);
      ++zone_particles;
    }
  }
  for (int r = 0; r < static_cast<int>(open.count()); ++r) {  // the buffers, below their levels
    for (const Vec& x : open.buffer_lattice(r)) {
      bool in_wall = false;
      for (const scene::Shape& wall : water_walls)
        in_wall = in_wall || sph::inside_shape<D>(wall, x, dp);
      if (in_wall || !inside_domain(x)) continue;
      water.push_back(x);
      zone.push_back(open.zone_below_level(x));
      ++zone_particles;
    }
  }
  InitialParticles<D> out;
  std::vector<double> wall_remove_at;
  std::vector<std::int32_t> wall_motion;
  const std::vector<std::int32_t> motion = MovingWalls<D>::motion_of_water_walls(s);
  std::vector<std::int32_t> wall_side;
  std::vector<Vec> wall_points, covering;  // covering: the walls' own lattices (hydrostatic_state)
  std::vector<std::int32_t> point_side;
  sph::ThinWallSet<D> thin =
      sph::thin_walls_of<D>(s, water_walls, "water", params.two_sided_thin_walls);
  for (std::size_t j = 0; j < water_walls.size(); ++j) {
    const scene::Shape& wall = water_walls[j];
    thin.fill(j, wall, params.h, dp, wall_points, point_side);
    for (std::size_t i = 0; i < wall_points.size(); ++i) {
      const Vec& x = wall_points[i];
      Vec wrapped = x;  // along periodic axes the domain itself closes the flow: no wall beyond it
      box.wrap(wrapped);
      if (wrapped != x) continue;
      walls.push_back(x);
      wall_side.push_back(point_side[i]);
      if (point_side[i] <= 0 && sph::inside_shape<D>(wall, x, dp)) covering.push_back(x);
      wall_remove_at.push_back(wall.remove_at);
      wall_motion.push_back(motion[j]);
      if (wall.remove_at >= 0.0 &&
          (out.next_wall_removal < 0.0 || wall.remove_at < out.next_wall_removal))
        out.next_wall_removal = wall.remove_at;
    }
  }
  WaterParticles<D>& P = out.particles;
  const std::size_t n = water.size() + walls.size();
  P.n_free = water.size();
  P.reserve(n + zone_particles);
  P.for_each_array([n](auto& array) { array.resize(n); });
  for (std::size_t i = 0; i < n; ++i) {
    const bool wall = i >= P.n_free;
    P.position[i] = wall ? walls[i - P.n_free] : water[i];
    P.zone[i] = wall ? -1 : zone[i];
    const bool inflow = P.zone[i] >= 0 && !open.owns(P.zone[i]);
    P.velocity[i] = inflow ? zones.velocity(P.zone[i], 0.0) : Vec::Zero();
    P.velocity_previous[i] = P.velocity[i];
    P.acceleration[i] = P.interaction[i] = P.wall_velocity[i] = Vec::Zero();
    P.viscosity_cut[i] = P.drag_rate[i] = 0.0;
    P.density[i] = params.eos.rho0();
    P.pressure[i] = P.density_rate[i] = 0.0;
    P.sound_speed[i] = params.eos.c0();
    P.remove_at[i] = wall ? wall_remove_at[i - P.n_free] : -1.0;
    P.wall_motion[i] = wall ? wall_motion[i - P.n_free] : -1;
    P.wall_side[i] = wall ? wall_side[i - P.n_free] : 0;
    P.id[i] = static_cast<std::int64_t>(i);
    P.fixed[i] = wall ? 1 : 0;
  }
  if (params.hydrostatic_initial) {
    // A thin wall's two sides: one copy of the wall's own lattice covers the water beneath it.
    hydrostatic_state<D>(P.position.data(), P.n_free, covering.data(), covering.size(),
                         params.gravity, dp, params.eos, P.pressure.data(), P.density.data());
  }
  if (s.water->initial_velocity == "taylor_green") {  // inflow-zone particles keep their own
    const TaylorGreenVortex vortex{s.water->taylor_green_speed, s.water->taylor_green_wavelength};
    for (std::size_t i = 0; i < P.n_free; ++i) {
      if (P.zone[i] >= 0) continue;
      P.velocity[i] = P.velocity_previous[i] = vortex.velocity<D>(P.position[i]);
      P.pressure[i] += vortex.pressure<D>(P.position[i], params.eos.rho0());
      P.density[i] = params.eos.density(P.pressure[i]);
    }
  }
  open.capture_and_impose(P);  // the buffers at the hydrostatic pressure of their levels
  for (std::size_t i = 0; i < P.n_free; ++i)
    if (open.owns(P.zone[i])) P.pressure[i] = params.eos.pressure(P.density[i]);
  // m = rho(t=0) dp^D: the particle volume m/rho equals the lattice volume dp^D, so the initial
  // hydrostatic state is an SPH equilibrium (with m = rho0 dp^D the volumes of the compressed deep
  // particles are too small and a still tank slowly settles to pressures ~2 % too high at depth).
  for (std::size_t i = 0; i < n; ++i) P.mass[i] = P.density[i] * params.volume;
  P.density_previous = P.density;
  out.occluders = std::move(thin.occluders);
  return out;
}

template InitialParticles<2> initial_particles<2>(const scene::Scene&, const WaterParams<2>&,
                                                  const sph::DomainBox<2>&, const FlowZones<2>&,
                                                  const OpenReservoirs<2>&);
template InitialParticles<3> initial_particles<3>(const scene::Scene&, const WaterParams<3>&,
                                                  const sph::DomainBox<3>&, const FlowZones<3>&,
                                                  const OpenReservoirs<3>&);

}  // namespace porosph::water
