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

  explicit SurfaceLoads(const std::vector<scene::SoilLoad>& loads) : loads_(loads) {}

  bool empty() const { return loads_.empty(); }

  /// Tags the free particles of `P` each load acts on (P.load, -1: none): of the particles in the
  /// load's box, the outermost layer facing the traction - those within dp / 2 of the box's
  /// particle farthest against the traction (the top row for a downward load), so that the
  /// same box selects the face layer at every resolution. Shares each load's force among its
  /// particles. Throws std::invalid_argument naming the load when its box holds no free soil.
  void tag(SoilParticles<D>& P, double dp) {
    std::fill(P.load.begin(), P.load.end(), -1);
    force_per_particle_.assign(loads_.size(), Vec::Zero());
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
      if (factor == 0.0) continue;
      const double effective_mass = P.mass[i] * P.weight_ratio[i];
      P.acceleration[i] += (factor / effective_mass) * force_per_particle_[k];
      if (force != nullptr) *force += factor * force_per_particle_[k];
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

  std::vector<scene::SoilLoad> loads_;
  std::vector<Vec> force_per_particle_;  ///< per load: F / N at full load [N / m^(3-D)]
};

}  // namespace porosph::soil
