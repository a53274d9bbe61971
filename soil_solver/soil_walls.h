// Fixed particles of the soil phase (walls, gates and fixed soil): their stress, density and the
// velocity the viscous terms see, extrapolated each step from the free soil around them. The soil
// analogue of Adami, Hu & Adams (2012) eq. 22-23 and 27-28 (see fluid_solver/wall_boundary.h):
//   sigma_w = (sum_f sigma_f W_wf - [(g - a_w) . sum_f rho_f x_wf W_wf] delta) / sum_f W_wf
//   rho_w   = sum_f rho_f W_wf / sum_f W_wf,   m_w = rho_w dp^D (volume of its lattice site)
//   v~_w    = 2 v_w - v_f^       (no-slip: the soil's velocity mirrored, v_f^ = sum_f v_f W / sum
//   W) v~_w    = v_f^ - 2 ((v_f^ - v_w) . n_w) n_w   (free-slip: only the normal part mirrored)
// n_w = sum_f x_fw W_wf / |...|, the direction from the wall particle into the soil around it, so
// a free-slip wall still stops the soil moving into it (the strain rate of eq. 7 sees the normal
// approach) but offers no resistance along it. The velocity gradient and the artificial viscosity
// use v~_w; the continuity equation uses v_w (Adami et al. 2012). A free-slip wall also reflects
// the stress across its plane, sigma_w = M sigma_f^ M with M = I - 2 n n (the normal-tangential
// shear changes sign, the rest is kept), so the shear traction on the wall plane vanishes. n here
// is the geometric normal of wall_normals.h (zero at corners: no reflection, the point reflection
// of a corner leaves the stress as it is), or the soil-side estimate where the geometry gives none.
// With the Shepard stress as it is, the shear locked in while a column settles hangs the soil on
// the walls (measured: a frictionless 1 m column carried 9 % more than its weight at the bottom).
// x_wf = x_w - x_f, tension positive (hence the minus sign: below the soil the wall is more
// compressed by the weight of the soil between w and f). That is the "weight" continuation of
// soil.wall_stress_continuation (the default); "linear" continues each neighbour's stress with its
// own gradient instead, sigma_f + grad sigma_f . x_wf, exact for a geostatic state's horizontal
// stress too (wall_stress_continuation.h); a neighbour whose gradient is not trusted keeps the
// weight form.
// A fixed particle without free neighbours keeps zero stress, its reference density and v~ = v_w.
#pragma once

#include <cstdint>

#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "soil_solver/velocity_gradient.h"
#include "soil_solver/wall_stress_continuation.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {

/// `gradients`: scratch for the free particles' stress gradients (used with the linear
/// continuation; kept between calls so that it allocates once).
template <int D, class Kernel>
void update_soil_wall_state(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                            const SoilParams<D>& params, SoilParticles<D>& P,
                            std::vector<StressGradient<D>>& gradients) {
  using Vec = sph::Vec<D>;
  const std::int64_t n0 = static_cast<std::int64_t>(P.n_free);
  const std::int64_t n1 = static_cast<std::int64_t>(P.size());
  const Vec body = params.gravity;  // fixed particles: a_w = 0
  const bool linear = params.linear_wall_stress;
  if (linear) stress_gradients_next_to_walls<D>(neighbours, kernel, P, gradients);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t w = n0; w < n1; ++w) {
    double sum_w = 0.0, sum_rho_w = 0.0;
    Eigen::Matrix3d sum_sigma_w = Eigen::Matrix3d::Zero();
    Vec sum_rho_x_w = Vec::Zero(), sum_v_w = Vec::Zero(), sum_x_w = Vec::Zero();
    for (auto it = neighbours.begin(w); it != neighbours.mid(w); ++it) {  // free soil only
      const double kw = kernel.w(it->r);
      sum_w += kw;
      sum_rho_w += P.density[it->b] * kw;
      sum_sigma_w += kw * P.stress[it->b];
      if (linear && gradients[it->b].trusted)
        sum_sigma_w.noalias() += kw * limited_change(gradients[it->b].change_over(it->x_ab),
                                                     -P.density[it->b] * body.dot(it->x_ab));
      else
        sum_rho_x_w += (P.density[it->b] * kw) * it->x_ab;
      sum_v_w += kw * P.velocity[it->b];
      sum_x_w += kw * it->x_ab;
    }
    if (sum_w > 0.0) {
      Eigen::Matrix3d sigma = sum_sigma_w / sum_w;
      P.density[w] = sum_rho_w / sum_w;
      const Vec mean_v = sum_v_w / sum_w;
      if (P.no_slip[w]) {
        P.wall_velocity[w] = 2.0 * P.velocity[w] - mean_v;
      } else {
        const double norm = sum_x_w.norm();
        const Vec normal = norm > 0.0 ? Vec(-sum_x_w / norm) : Vec::Zero();
        P.wall_velocity[w] = mean_v - 2.0 * (mean_v - P.velocity[w]).dot(normal) * normal;
        const Vec& geometric = P.wall_normal[w];
        const Eigen::Vector3d n3 = embed_in_3d<D>(geometric.allFinite() ? geometric : normal);
        const Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity() - 2.0 * n3 * n3.transpose();
        sigma = mirror * sigma * mirror;  // shear along the wall reflected: zero traction there
      }
      P.stress[w] = sigma - (body.dot(sum_rho_x_w) / sum_w) * Eigen::Matrix3d::Identity();
    } else {
      P.stress[w].setZero();
      P.density[w] = P.reference_density[w];
      P.wall_velocity[w] = P.velocity[w];
    }
    P.mass[w] = P.density[w] * params.volume;
  }
}

}  // namespace porosph::soil
