// Hand-made particle sets and scenes for the water-phase tests (scene structs built directly, no
// TOML parser involved).
#pragma once

#include <string>
#include <vector>

#include "fluid_solver/water_params.h"
#include "fluid_solver/water_particles.h"
#include "scene/scene.h"

namespace porosph::water::testing {

inline scene::Shape box(std::vector<double> lo, std::vector<double> hi, double remove_at = -1.0) {
  scene::Shape s;
  s.kind = scene::Shape::Kind::Box;
  s.min = std::move(lo);
  s.max = std::move(hi);
  s.remove_at = remove_at;
  return s;
}

inline scene::Shape container(std::vector<double> lo, std::vector<double> hi, int layers,
                              std::vector<std::string> open = {"y+"}) {
  scene::Shape s = box(std::move(lo), std::move(hi));
  s.kind = scene::Shape::Kind::Container;
  s.layers = layers;
  s.open_faces = std::move(open);
  return s;
}

/// An inflow zone [lo, hi] moving water along `direction` at `speed` (ramp from start over ramp).
inline scene::InflowZone inflow(std::vector<double> lo, std::vector<double> hi,
                                std::vector<double> direction, double speed,
                                double start_time = 0.0, double ramp_time = 0.0) {
  scene::InflowZone z;
  z.min = std::move(lo);
  z.max = std::move(hi);
  z.direction = std::move(direction);
  z.speed = speed;
  z.start_time = start_time;
  z.ramp_time = ramp_time;
  return z;
}

inline scene::OutflowZone outflow(std::vector<double> lo, std::vector<double> hi) {
  scene::OutflowZone z;
  z.min = std::move(lo);
  z.max = std::move(hi);
  return z;
}

/// A 2D water scene without blocks or walls: rho0 1000, c 20, mu 1e-3, alpha 0.05, g = -9.81 y.
inline scene::Scene water_scene(double dp, std::vector<double> domain_min,
                                std::vector<double> domain_max) {
  scene::Scene s;
  s.run.dimension = static_cast<int>(domain_min.size());
  s.run.dp = dp;
  s.run.h_factor = 1.2;
  s.run.gravity.assign(domain_min.size(), 0.0);
  s.run.gravity[1] = -9.81;
  s.run.periodic.assign(domain_min.size(), false);
  s.domain.min = std::move(domain_min);
  s.domain.max = std::move(domain_max);
  s.water = scene::WaterPhase{};
  return s;
}

/// Particles at `x` (the first n_free water), all arrays sized, at rest, rho = rho0, m = m0, no
/// inflow-zone particle.
template <int D>
WaterParticles<D> make_particles(const std::vector<sph::Vec<D>>& x, std::size_t n_free, double rho0,
                                 double m0) {
  WaterParticles<D> P;
  P.n_free = n_free;
  const std::size_t n = x.size();
  P.for_each_array([n](auto& a) { a.resize(n); });
  for (std::size_t i = 0; i < n; ++i) {
    P.position[i] = x[i];
    P.velocity[i] = P.velocity_previous[i] = P.acceleration[i] = sph::Vec<D>::Zero();
    P.interaction[i] = P.wall_velocity[i] = sph::Vec<D>::Zero();
    P.density[i] = P.density_previous[i] = rho0;
    P.pressure[i] = P.density_rate[i] = 0.0;
    P.sound_speed[i] = 20.0;
    P.mass[i] = m0;
    P.remove_at[i] = -1.0;
    P.id[i] = static_cast<std::int64_t>(i);
    P.fixed[i] = i >= n_free;
    P.zone[i] = -1;
  }
  return P;
}

}  // namespace porosph::water::testing
