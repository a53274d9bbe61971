// The weight with which a water particle counts as held by the seepage drag:
//   s_a = min(1, lambda_a / (0.5 lambda_max,a)),
// lambda_a the particle's drag rate from the coupler (the derivative of eq. 13-17 along v_r) and
// lambda_max,a the largest over it and its water neighbours. It is 1 inside soil, a ramp over the
// soil's surface layer, where the kernel sum of the soil thins out, and 0 without drag. The ramp is
// a fraction of the soil's own drag, so it spans the same kernel-scale layer at every resolution:
// unlike the drag share min(1, lambda_a / r_av) of artificial_viscosity.h it depends on neither h
// nor alpha nor c0.
// Used by the hydrostatic difference form of the pressure gradient (hydrostatic_difference.h) and
// by the artificial viscosity that the drag replaces (water.artificial_viscosity_in_soil =
// "drag_replaced", artificial_viscosity.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sph/neighbour_list.h"

namespace porosph::water {

struct DragWeight {
  /// The share of the neighbourhood's largest drag rate at which s_a reaches 1.
  static constexpr double kFullWeightFrom = 0.5;

  /// s_a of the particle's drag rate lambda_a >= 0 and lambda_max >= lambda_a [1/s]: 0 without
  /// drag.
  static double of(double drag_rate, double neighbour_max) {
    if (!(drag_rate > 0.0) || !(neighbour_max > 0.0)) return 0.0;
    return std::min(1.0, drag_rate / (kFullWeightFrom * neighbour_max));
  }

  /// s_a of every free water particle a < n_free into out[a] (lambda_max over its water
  /// neighbours, the list's first part); out is resized to n_free.
  template <int D>
  static void compute(const sph::NeighbourList<D>& neighbours, std::size_t n_free,
                      const std::vector<double>& drag_rate, std::vector<double>& out) {
    out.resize(n_free);
    const std::int64_t n = static_cast<std::int64_t>(n_free);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t a = 0; a < n; ++a) {
      if (!(drag_rate[a] > 0.0)) {
        out[a] = 0.0;
        continue;
      }
      double neighbour_max = drag_rate[a];
      for (auto it = neighbours.begin(a); it != neighbours.mid(a); ++it)
        neighbour_max = std::max(neighbour_max, drag_rate[it->b]);
      out[a] = of(drag_rate[a], neighbour_max);
    }
  }
};

}  // namespace porosph::water
