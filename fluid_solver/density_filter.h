// Shepard density filter (zeroth-order density re-initialisation; Colagrossi & Landrini 2003,
// J. Comput. Phys. 191, 448-475, as used by DualSPHysics):
//   rho_a <- sum_b m_b W_ab / sum_b (m_b / rho_b) W_ab,
// sums over the particles b within the support, a itself included (W_aa = W(0)), wall particles
// included with their Adami-extrapolated density (so the wall state must be current). Without
// the walls the average next to a wall is one-sided and loses the hydrostatic density gradient:
// in a 0.6 m still tank (dp 0.02) the bottom-row pressures then fell 3.5 % of rho g H low.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid_solver/water_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::water {

/// Filters the density of the water particles of P (walls up to date); `scratch` is reused.
template <int D, class Kernel>
void shepard_density_filter(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                            WaterParticles<D>& P, std::vector<double>& scratch) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  scratch.resize(P.n_free);
  const double w0 = kernel.w(0.0);
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) {
    double mass_sum = P.mass[a] * w0;
    double volume_sum = P.mass[a] / P.density[a] * w0;
    for (auto it = neighbours.begin(a); it != neighbours.end(a); ++it) {
      const double kw = kernel.w(it->r);
      mass_sum += P.mass[it->b] * kw;
      volume_sum += P.mass[it->b] / P.density[it->b] * kw;
    }
    scratch[a] = mass_sum / volume_sum;
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) P.density[a] = scratch[a];
}

}  // namespace porosph::water
