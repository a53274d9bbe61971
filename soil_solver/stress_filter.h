// Shepard (zeroth-order) filter of the soil stress, the stress regularisation of Nguyen, Bui et al.
// (2017), "A new SPH-based approach to simulation of granular flows using viscous damping and
// stress regularisation", Landslides 14, 69-81:
//   sigma_i <- sum_j sigma_j W_ij V_j / sum_j W_ij V_j     (j over the free soil around i, i
//   included)
// applied every N steps. The pair form of the stress divergence (eq. 5) cannot see a stress that
// alternates from one particle row to the next (the sums over the rows above and below cancel), so
// such a pattern, once excited by the settling waves, never decays; the filter removes it and
// leaves a linear stress field unchanged in the interior (to the kernel's discretisation error).
#pragma once

#include <cstdint>
#include <vector>

#include "soil_solver/soil_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {

/// Filters the stress of the free particles in place; `scratch` is reused between calls.
template <int D, class Kernel>
void shepard_stress_filter(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                           SoilParticles<D>& P, std::vector<Eigen::Matrix3d>& scratch) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  scratch.resize(P.n_free);
  const double w0 = kernel.w(0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < n; ++i) {
    const double volume_i = P.mass[i] / P.density[i];
    Eigen::Matrix3d sum = (w0 * volume_i) * P.stress[i];
    double weight = w0 * volume_i;
    for (auto it = neighbours.begin(i); it != neighbours.mid(i); ++it) {
      const double wv = kernel.w(it->r) * P.mass[it->b] / P.density[it->b];
      sum += wv * P.stress[it->b];
      weight += wv;
    }
    scratch[i] = sum / weight;
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) P.stress[i] = scratch[i];
}

}  // namespace porosph::soil
