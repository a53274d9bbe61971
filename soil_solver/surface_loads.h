// Surface loads on the soil ([[soil.loads]]; docs/soil.md): a traction t on a face of the soil,
// carried by the free soil particles that lay in the load's box at t = 0. The load's total force
// per unit thickness (2D) or area (3D) of the face is F = t A, A the box's extent across the
// traction's axis; the particles are the box's outermost layer facing the traction (its face);
// each of its N particles carries F / N, and the particle's acceleration is
//   a_i = f(t) F / (N m_i^s),   m_i^s = m_i rho_i^s / rho_i
// with f(t) the load's ramp (0 before start_time, linear over ramp_time, then 1) and m_i^s the
// effective mass of the soil's momentum equation (seed eq. 16: the stress divergence and the
// seepage force act on the submerged density rho^s when the particle is submerged; the load is
// one more force on the same inertia).
//
// A rigid load (`rigid = true`) is a rigid, frictionless plate: after every kick its particles'
// velocities along the traction's axis are set to their mean weighted by the effective mass,
//   v_i . e = sum_j m_j^s v_j . e / sum_j m_j^s,
// which moves the plate as one body under the load and the forces the soil and water put on it
// (Mandel 1953; Cheng & Detournay 1988), leaves it free across the axis, and changes no momentum
// (the constraint forces are internal to the plate). `material` swaps the loaded particles'
// material at t = 0, e.g. for an impermeable one that seals the plate against the pore water.
// `plus_force_from` adds a force the coupler sends each step (StepCommand.load_force: the value of
// an observable, e.g. the water's force on the lid that moves with the plate) to the load's own,
// shared like it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "soil_solver/soil_particles.h"
#include "sph/vector.h"

namespace porosph::soil {

template <int D>
class SurfaceLoads {
 public:
  using Vec = sph::Vec<D>;

  /// `soil`: the loads and the materials they name.
  explicit SurfaceLoads(const scene::SoilPhase& soil) : loads_(soil.loads) {
    for (const scene::SoilLoad& load : loads_)
      material_.push_back(load.material.empty() ? -1 : soil.material_index(load.material));
  }

  bool empty() const { return loads_.empty(); }

