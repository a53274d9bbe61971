// The soil solver's external-impulse book (docs/coupling.md, "The external-impulse ledger"). The
// soil's equation of motion (seed eq. 16) has the effective mass m^s = r m, r = rho^s / rho the
// weight ratio (the submerged ratio while the particle is submerged, else 1): the stress
// divergence and the interaction act on it, and the momentum they balance is
//   Pi = sum_i r_i m_i v_i      over the free soil (Diagnostics.balance_momentum).
// The kick of a step is v^{n+1} = v^n + dt (a_own + a_int - D_i v^n), a_own = g + (F_pair + F_wall
// + F_load) / (r m) from the rates (r: the ratio they used), a_int the coupler's drag computed on
// r' m (r' the ratio of this step's saturation, set just before the kick), D_i the damping
// stage's rate (soil_solver.h). Per step the book holds
//   gravity         dt sum r' m g                       (the submerged weight where submerged)
//   walls           dt sum r m a_wall                   the fixed neighbours' force (walls, fixed
//                                                        soil; soil_rates.h)
//   loads           dt sum F_load                       [[soil.loads]] (surface_loads.h)
//   damping         -dt sum r' m D_i v^n  during the stage, -sum r' m v of the velocities zeroed
//                   at its end
//   outflow         -sum r' m v of the particles leaving the domain
//   fixed_soil      -dt sum m^s a_int over the fixed soil in the overlap: the coupler books that
//                   drag to the soil, but a fixed bed never moves (its support takes it)
//   inertia_switch  sum (r' - r) m (v^n + dt (a_own - g))   where a particle's submergence
//                   changed this step: the change of its effective mass, not an impulse
//   submergence     dt sum_i m_i sum_j (r_i - r_j) / 2 a_ij   over free neighbours j, a_ij the
//                   artificial stress and viscosity terms: these act per unit of the full mass m
//                   (m_i a_ij = -m_j a_ji), so across a water surface (r_i != r_j) they are not
//                   antisymmetric in r m, and this is all they add to Pi (their symmetric share
//                   (r_i + r_j) / 2 cancels pair by pair). Internal, but not conserving: 0 where
//                   neighbours share r (a soil wholly submerged or dry)
// so that Pi^{n+1} - Pi^n = sum of the book + impulse_to_soil of the coupler's ledger + dt sum
// F_pair, the last 0 to round-off: the stress divergence acts per unit of r m (seed eq. 16), so
// its pairs cancel in Pi whatever r.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "soil_solver/soil_particles.h"
#include "sph/impulse_book.h"

namespace porosph::soil {

/// The soil's sources, in the order of soil_impulse_sources().
enum SoilImpulse : std::size_t {
  kSoilGravity,
  kSoilWalls,
  kSoilLoads,
  kSoilDamping,
  kSoilOutflow,
  kSoilFixedSoil,
  kSoilInertiaSwitch,
  kSoilSubmergence,
  kSoilImpulseCount
};

inline std::vector<std::string> soil_impulse_sources() {
  return {"gravity", "walls",      "loads",          "damping",
          "outflow", "fixed_soil", "inertia_switch", "submergence"};
}

template <int D>
using SoilImpulseBook = sph::ImpulseBook<D, kSoilImpulseCount>;

/// Pi = sum r m v over the particles [begin, end) of P.
template <int D>
sph::Vec<D> effective_momentum(const SoilParticles<D>& P, std::size_t begin, std::size_t end) {
  sph::Vec<D> p = sph::Vec<D>::Zero();
  for (std::size_t i = begin; i < end; ++i) p += (P.weight_ratio[i] * P.mass[i]) * P.velocity[i];
  return p;
}

/// Adds to `book` the gravity, walls, damping (during the stage), inertia_switch and submergence
/// terms (above)
/// of the kick of length dt about to be made: call with the state before it, the saturation of
/// this step already set. `rates_ratio`: the weight ratio of each free particle when the rates
/// were computed (empty: unchanged since); `damping_rate(i)`: D_i (0 outside the stage).
template <int D, class DampingRate>
void book_soil_kick(const SoilParticles<D>& P, const std::vector<double>& rates_ratio,
                    const sph::Vec<D>& g, double dt, const DampingRate& damping_rate,
                    SoilImpulseBook<D>& book) {
  using Vec = sph::Vec<D>;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  const bool ratios_known = rates_ratio.size() == P.n_free;
  double mass = 0.0;  // sum r' m
  double walls[D] = {}, damping[D] = {}, inertia[D] = {}, mixed[D] = {};
#pragma omp parallel for schedule(static) \
    reduction(+ : mass, walls[:D], damping[:D], inertia[:D], mixed[:D])
  for (std::int64_t i = 0; i < n; ++i) {
    const double m = P.mass[i];
    const double r_now = P.weight_ratio[i];
    const double r_rates = ratios_known ? rates_ratio[i] : r_now;
    const Vec& v = P.velocity[i];
    mass += r_now * m;
    const Vec wall = (r_rates * m) * P.wall_acceleration[i];
    const Vec damped = (-dt * r_now * m * damping_rate(i)) * v;
    for (int k = 0; k < D; ++k) {
      walls[k] += dt * wall[k];
      damping[k] += damped[k];
      mixed[k] += dt * m * P.submergence_acceleration[i][k];
    }
    if (r_now != r_rates) {
      const Vec switched = ((r_now - r_rates) * m) * (v + dt * (P.acceleration[i] - g));
      for (int k = 0; k < D; ++k) inertia[k] += switched[k];
    }
  }
  book[kSoilGravity] += (dt * mass) * g;
  for (int k = 0; k < D; ++k) {
    book[kSoilWalls][k] += walls[k];
    book[kSoilDamping][k] += damping[k];
    book[kSoilInertiaSwitch][k] += inertia[k];
    book[kSoilSubmergence][k] += mixed[k];
  }
}

/// Adds to `book` the fixed_soil term (above): `fixed_interaction` holds the index and the
/// interaction acceleration of each fixed soil particle the coupler sent one, whose effective
/// mass is its reference density times `volume` (= dp^D, as the coupler sees it) times its weight
/// ratio of this step.
template <int D>
void book_fixed_soil(const SoilParticles<D>& P,
                     const std::vector<std::pair<std::int32_t, sph::Vec<D>>>& fixed_interaction,
                     double dt, double volume, SoilImpulseBook<D>& book) {
  for (const auto& [i, acceleration] : fixed_interaction) {
    const double effective_mass = P.reference_density[i] * volume * P.weight_ratio[i];
    book[kSoilFixedSoil] -= (dt * effective_mass) * acceleration;
  }
}

}  // namespace porosph::soil
