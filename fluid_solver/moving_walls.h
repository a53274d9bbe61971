// Walls that move as one body ([[walls]] moves_with / move_direction; docs/scene.md): each step the
// coupler sends every scene wall's speed (StepCommand.wall_speed: the latest value of the
// observable the wall follows, e.g. the load_velocity of a rigid soil plate), and the wall's
// particles move by dt times that along the wall's direction, carrying that velocity into the
// continuity equation (the water beside it is compressed or drawn along) and into the mirrored
// no-slip velocity of Adami et al. (2012). The wall's acceleration is left out of its pressure
// extrapolation (wall_boundary.h): a wall that follows a consolidating sample accelerates by
// micrometres per second squared.
// A moving wall also measures the force the water's pressure puts on it (observables of kind
// wall_force), so that the body it follows can carry it (soil.loads[].plus_force_from: a lid and
// the rigid plate it moves with are one body, and the lid's share of the load reaches the plate):
//   F_W = - sum_a sum_{b in W} m_a a_ab,   a_ab = -m_b (s p_a + p_b) / (rho_a rho_b) grad W_ab,
// the symmetric pressure pair term of seed eq. 3 (s = -1 with particle shifting, as in the rates)
// over the water particles a and their neighbours b in the wall, from the latest rates.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid_solver/particle_gradient.h"
#include "fluid_solver/pressure_force.h"
#include "fluid_solver/water_particles.h"
#include "scene/scene.h"
#include "sph/neighbour_list.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
class MovingWalls {
 public:
  using Vec = sph::Vec<D>;

  /// The moving walls among the scene's walls that act on water, in the order
  /// Scene::walls_acting_on("water") lists them (the order of `motion_of_water_wall`).
  explicit MovingWalls(const scene::Scene& s) {
    for (std::size_t i = 0; i < s.walls.size(); ++i) {
      const scene::Shape& w = s.walls[i];
      if (!acts_on_water(w) || w.moves_with.empty()) continue;
      scene_index_.push_back(i);
      label_.push_back(w.label);
      direction_.push_back(sph::to_vec<D>(w.move_direction, "walls.move_direction"));
    }
    force_.assign(scene_index_.size(), Vec::Zero());
  }

  /// Index of the moving wall labelled `label`; -1 when none.
  int index_of(const std::string& label) const {
    for (std::size_t k = 0; k < label_.size(); ++k)
      if (label_[k] == label) return static_cast<int>(k);
    return -1;
  }

  /// The force the water's pressure put on moving wall k in the latest measure_forces()
  /// [N/m^(3-D)].
  const Vec& force(std::size_t k) const { return force_[k]; }

  /// F_W of every moving wall (above) from the pairs of `nl` and the pressures, densities, masses
  /// and gradient scales of the latest rates; `pressure_sign` as in the rates (water_rates.cpp).
  template <class Kernel>
  void measure_forces(const sph::NeighbourList<D>& nl, const Kernel& kernel,
                      const WaterParticles<D>& P, double pressure_sign) {
    for (Vec& f : force_) f.setZero();
    if (scene_index_.empty()) return;
    for (std::size_t a = 0; a < P.n_free; ++a) {
      for (auto it = nl.mid(a); it != nl.end(a); ++it) {
        const std::int32_t k = P.wall_motion[it->b];
        if (k < 0) continue;
        const Vec grad_w = ParticleGradient::wall_pair<D>(
                               P.gradient_scale.data(),
                               P.gradient_matrix.empty() ? nullptr : P.gradient_matrix.data(), a,
                               kernel.grad_factor(it->r), it->x_ab, it->r)
                               .grad_w;
        force_[k] -=
            P.mass[a] * pressure_acceleration<D>(P.mass[it->b], pressure_sign * P.pressure[a],
                                                 P.pressure[it->b], P.inverse_density[a],
                                                 P.inverse_density[it->b], grad_w);
      }
    }
  }

  /// For each wall acting on water (walls_acting_on order): its index among the moving walls, -1
  /// for a fixed wall (WaterParticles::wall_motion of its particles).
  static std::vector<std::int32_t> motion_of_water_walls(const scene::Scene& s) {
    std::vector<std::int32_t> motion;
    std::int32_t moving = 0;
    for (const scene::Shape& w : s.walls)
      if (acts_on_water(w)) motion.push_back(w.moves_with.empty() ? -1 : moving++);
    return motion;
  }

  bool empty() const { return scene_index_.empty(); }

  /// StepCommand.wall_speed: one speed per scene wall (empty: every wall at rest).
  void set_speeds(const std::vector<double>& speeds) {
    speed_.assign(scene_index_.size(), 0.0);
    if (speeds.empty()) return;
    for (std::size_t k = 0; k < scene_index_.size(); ++k) {
      if (scene_index_[k] >= speeds.size())
        throw std::invalid_argument("wall_speed: expected one speed per scene wall, got " +
                                    std::to_string(speeds.size()));
      speed_[k] = speeds[scene_index_[k]];
    }
  }

  /// Gives each moving wall particle its wall's velocity and moves it by dt times that.
  void move(WaterParticles<D>& P, double dt) const {
    if (scene_index_.empty()) return;
    for (std::size_t w = P.n_free; w < P.size(); ++w) {
      const std::int32_t k = P.wall_motion[w];
      if (k < 0) continue;
      const double speed = static_cast<std::size_t>(k) < speed_.size() ? speed_[k] : 0.0;
      P.velocity[w] = speed * direction_[k];
      P.position[w] += dt * P.velocity[w];
    }
  }

 private:
  static bool acts_on_water(const scene::Shape& w) {
    if (w.phases.empty()) return true;
    for (const std::string& p : w.phases)
      if (p == "water") return true;
    return false;
  }

  std::vector<std::size_t> scene_index_;  ///< per moving wall: its index among the scene's walls
  std::vector<std::string> label_;        ///< per moving wall: its label
  std::vector<Vec> direction_;            ///< per moving wall: unit direction
  std::vector<double> speed_;             ///< per moving wall: speed of this step [m/s]
  std::vector<Vec> force_;                ///< per moving wall: F_W of the latest rates
};

}  // namespace porosph::water
