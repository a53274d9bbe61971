// Fickian particle shifting of Lind, Xu, Stansby & Rogers (2012), J. Comput. Phys. 231,
// 1499-1523 (eqs. 9-13 there), with the velocity scale of Sun, Colagrossi, Marrone & Zhang (2017),
// Comput. Methods Appl. Mech. Engrg. 315, 25-49 (delta+-SPH), for water.particle_shifting = A > 0:
//   delta r_a = -A h U_max dt grad C_a,
//   grad C_a  = sum_b V_b (1 + R (W_ab / W(dp))^n) grad_a W_ab,   R = 0.2, n = 4,
// applied after each position update; the particle keeps its velocity (as in Sun et al.; a
// first-order Taylor correction of velocity and density, as in Lind et al., was tried twice: no
// better on the Taylor-Green vortex, +6.44 % against +6.54 % at L/50, docs/verification.md).
// Momentum is unchanged by the shift. The shift is a motion of the particles and their mass, so
// the continuity equation sees it (add_to_continuity): the density follows the particles' volume
// under the shift as under the flow, and the mean density stays at rho0 in a closed box. With
// shifting on, the pressure gradient takes its zeroth-order consistent difference form
// (pressure_force.h): the shift, not the symmetric form's residue force, keeps the particles
// uniform. Why: a Lagrangian lattice is stretched by the flow's strain (at the stagnation points of
// a Taylor-Green vortex by exp(U k t)), and standard SPH on such a stretched, then disordered,
// particle set loses its accuracy and becomes unstable within t ~ 1 / (U k) (measured: the vortex
// breaks down at t ~ 0.1 s at every dp). Shifting moves each particle down the gradient of the
// particle concentration, back toward a uniform distribution. The shift is proportional to the
// distance the fastest particle travels (U_max dt, the largest water speed of the step), so still
// water is never shifted; Lind's local |v_a| would leave the stagnation points, where the strain
// stretches the lattice most, unshifted. Sun et al.'s choice equals A = 4. The tensile term
// (Monaghan 2000) keeps pairs from clumping. Wall particles count in C (they complete the
// support). Lind's free-surface treatment is not implemented: confined or periodic water only.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid_solver/water_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::water {

/// grad C of every water particle and U_max, from the state before a step (derived per step,
/// sized by compute()).
template <int D>
struct ParticleShiftingGradients {
  using Vec = sph::Vec<D>;
  static constexpr double kTensileR = 0.2;
  static constexpr int kTensileN = 4;  // (W / W(dp))^4, written as two squares below
  std::vector<Vec> concentration;
  double speed = 0.0;  ///< U_max: the largest water speed of the same state [m/s]

  /// Needs P.volume of the current state (compute_water_rates fills it).
  template <class Kernel>
  void compute(const sph::NeighbourList<D>& nl, const Kernel& kernel, double dp, double max_speed,
               const WaterParticles<D>& P) {
    speed = max_speed;
    const std::int64_t n = static_cast<std::int64_t>(P.n_free);
    concentration.resize(P.n_free);
    const double inv_w_dp = 1.0 / kernel.w(dp);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t a = 0; a < n; ++a) {
      Vec grad_c = Vec::Zero();
      for (auto it = nl.begin(a); it != nl.end(a); ++it) {
        const double ratio = kernel.w(it->r) * inv_w_dp;
        const double ratio2 = ratio * ratio;
        grad_c +=
            (P.volume[it->b] * (1.0 + kTensileR * ratio2 * ratio2) * kernel.grad_factor(it->r)) *
            it->x_ab;
      }
      concentration[a] = grad_c;
    }
  }

  /// The shifting velocity of free water particle a, u_a = -A h U_max grad C_a (the shift of
  /// the next step over its dt); zero for the particles of inflow zones and open reservoirs,
  /// which move as prescribed and are not shifted.
  Vec velocity(double coefficient, double h, std::size_t a, const WaterParticles<D>& P) const {
    if (P.zone[a] >= 0) return Vec::Zero();
    return (-coefficient * h * speed) * concentration[a];
  }

  /// The shift moves the particles, and with them their mass: adds its share of the continuity
  /// equation (seed eq. 2 with the shifting velocity u, continuity.h),
  ///   drho_a/dt += rho_a sum_b V_b (u_a - u_b) . grad_a W_ab     (u = 0 for walls),
  /// to P.density_rate, so that each particle's volume m / rho follows its neighbourhood under
  /// the shift as under the flow. Without it the density integrates the flow's disordering of the
  /// particles but not the shift's reordering of them, and drifts: +2.3 % at L/50 over the
  /// Taylor-Green vortex's fit window (docs/verification.md), which raises the pressure and lowers
  /// the Morris viscosity mu / rho by as much. Call after compute(), on the same neighbour list.
  template <class Kernel>
  void add_to_continuity(const sph::NeighbourList<D>& nl, const Kernel& kernel, double coefficient,
                         double h, WaterParticles<D>& P) const {
    const std::int64_t n = static_cast<std::int64_t>(P.n_free);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t a = 0; a < n; ++a) {
      const Vec u_a = velocity(coefficient, h, static_cast<std::size_t>(a), P);
      double sum = 0.0;
      for (auto it = nl.begin(a); it != nl.end(a); ++it) {
        const std::size_t b = it->b;
        const Vec u_ab = b < P.n_free ? Vec(u_a - velocity(coefficient, h, b, P)) : u_a;
        sum += P.volume[b] * kernel.grad_factor(it->r) * u_ab.dot(it->x_ab);
      }
      P.density_rate[a] += P.density[a] * sum;
    }
  }

  /// Shifts water particle a, which has just moved over dt, by u_a dt (velocity(); nothing for a
  /// zone particle).
  void shift(double coefficient, double h, double dt, std::size_t a, WaterParticles<D>& P) const {
    P.position[a] += dt * velocity(coefficient, h, a, P);
  }
};

}  // namespace porosph::water