  /// Tags the free particles of `P` each load acts on (P.load, -1: none): of the particles in the
  /// load's box, the outermost layer facing the traction - those within dp / 2 of the box's
  /// particle farthest against the traction (the top row for a downward load), so that the
  /// same box selects the face layer at every resolution. Shares each load's force among its
  /// particles, and gives them the load's material, if it names one. Throws
  /// std::invalid_argument naming the load when its box holds no free soil, or when its material
  /// differs from a particle's own in density or porosity (the particle keeps its mass).
  template <class Materials>
  void tag(SoilParticles<D>& P, double dp, const Materials& materials) {
    std::fill(P.load.begin(), P.load.end(), -1);
    force_per_particle_.assign(loads_.size(), Vec::Zero());
    count_.assign(loads_.size(), 0);
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      const Vec traction = sph::to_vec<D>(loads_[k].traction, "traction");
      const Vec outward = -traction.normalized();  // the loaded face looks this way
      double outermost = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < P.n_free; ++i)
        if (P.load[i] < 0 && inside(loads_[k], P.position[i]))
          outermost = std::max(outermost, P.position[i].dot(outward));
      std::int64_t count = 0;
      for (std::size_t i = 0; i < P.n_free; ++i) {
        if (P.load[i] >= 0 || !inside(loads_[k], P.position[i])) continue;
        if (P.position[i].dot(outward) < outermost - 0.5 * dp) continue;
        P.load[i] = static_cast<std::int32_t>(k);
        ++count;
      }
      if (count == 0) {
        throw std::invalid_argument("soil.loads[" + std::to_string(k) + "]" +
                                    (loads_[k].label.empty() ? "" : " '" + loads_[k].label + "'") +
                                    ": no free soil particle in its box at t = 0");
      }
      force_per_particle_[k] = traction * (loads_[k].face_extent() / static_cast<double>(count));
      count_[k] = count;
      if (material_[k] >= 0) assign_material(k, P, materials);
    }
  }

  /// The mean velocity along its traction's axis [m/s] of the particles of the load labelled
  /// `label` (the plate's speed for a rigid load; observables of kind load_velocity); NaN when no
  /// load has that label or its particles are gone.
  double velocity(const std::string& label, const SoilParticles<D>& P) const {
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      if (loads_[k].label != label) continue;
      const int axis = axis_of(k);
      double sum = 0.0;
      std::size_t count = 0;
      for (std::size_t i = 0; i < P.n_free; ++i)
        if (P.load[i] == static_cast<std::int32_t>(k)) sum += P.velocity[i][axis], ++count;
      if (count > 0) return sum / static_cast<double>(count);
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// StepCommand.load_force: per load, a force [N/m^(3-D)] added to it along the positive direction
  /// of its traction's axis, shared like the traction (empty: none).
  void set_extra_forces(const std::vector<double>& forces) {
    if (!forces.empty() && forces.size() != loads_.size())
      throw std::invalid_argument("load_force: expected one force per soil load, got " +
                                  std::to_string(forces.size()));
    extra_.assign(loads_.size(), 0.0);
    for (std::size_t k = 0; k < forces.size(); ++k) extra_[k] = forces[k];
  }

  /// Moves each rigid load's particles as one along its axis (above): call after the kick.
  void make_rigid(SoilParticles<D>& P) const {
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      if (!loads_[k].rigid) continue;
      const int axis = axis_of(k);
      double weight = 0.0, momentum = 0.0;
      for (std::size_t i = 0; i < P.n_free; ++i) {
        if (P.load[i] != static_cast<std::int32_t>(k)) continue;
        const double m = P.mass[i] * P.weight_ratio[i];
        weight += m;
        momentum += m * P.velocity[i][axis];
      }
      if (weight <= 0.0) continue;
      const double v = momentum / weight;
      for (std::size_t i = 0; i < P.n_free; ++i)
        if (P.load[i] == static_cast<std::int32_t>(k)) P.velocity[i][axis] = v;
    }
  }

  /// Adds the loads' accelerations at `time` to P.acceleration; returns the largest |a +
  /// interaction| of a loaded particle (for the eq. 21 limit), 0 when no load acts. `force`: the
  /// loads' total force sum f(t) F / N (the impulse books), when given.
  double apply(double time, SoilParticles<D>& P, Vec* force = nullptr) const {
    if (force != nullptr) force->setZero();
    if (loads_.empty()) return 0.0;
    double max_a2 = 0.0;
    for (std::size_t i = 0; i < P.n_free; ++i) {
      const std::int32_t k = P.load[i];
      if (k < 0) continue;
      const double factor = loads_[k].factor_at(time);
      const double extra = extra_.empty() ? 0.0 : extra_[k];
      if (factor == 0.0 && extra == 0.0) continue;
      Vec f = factor * force_per_particle_[k];
      f[axis_of(k)] += extra / static_cast<double>(count_[k]);
      const double effective_mass = P.mass[i] * P.weight_ratio[i];
      P.acceleration[i] += f / effective_mass;
      if (force != nullptr) *force += f;
      max_a2 = std::max(max_a2, (P.acceleration[i] + P.interaction[i]).squaredNorm());
    }
    return std::sqrt(max_a2);
  }

 private:
  static bool inside(const scene::SoilLoad& load, const Vec& x) {
    for (int k = 0; k < D; ++k)
      if (x[k] < load.min[k] || x[k] > load.max[k]) return false;
    return true;
  }

  /// The axis the load's traction acts along.
  int axis_of(std::size_t k) const {
    int axis = 0;
    for (int c = 0; c < D; ++c)
      if (loads_[k].traction[c] != 0.0) axis = c;
    return axis;
  }

  template <class Materials>
  void assign_material(std::size_t k, SoilParticles<D>& P, const Materials& materials) const {
    const auto& to = materials[static_cast<std::size_t>(material_[k])];
    for (std::size_t i = 0; i < P.n_free; ++i) {
      if (P.load[i] != static_cast<std::int32_t>(k)) continue;
      const auto& from = materials[static_cast<std::size_t>(P.material[i])];
      if (from.density != to.density || from.porosity != to.porosity) {
        throw std::invalid_argument(
            "soil.loads[" + std::to_string(k) + "].material '" + loads_[k].material +
            "': its density and porosity must be those of the loaded particles' own material");
      }
      P.material[i] = material_[k];
    }
  }

  std::vector<scene::SoilLoad> loads_;
  std::vector<int> material_;            ///< per load: index of the material it assigns; -1: none
  std::vector<std::int64_t> count_;      ///< per load: its particles
  std::vector<double> extra_;            ///< per load: StepCommand.load_force of this step
  std::vector<Vec> force_per_particle_;  ///< per load: F / N at full load [N / m^(3-D)]
};

}  // namespace porosph::soil
