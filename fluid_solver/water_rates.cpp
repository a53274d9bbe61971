#include "fluid_solver/water_rates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "fluid_solver/artificial_viscosity.h"
#include "fluid_solver/continuity.h"
#include "fluid_solver/density_diffusion.h"
#include "fluid_solver/density_diffusion_gradient.h"
#include "fluid_solver/drag_weight.h"
#include "fluid_solver/hydrostatic_difference.h"
#include "fluid_solver/laminar_viscosity.h"
#include "fluid_solver/particle_gradient.h"
#include "fluid_solver/pressure_force.h"
#include "sph/kernels.h"

namespace porosph::water {
namespace {

template <int D, class Kernel, class Laminar, bool kArtificial, bool kNoSlip, bool kDiffusion>
RateSummary rates_loop(const sph::NeighbourList<D>& nl, const Kernel& kernel,
                       const WaterParams<D>& prm, WaterParticles<D>& P, ViscousLevel level) {
  using Vec = sph::Vec<D>;
  constexpr bool kLaminar = !std::is_same_v<Laminar, NoLaminarViscosity>;
  constexpr bool kRegularised = kLaminar || kArtificial || kDiffusion;  // need 1/(r^2 + eta^2)
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  const Vec* vel = P.velocity.data();
  // The velocities the viscous terms act on: v^n, or v^{n-1} on a Verlet step (viscous_level.h).
  const Vec* visc_vel = level == ViscousLevel::Previous ? P.velocity_previous.data() : vel;
  // p_a enters the pressure pair term with +1 (symmetric form) or -1 (difference form, with
  // particle shifting; pressure_force.h).
  const double pressure_sign = prm.shifting_on() ? -1.0 : 1.0;
  const Vec* wall_v = P.wall_velocity.data();
  const double* rho = P.density.data();
  const double* inv_rho = P.inverse_density.data();
  const double* volume = P.volume.data();
  const double* p = P.pressure.data();
  const double* c = P.sound_speed.data();
  const double* m = P.mass.data();
  const double* cut = P.viscosity_cut.data();     // artificial_viscosity.h: 0 without soil
  const double* drag_rate = P.drag_rate.data();   // lambda_a: 0 without soil
  const double* scale = P.gradient_scale.data();  // particle_gradient.h: 1 unless "particle"
  // C_a of "particle_matrix" (particle_gradient.h), null otherwise; with it scale is 1.
  const auto* correction = prm.particle_gradient_matrix ? P.gradient_matrix.data() : nullptr;
  const double eta2 = prm.eta2;
  const LaminarViscosityConstants laminar{prm.mu, prm.eos.rho0()};
  const ArtificialViscosity av = prm.artificial;
  const WallArtificialViscosity av_at_walls = prm.artificial_at_walls;
  const Vec g = prm.gravity;
  const Vec rho0_g = prm.eos.rho0() * g;  // hydrostatic_difference.h
  const bool hydrostatic_difference = prm.hydrostatic_difference_in_soil;
  // The artificial viscosity yields to the drag only when drag-limited or drag-replaced
  // (artificial_viscosity.h).
  const double av_cut_weight = prm.artificial_yields_to_drag() ? 1.0 : 0.0;
  const DensityDiffusion<D> diffusion(prm.density_diffusion, prm.h, prm.eos, g);
  if constexpr (kDiffusion) {
    fill_diffusion_states(diffusion, P, level);  // rho^{n-1} on a Verlet step (viscous_level.h)
    if (prm.diffusion_linear) {
      departure_gradients(nl, kernel, diffusion, P, P.departure_gradient);
    } else {
      P.departure_gradient.assign(P.n_free, Vec::Zero());  // the plain bracket
    }
  }
  P.wall_acceleration.resize(P.n_free);
  P.pressure_form_acceleration.resize(P.n_free);
  const Vec* departure_gradient = P.departure_gradient.data();
  const DiffusionState* diffusion_state = P.diffusion_state.data();
  double max_v2 = 0.0, max_a2 = 0.0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : max_v2, max_a2)
  for (std::int64_t a = 0; a < n; ++a) {
    const Vec v_a = vel[a];
    const double rho_a = rho[a], inv_rho_a = inv_rho[a], p_a = p[a], c_a = c[a];
    Vec acc = Vec::Zero();
    // Inside soil the pressure term is summed in both forms and blended after the loops.
    const bool in_soil = hydrostatic_difference && drag_rate[a] > 0.0;
    SoilPressureSums<D> soil_pressure;
    double divergence = 0.0;
    double diffusion_sum = 0.0;  // D_a / (delta h c0), water neighbours only (density_diffusion.h)
    DiffusionState diffusion_a;
    if constexpr (kDiffusion) diffusion_a = diffusion_state[a];
    // Water neighbours.
    for (auto it = nl.begin(a); it != nl.mid(a); ++it) {
      const std::int32_t b = it->b;
      const double grad_factor = kernel.grad_factor(it->r);
      const auto pair =
          ParticleGradient::water_pair<D>(scale, correction, a, b, grad_factor, it->x_ab, it->r);
      const Vec& grad_w = pair.grad_w;
      const double scaled_factor = pair.factor;
      const Vec v_ab = v_a - vel[b];
      divergence += continuity_term<D>(volume[b], v_ab, grad_w);
      const Vec pressure_term =
          pressure_acceleration<D>(m[b], pressure_sign * p_a, p[b], inv_rho_a, inv_rho[b], grad_w);
      if (in_soil) {
        soil_pressure.add(false, pressure_term, m[b], p_a, p[b], inv_rho_a, inv_rho[b],
                          rho0_g.dot(it->x_ab), volume[b], scaled_factor, it->r, grad_w);
      } else {
        acc += pressure_term;
      }
      if constexpr (kRegularised) {
        const double r2 = it->r * it->r;
        const double inv_r2_eta2 = 1.0 / (r2 + eta2);
        const double factor = regularised_gradient_factor(grad_factor * r2, inv_r2_eta2);
        if constexpr (kDiffusion) {
          diffusion_sum +=
              diffusion.pair_term(diffusion_a, diffusion_state[b], volume[b], it->x_ab, factor,
                                  departure_gradient[a], departure_gradient[b]);
        }
        if constexpr (kLaminar) {
          acc += Laminar::template acceleration<D>(
              laminar, LaminarPair<D>{m[b], rho_a, rho[b], inv_rho_a, inv_rho[b], factor,
                                      Vec(visc_vel[a] - visc_vel[b])});
        }
        if constexpr (kArtificial) {
          acc += av.acceleration<D>(m[b], Vec(visc_vel[a] - visc_vel[b]), it->x_ab, inv_r2_eta2,
                                    c_a, c[b], rho_a, rho[b], grad_w,
                                    1.0 - av_cut_weight * 0.5 * (cut[a] + cut[b]));
        }
      }
    }
    // Wall neighbours (Adami 2012): own velocity in eq. 2, mirrored velocity in viscous terms.
    // Their share is also summed apart: an external force in the solver's impulse books.
    Vec acc_wall = Vec::Zero();
    const auto add_wall_term = [&acc, &acc_wall](const Vec& term) {
      acc += term;
      acc_wall += term;
    };
    Vec wall_normal = Vec::Zero();  // n_a of wall_normal_damping.h
    if constexpr (kNoSlip && kArtificial) {
      if (av_at_walls == WallArtificialViscosity::normal)
        wall_normal = wall_normal_of<D>(nl, kernel, volume, a);
    }
    for (auto it = nl.mid(a); it != nl.end(a); ++it) {
      const std::int32_t b = it->b;
      const double grad_factor = kernel.grad_factor(it->r);
      const auto pair =
          ParticleGradient::wall_pair<D>(scale, correction, a, grad_factor, it->x_ab, it->r);
      const Vec& grad_w = pair.grad_w;
      const double scaled_factor = pair.factor;
      divergence += continuity_term<D>(volume[b], Vec(v_a - vel[b]), grad_w);
      const Vec pressure_term =
          pressure_acceleration<D>(m[b], pressure_sign * p_a, p[b], inv_rho_a, inv_rho[b], grad_w);
      if (in_soil) {
        soil_pressure.add(true, pressure_term, m[b], p_a, p[b], inv_rho_a, inv_rho[b],
                          rho0_g.dot(it->x_ab), volume[b], scaled_factor, it->r, grad_w);
      } else {
        add_wall_term(pressure_term);
      }
      if constexpr (kNoSlip && (kLaminar || kArtificial)) {
        const Vec v_ab = visc_vel[a] - wall_v[b];  // mirrored: v_a - (2 v_w - <v>_w)
        const double r2 = it->r * it->r;
        const double inv_r2_eta2 = 1.0 / (r2 + eta2);
        if constexpr (kLaminar) {
          const double factor = regularised_gradient_factor(grad_factor * r2, inv_r2_eta2);
          add_wall_term(Laminar::template acceleration<D>(
              laminar, LaminarPair<D>{m[b], rho_a, rho[b], inv_rho_a, inv_rho[b], factor, v_ab}));
        }
        if constexpr (kArtificial) {
          if (av_at_walls != WallArtificialViscosity::none)
            add_wall_term(av.acceleration<D>(
                m[b], wall_damped_velocity<D>(av_at_walls, wall_normal, v_ab), it->x_ab,
                inv_r2_eta2, c_a, c[b], rho_a, rho[b], grad_w, 1.0 - av_cut_weight * cut[a]));
        }
      }
    }
    Vec form_residual = Vec::Zero();
    if (in_soil) {
      const auto split = soil_pressure.split(P.drag_weight[a], inv_rho_a, rho0_g);
      acc += split.total;
      acc_wall += split.walls;
      form_residual = split.residual;
    }
    acc += g;
    P.acceleration[a] = acc;
    P.wall_acceleration[a] = acc_wall;
    P.pressure_form_acceleration[a] = form_residual;
    if constexpr (kDiffusion) {
      P.density_rate[a] = rho_a * divergence + diffusion.coefficient() * diffusion_sum;
    } else {
      P.density_rate[a] = rho_a * divergence;
    }
    max_v2 = std::max(max_v2, v_a.squaredNorm());
    if (P.zone[a] < 0)  // inflow-zone particles move as prescribed: no eq. 21 limit from them
      max_a2 = std::max(max_a2, (acc + P.interaction[a]).squaredNorm());
  }
  return RateSummary{std::sqrt(max_v2), std::sqrt(max_a2)};
}

template <int D, class Kernel, class Laminar, bool kArtificial, bool kNoSlip>
RateSummary dispatch_diffusion(const sph::NeighbourList<D>& nl, const Kernel& k,
                               const WaterParams<D>& prm, WaterParticles<D>& P,
                               ViscousLevel level) {
  if (prm.diffusion_on())
    return rates_loop<D, Kernel, Laminar, kArtificial, kNoSlip, true>(nl, k, prm, P, level);
  return rates_loop<D, Kernel, Laminar, kArtificial, kNoSlip, false>(nl, k, prm, P, level);
}

template <int D, class Kernel, class Laminar, bool kArtificial>
RateSummary dispatch_wall(const sph::NeighbourList<D>& nl, const Kernel& k,
                          const WaterParams<D>& prm, WaterParticles<D>& P, ViscousLevel level) {
  if (prm.no_slip)
    return dispatch_diffusion<D, Kernel, Laminar, kArtificial, true>(nl, k, prm, P, level);
  return dispatch_diffusion<D, Kernel, Laminar, kArtificial, false>(nl, k, prm, P, level);
}

template <int D, class Kernel, class Laminar>
RateSummary dispatch_artificial(const sph::NeighbourList<D>& nl, const Kernel& k,
                                const WaterParams<D>& prm, WaterParticles<D>& P,
                                ViscousLevel level) {
  if (prm.artificial_on()) return dispatch_wall<D, Kernel, Laminar, true>(nl, k, prm, P, level);
  return dispatch_wall<D, Kernel, Laminar, false>(nl, k, prm, P, level);
}

}  // namespace

