// The simulation box (scene.domain): periodic axes wrap at its faces (minimum-image convention for
// pair displacements); on the other axes a particle that leaves the box is removed by the solver.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::sph {

template <int D>
struct DomainBox {
  Vec<D> min = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  Vec<D> max = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  std::array<bool, D> periodic{};

  /// Same bounds and periodic axes (a neighbour search laid out for one is valid for the other).
  bool same_as(const DomainBox& other) const {
    return periodic == other.periodic && min == other.min && max == other.max;
  }

  /// Box from the scene (empty min/max: unbounded); periodic flags from scene.run.periodic.
  /// Throws std::invalid_argument if a periodic axis is unbounded or shorter than 2 `support`
  /// (the minimum image must be unique within the kernel support).
  static DomainBox from_scene(const scene::Scene& s, double support) {
    DomainBox box;
    box.min = to_vec<D>(s.domain.min, "domain.min", box.min);
    box.max = to_vec<D>(s.domain.max, "domain.max", box.max);
    if (!s.run.periodic.empty() && static_cast<int>(s.run.periodic.size()) != D) {
      throw std::invalid_argument("run.periodic: expected " + std::to_string(D) + " flags");
    }
    for (int k = 0; k < D; ++k) {
      box.periodic[k] = !s.run.periodic.empty() && s.run.periodic[k];
      if (!box.periodic[k]) continue;
      const double length = box.max[k] - box.min[k];
      if (!std::isfinite(length) || length < 2.0 * support) {
        throw std::invalid_argument("periodic axis " + std::to_string(k) +
                                    ": domain length must be finite and >= 2 x kernel support (" +
                                    std::to_string(2.0 * support) + " m)");
      }
    }
    return box;
  }

  bool any_periodic() const {
    for (int k = 0; k < D; ++k)
      if (periodic[k]) return true;
    return false;
  }

  double length(int k) const { return max[k] - min[k]; }

  /// Minimum-image displacement on the periodic axes.
  void minimum_image(Vec<D>& dx) const {
    for (int k = 0; k < D; ++k) {
      if (!periodic[k]) continue;
      const double L = length(k);
      if (dx[k] > 0.5 * L) {
        dx[k] -= L;
      } else if (dx[k] < -0.5 * L) {
        dx[k] += L;
      }
    }
  }

  /// Brings a position back into [min, max) along the periodic axes.
  void wrap(Vec<D>& x) const {
    for (int k = 0; k < D; ++k) {
      if (!periodic[k]) continue;
      const double L = length(k);
      if (x[k] < min[k] || x[k] >= max[k]) {
        x[k] -= L * std::floor((x[k] - min[k]) / L);
        if (x[k] >= max[k]) x[k] = min[k];  // round-off of the line above
      }
    }
  }

  /// True if x is outside the box along a non-periodic axis (such a particle is removed).
  bool outside(const Vec<D>& x) const {
    for (int k = 0; k < D; ++k) {
      if (periodic[k]) continue;
      if (x[k] < min[k] || x[k] > max[k]) return true;  // NaN is not outside: reported, not removed
    }
    return false;
  }
};

}  // namespace porosph::sph
