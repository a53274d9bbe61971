#include "soil_solver/soil_rates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "soil_solver/artificial_stress.h"
#include "soil_solver/soil_artificial_viscosity.h"
#include "soil_solver/stress_divergence.h"
#include "soil_solver/velocity_gradient.h"
#include "soil_solver/wall_mirror.h"
#include "sph/kernels.h"

namespace porosph::soil {
namespace {

template <int D, class Kernel, bool kViscosity, bool kArtificialStress>
SoilRateSummary acceleration_loop(const sph::NeighbourList<D>& nl, const Kernel& kernel,
                                  const SoilParams<D>& prm, SoilParticles<D>& P) {
  using Vec = sph::Vec<D>;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  const SoilArtificialViscosity av = prm.viscosity;
  const double c = prm.sound_speed;
  const double w_dp = kernel.w(prm.dp);
  const double as_exponent = prm.artificial_stress.exponent;
  const Vec g = prm.gravity;
  P.wall_acceleration.resize(P.n_free);
  P.submergence_acceleration.resize(P.n_free);
  double max_v2 = 0.0, max_a2 = 0.0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : max_v2, max_a2)
  for (std::int64_t i = 0; i < n; ++i) {
    const Vec v_i = P.velocity[i];
    const double rho_i = P.density[i];
    const double rho_weight_i = rho_i * P.weight_ratio[i];  // rho^s of eq. 16 when submerged
    const Eigen::Matrix3d& sigma_i = P.stress[i];
    const std::uint8_t tension_i = kArtificialStress ? P.in_tension[i] : 0;
    Vec acc = Vec::Zero();
    Vec acc_wall = Vec::Zero();  // the fixed neighbours' share: external, in the impulse books
    // The artificial stress and viscosity act per unit of the full mass m, the stress divergence
    // per unit of the effective mass r m: between free neighbours of different submergence
    // (r_i != r_j) the former are not antisymmetric in r m. Their share (r_i - r_j) / 2, whose
    // r m-weighted sum is all they add to the soil's momentum, is summed apart for the impulse
    // books (soil_impulse_book.h).
    const double r_i = P.weight_ratio[i];
    Vec acc_mixed = Vec::Zero();
    const WallView<D> walls = view_walls<D>(nl, i, P, prm.dp, prm.wall_images);
    auto pair_terms = [&](const auto& pair, const Vec& v_j, bool fixed_j) {
      const auto add = [&](const Vec& term) {
        acc += term;
        if (fixed_j) acc_wall += term;
      };
      const double half_dr = fixed_j ? 0.0 : 0.5 * (r_i - P.weight_ratio[pair.b]);
      const auto add_per_full_mass = [&](const Vec& term) {
        add(term);
        if (half_dr != 0.0) acc_mixed += half_dr * term;
      };
      const std::int32_t j = pair.b;
      const Vec grad_w = kernel.grad_factor(pair.r) * pair.x_ab;
      if (fixed_j && walls.images) {
        // eq. 5 against this wall comes from the images below
      } else if (fixed_j && walls.straight) {
        add(wall_stress_divergence_acceleration<D>(P.mass[j], sigma_i, P.stress[j], rho_weight_i,
                                                   P.density[j], grad_w, walls.plane_normal));
      } else {
        add(stress_divergence_acceleration<D>(P.mass[j], sigma_i, P.stress[j], rho_weight_i,
                                              P.density[j], grad_w));
      }
      if constexpr (kArtificialStress) {
        if (tension_i | P.in_tension[j]) {  // else R_i + R_j = 0: no term (and no pow)
          const double f_n = artificial_stress_factor(kernel.w(pair.r), w_dp, as_exponent);
          add_per_full_mass(artificial_stress_acceleration<D>(P.mass[j], P.artificial_stress[i],
                                                              P.artificial_stress[j], f_n, grad_w));
        }
      }
      if constexpr (kViscosity) {
        add_per_full_mass(av.acceleration<D>(P.mass[j], Vec(v_i - v_j), pair.x_ab, pair.r, c, c,
                                             rho_i, P.density[j], grad_w));
      }
    };
    for (auto it = nl.begin(i); it != nl.mid(i); ++it) pair_terms(*it, P.velocity[it->b], false);
    for (auto it = nl.mid(i); it != nl.end(i); ++it) pair_terms(*it, P.wall_velocity[it->b], true);
    if (walls.images) {
      const Vec from_images =
          mirror_stress_divergence_acceleration<D>(nl, kernel, i, P, rho_weight_i, g, walls.face);
      acc += from_images;
      acc_wall += from_images;
    }
    acc += g;
    P.acceleration[i] = acc;
    P.wall_acceleration[i] = acc_wall;
    P.submergence_acceleration[i] = acc_mixed;
    max_v2 = std::max(max_v2, v_i.squaredNorm());
    max_a2 = std::max(max_a2, (acc + P.interaction[i]).squaredNorm());
  }
  return SoilRateSummary{std::sqrt(max_v2), std::sqrt(max_a2)};
}

template <int D, class Kernel, bool kViscosity>
SoilRateSummary dispatch_artificial_stress(const sph::NeighbourList<D>& nl, const Kernel& k,
                                           const SoilParams<D>& prm, SoilParticles<D>& P) {
  if (prm.any_artificial_stress())
    return acceleration_loop<D, Kernel, kViscosity, true>(nl, k, prm, P);
  return acceleration_loop<D, Kernel, kViscosity, false>(nl, k, prm, P);
}

}  // namespace

