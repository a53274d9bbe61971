// The renormalised gradient of the hydrostatic departure potential, for the density diffusion's
// linear correction (density_diffusion.h; Antuono, Colagrossi, Marrone & Molteni 2010,
// "Free-surface flows solved by means of SPH schemes with numerical diffusive terms", Comput. Phys.
// Commun. 181, 532-549, eq. 9-10: the delta-SPH of "<grad rho>^L").
//
// psi = Phi(rho) - g . x (over c0^2) is constant in still water; in a steady seepage flow, or any
// flow whose pressure is not hydrostatic, it has a gradient, and the pair bracket psi_b - psi_a of
// the diffusion term is then its linear part G . x_ba: a flux that never vanishes, which the
// continuity equation answers with a velocity jump wherever G changes (a bed's top, a free
// surface). Measured before this correction: the water inside a fluidised bed moved at 0.963-0.98
// of the superficial velocity Q / A while the flux through it was Q.
//
// G_a = L_a sum_b V_b (psi_b - psi_a) grad_a W_ab,   L_a = (sum_b V_b x_ba (x) grad_a W_ab)^-1,
// over water neighbours only (the diffusion's own stencil), so that G is exact for a linear psi at
// any particle, a truncated stencil included (Bonet & Lok 1999). Where the moment matrix is
// singular or badly conditioned (an isolated particle, a row of particles: |det| below 1e-3 of the
// full stencil's) G_a = 0, and the pair bracket falls back to the uncorrected psi_b - psi_a.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid_solver/density_diffusion.h"
#include "fluid_solver/viscous_level.h"
#include "fluid_solver/water_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::water {

/// P.diffusion_state of every water particle from its density: rho^n (Current; Euler steps) or the
/// stored rho^{n-1} (Previous; Verlet steps), for the reason the viscous terms of a Verlet step
/// act on v^{n-1} (viscous_level.h): the diffusion is a damping term of the continuity equation.
template <int D>
void fill_diffusion_states(const DensityDiffusion<D>& diffusion, WaterParticles<D>& P,
                           ViscousLevel level = ViscousLevel::Current) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  P.diffusion_state.resize(P.n_free);
  const double* density =
      level == ViscousLevel::Previous ? P.density_previous.data() : P.density.data();
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) P.diffusion_state[a] = diffusion.state(density[a]);
}

/// Fills `gradient` (size n_free; grown only when too small) with G_a of every water particle;
/// P.diffusion_state must be filled (fill_diffusion_states).
template <int D, class Kernel>
void departure_gradients(const sph::NeighbourList<D>& nl, const Kernel& kernel,
                         const DensityDiffusion<D>& diffusion, const WaterParticles<D>& P,
                         std::vector<sph::Vec<D>>& gradient) {
  using Vec = sph::Vec<D>;
  using Mat = Eigen::Matrix<double, D, D>;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  gradient.resize(P.n_free);
  const DiffusionState* state = P.diffusion_state.data();
  const double* volume = P.volume.data();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t a = 0; a < n; ++a) {
    const DiffusionState state_a = state[a];
    Mat moment = Mat::Zero();
    Vec sum = Vec::Zero();
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      const Vec grad_w = kernel.grad_factor(it->r) * it->x_ab;
      const double d_psi = diffusion.potential_difference(state_a, state[it->b], it->x_ab);
      sum += (volume[it->b] * d_psi) * grad_w;
      moment -= volume[it->b] * (it->x_ab * grad_w.transpose());  // x_ba (x) grad W
    }
    // A full lattice stencil gives moment = I (det 1); a half-space one about 0.5 in its normal.
    const double det = moment.determinant();
    gradient[a] = std::abs(det) > 1e-3 ? Vec(moment.inverse() * sum) : Vec::Zero();
  }
}

}  // namespace porosph::water
