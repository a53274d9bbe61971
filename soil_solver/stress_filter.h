// Periodic filter of the soil stress (stress regularisation, Nguyen, Bui et al. (2017), "A new
// SPH-based approach to simulation of granular flows using viscous damping and stress
// regularisation", Landslides 14, 69-81). The pair form of the stress divergence (eq. 5) cannot see
// a stress that alternates from one particle row to the next (the sums over the rows above and
// below cancel), so such a pattern, once excited by the settling waves, never decays; the filter,
// applied every N steps, removes it:
//   sigma_i <- sum_j w_ij sigma_j      (j over the free soil of i's material, i included)
// with one of two weightings:
//   shepard  w_ij = W_ij V_j / sum_k W_ik V_k  (Nguyen et al. 2017). Exact for a constant field
//            only: where the kernel is cut by a free surface or a wall, it replaces a particle's
//            stress by that of the deeper rows (at the top row of a soil column about twice its
//            own), so near every free face each filtering pushes the soil out of equilibrium.
//   mls      moving least squares of first order (Colagrossi & Landrini 2003, J. Comput. Phys.
//            191, 448-475, there for the water density): w_ij = W_ij V_j beta_i . (1, x_j - x_i)
//            with A_i beta_i = e_1, A_i = sum_j W_ij V_j p_j p_j^T, p_j = (1, x_j - x_i). Exact for
//            a linear field also where the support is cut (a surface row keeps its own stress),
//            and still removes the row-to-row pattern. Falls back to shepard where A_i is near
//            singular or the weights would amplify (a thin flow front; constants below).
// Both stay within one material (averaging sand with gravel mixes two yield cones), and the
// filtered stress is projected back onto the particle's current Drucker-Prager cone with the
// return corrections of Bui et al. 2008 (drucker_prager.h): mls weights can be negative, and a
// wet particle that lost its cohesion must not inherit a dry neighbour's cohesive stress.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "soil_solver/drucker_prager.h"
#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {

/// Smallest determinant of the scaled MLS moment matrix (positions in units of h, divided by
/// A_00^(D+1)) for which the first-order weights are tried. Cubic spline, h = 1.2 dp, 2D lattice:
/// full support 0.098, a flat free surface 0.046, a corner 0.022, a row on one line 0.
constexpr double kMlsMinScaledDeterminant = 1e-2;
/// Largest sum of |w_ij| the first-order weights may have (shepard: 1; a lattice surface row
/// ~1.2). Beyond it a near-degenerate neighbourhood (the thin front of a granular flow) would
/// amplify stress differences at every filtering; shepard is used there instead. A precaution:
/// no run has been shown to need it (the granular collapse that went non-finite with the filter
/// did so through the 0 / 0 of the scaling back, fixed in drucker_prager.h, with shepard too).
constexpr double kMlsMaxAbsWeightSum = 2.0;

/// Filtered stress of free particle i (see the file comment).
template <int D, class Kernel>
Eigen::Matrix3d filtered_stress(StressFilterKind kind, const sph::NeighbourList<D>& neighbours,
                                const Kernel& kernel, double h, const SoilParticles<D>& P,
                                std::size_t i) {
  using Basis = Eigen::Matrix<double, D + 1, 1>;
  const auto same_material = [&](std::int32_t b) { return P.material[b] == P.material[i]; };
  const double self_weight = kernel.w(0.0) * P.mass[i] / P.density[i];
  Eigen::Matrix<double, D + 1, D + 1> moments = Eigen::Matrix<double, D + 1, D + 1>::Zero();
  moments(0, 0) = self_weight;
  Eigen::Matrix3d shepard_sum = self_weight * P.stress[i];
  for (auto it = neighbours.begin(i); it != neighbours.mid(i); ++it) {
    if (!same_material(it->b)) continue;
    const double wv = kernel.w(it->r) * P.mass[it->b] / P.density[it->b];
    shepard_sum += wv * P.stress[it->b];
    Basis p;
    p << 1.0, -it->x_ab / h;  // x_b - x_a in units of h
    moments += wv * p * p.transpose();
  }
  const Eigen::Matrix3d shepard = shepard_sum / moments(0, 0);
  if (kind == StressFilterKind::Shepard ||
      !(moments.determinant() > kMlsMinScaledDeterminant * std::pow(moments(0, 0), D + 1)))
    return shepard;
  const Basis beta = moments.fullPivLu().solve(Basis::Unit(0));
  Eigen::Matrix3d sum = (self_weight * beta(0)) * P.stress[i];
  double abs_weights = std::abs(self_weight * beta(0));
  for (auto it = neighbours.begin(i); it != neighbours.mid(i); ++it) {
    if (!same_material(it->b)) continue;
    Basis p;
    p << 1.0, -it->x_ab / h;
    const double w = kernel.w(it->r) * P.mass[it->b] / P.density[it->b] * beta.dot(p);
    sum += w * P.stress[it->b];
    abs_weights += std::abs(w);
  }
  return abs_weights <= kMlsMaxAbsWeightSum ? sum : shepard;
}

/// Filters the stress of the free particles in place and returns each onto its current yield
/// cone; `scratch` is reused between calls.
template <int D, class Kernel>
void filter_soil_stress(StressFilterKind kind, const sph::NeighbourList<D>& neighbours,
                        const Kernel& kernel, const SoilParams<D>& params, SoilParticles<D>& P,
                        std::vector<Eigen::Matrix3d>& scratch) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  scratch.resize(P.n_free);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < n; ++i)
    scratch[i] =
        filtered_stress(kind, neighbours, kernel, params.h, P, static_cast<std::size_t>(i));
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const SoilMaterialConstants& m = params.materials[P.material[i]];
    P.stress[i] = scratch[i];
    apply_return_corrections(m.current_model(P.wet[i] != 0), P.stress[i]);
  }
}

}  // namespace porosph::soil