template <int D>
void update_inverse_density_and_volume(WaterParticles<D>& P) {
  const std::int64_t n = static_cast<std::int64_t>(P.size());
  P.inverse_density.resize(P.size());
  P.volume.resize(P.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < n; ++b) {
    P.inverse_density[b] = 1.0 / P.density[b];
    P.volume[b] = P.mass[b] * P.inverse_density[b];
  }
}

template <int D>
void update_water_pressure(const WaterParams<D>& params, WaterParticles<D>& P) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  const TaitEos eos = params.eos;
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) {
    P.pressure[a] = eos.pressure(P.density[a]);
    P.sound_speed[a] = eos.sound_speed(P.density[a]);
  }
}

template <int D, class Kernel>
RateSummary compute_water_rates(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                                const WaterParams<D>& params, WaterParticles<D>& P,
                                ViscousLevel level) {
  update_inverse_density_and_volume(P);
  if (params.particle_gradient) {
    ParticleGradient::compute(neighbours, kernel, P.n_free, P.volume, P.gradient_scale);
  } else {  // every entry stays 1: only new particles need a value
    P.gradient_scale.resize(P.n_free, 1.0);
  }
  if (params.particle_gradient_matrix)
    ParticleGradient::compute_matrix(neighbours, kernel, P.n_free, P.volume, P.gradient_matrix);
  if (params.hydrostatic_difference_in_soil || params.artificial_replaced_by_drag)
    DragWeight::compute(neighbours, P.n_free, P.drag_rate, P.drag_weight);
  if (params.artificial_replaced_by_drag)  // the share the drag replaces (artificial_viscosity.h)
    std::copy(P.drag_weight.begin(), P.drag_weight.end(), P.viscosity_cut.begin());
  return visit_laminar_viscosity<RateSummary>(params.laminar_law(), [&](auto law) {
    return dispatch_artificial<D, Kernel, decltype(law)>(neighbours, kernel, params, P, level);
  });
}

#define POROSPH_INSTANTIATE(D, KERNEL)                                                            \
  template RateSummary compute_water_rates<D, KERNEL<D>>(const sph::NeighbourList<D>&,            \
                                                         const KERNEL<D>&, const WaterParams<D>&, \
                                                         WaterParticles<D>&, ViscousLevel);
POROSPH_INSTANTIATE(2, sph::CubicSpline)
POROSPH_INSTANTIATE(2, sph::WendlandC2)
POROSPH_INSTANTIATE(3, sph::CubicSpline)
POROSPH_INSTANTIATE(3, sph::WendlandC2)
#undef POROSPH_INSTANTIATE
template void update_inverse_density_and_volume<2>(WaterParticles<2>&);
template void update_inverse_density_and_volume<3>(WaterParticles<3>&);
template void update_water_pressure<2>(const WaterParams<2>&, WaterParticles<2>&);
template void update_water_pressure<3>(const WaterParams<3>&, WaterParticles<3>&);

}  // namespace porosph::water