template <int D>
void update_artificial_stress(const SoilParams<D>& params, SoilParticles<D>& P) {
  const std::int64_t n = static_cast<std::int64_t>(P.size());
  const double epsilon = params.artificial_stress.epsilon;
  P.in_tension.resize(P.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const std::int64_t m = P.material[i];
    const bool on = m < 0 || params.materials[m].artificial_stress;
    if (on) {
      P.artificial_stress[i] = artificial_stress<D>(P.stress[i], P.density[i], epsilon);
    } else {
      P.artificial_stress[i].setZero();
    }
    P.in_tension[i] = (P.artificial_stress[i].array() != 0.0).any() ? 1 : 0;
  }
}

template <int D, class Kernel>
SoilRateSummary compute_soil_rates(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                                   const SoilParams<D>& params, SoilParticles<D>& P) {
  if (params.viscosity_on())
    return dispatch_artificial_stress<D, Kernel, true>(neighbours, kernel, params, P);
  return dispatch_artificial_stress<D, Kernel, false>(neighbours, kernel, params, P);
}

template <int D, class Kernel>
void compute_soil_kinematics(const sph::NeighbourList<D>& nl, const Kernel& kernel,
                             const SoilParams<D>& prm, SoilParticles<D>& P) {
  using Vec = sph::Vec<D>;
  using Mat = MatD<D>;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t i = 0; i < n; ++i) {
    const WallView<D> walls = view_walls<D>(nl, i, P, prm.dp, prm.wall_images);
    const Vec v_i = P.velocity[i];
    Mat grad_v = Mat::Zero();
    double divergence = 0.0;
    for (auto it = nl.begin(i); it != nl.mid(i); ++it) {
      const std::int32_t j = it->b;
      const Vec grad_w = kernel.grad_factor(it->r) * it->x_ab;
      const double volume_j = P.mass[j] / P.density[j];
      accumulate_velocity_gradient<D>(grad_v, volume_j, Vec(P.velocity[j] - v_i), grad_w);
      divergence += volume_j * (v_i - P.velocity[j]).dot(grad_w);
    }
    if (walls.images) add_mirror_kinematics<D>(nl, kernel, i, P, walls.face, grad_v, divergence);
    for (auto it = nl.mid(i); it != nl.end(i) && !walls.images;
         ++it) {  // fixed: own v in continuity
      const std::int32_t w = it->b;
      const Vec grad_w = kernel.grad_factor(it->r) * it->x_ab;
      const double volume_w = P.mass[w] / P.density[w];
      accumulate_velocity_gradient<D>(grad_v, volume_w, Vec(P.wall_velocity[w] - v_i), grad_w);
      divergence += volume_w * (v_i - P.velocity[w]).dot(grad_w);
    }
    P.velocity_gradient[i] = embed_in_3d<D>(grad_v);
    P.density_rate[i] = P.density[i] * divergence;
  }
}

#define POROSPH_INSTANTIATE(D, KERNEL)                                                          \
  template SoilRateSummary compute_soil_rates<D, KERNEL<D>>(                                    \
      const sph::NeighbourList<D>&, const KERNEL<D>&, const SoilParams<D>&, SoilParticles<D>&); \
  template void compute_soil_kinematics<D, KERNEL<D>>(                                          \
      const sph::NeighbourList<D>&, const KERNEL<D>&, const SoilParams<D>&, SoilParticles<D>&);
POROSPH_INSTANTIATE(2, sph::CubicSpline)
POROSPH_INSTANTIATE(2, sph::WendlandC2)
POROSPH_INSTANTIATE(3, sph::CubicSpline)
POROSPH_INSTANTIATE(3, sph::WendlandC2)
#undef POROSPH_INSTANTIATE
template void update_artificial_stress<2>(const SoilParams<2>&, SoilParticles<2>&);
template void update_artificial_stress<3>(const SoilParams<3>&, SoilParticles<3>&);

}  // namespace porosph::soil
