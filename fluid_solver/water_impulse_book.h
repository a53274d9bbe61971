// The water solver's external-impulse book (docs/coupling.md, "The external-impulse ledger"): by
// how much each source changed the momentum P = sum_a m_a v_a of the free water (inflow-zone
// particles included) over one step, exactly as the integrator applies it. With a_own = g + a_wall
// + a_pair the particle's own acceleration (water_rates.h; a_wall its wall neighbours' share,
// a_pair the water pairs') and a_int the coupler's interaction, the modified Verlet step of a free
// particle (sph/integrator.h, verlet_step_coupled; q^n the stored previous velocity) is
//   v^{n+1} - v^n = [q^n - v^n + dt_previous a_own] + dt (g + a_wall + a_pair) + dt a_int
// (Verlet), the bracket absent on Euler steps. Per step the book holds
//   gravity       dt sum m g                      over the integrated (non-zone) particles
//   walls         dt sum m a_wall                 over the integrated particles
//   verlet_chain  sum m (q^n - v^n + dt_previous a_own)   Verlet steps, integrated particles: the
//                 momentum of the other time level minus the reported one plus the earlier span's
//                 share of the own forces. Not an external impulse: the two Verlet chains differ
//                 by it. It vanishes for constant forces (v^n = q^n + dt_previous a) and sums over
//                 a run to the difference between the chains' momenta, which Euler steps reset.
//   inflow        sum m (u^{n+1} - v^n) - dt sum m (a_own - g - a_wall + a_int)   over the zone
//                 particles (inflow zones and open reservoirs' buffers), which move at the
//                 prescribed u (flow_zones.h, open_reservoirs.h) instead of their
//                 equation of motion: what the zone's "piston" adds beyond the forces of the water
//                 and the interaction on them (their gravity and walls are simply not applied);
//                 plus sum m v of the particles the zones create
//   outflow       -sum m v of the particles removed in outflow zones or leaving the domain, and
//                 of those an open reservoir removes (above its level, past its far face)
//   reservoir     sum m v of the particles a reservoir adds, minus those it removes
//   damping       -sum m v of the velocities zeroed at the end of the damping stage
//   pressure_form dt sum m a_form over all free particles (zone particles too): what the
//                 hydrostatic difference form inside soil adds beyond antisymmetric pressure
//                 pairs (hydrostatic_difference.h); 0 with the symmetric form
// so that P^{n+1} - P^n = sum of the book + dt sum m a_int (the coupler's ledger) + dt sum m
// a_pair, the last zero to round-off where the pair forces are antisymmetric (the symmetric
// pressure form; not the difference form that particle shifting uses, pressure_force.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fluid_solver/flow_zones.h"
#include "fluid_solver/open_reservoirs.h"
#include "fluid_solver/water_particles.h"
#include "sph/impulse_book.h"

namespace porosph::water {

/// The water's sources, in the order of water_impulse_sources().
enum WaterImpulse : std::size_t {
  kWaterGravity,
  kWaterWalls,
  kWaterInflow,
  kWaterOutflow,
  kWaterReservoir,
  kWaterDamping,
  kWaterVerletChain,
  kWaterPressureForm,
  kWaterImpulseCount
};

inline std::vector<std::string> water_impulse_sources() {
  return {"gravity",   "walls",   "inflow",       "outflow",
          "reservoir", "damping", "verlet_chain", "pressure_form"};
}

template <int D>
using WaterImpulseBook = sph::ImpulseBook<D, kWaterImpulseCount>;

/// sum m v over the particles [begin, end) of P.
template <int D>
sph::Vec<D> momentum_of(const WaterParticles<D>& P, std::size_t begin, std::size_t end) {
  sph::Vec<D> p = sph::Vec<D>::Zero();
  for (std::size_t a = begin; a < end; ++a) p += P.mass[a] * P.velocity[a];
  return p;
}

/// Adds to `book` the gravity, walls, verlet_chain and zone-particle inflow terms (above) of the
/// step of length dt that is about to integrate P's free particles: call with the state before
/// it, after zones.begin_step(time, dt) and open.begin_step(P, time). `euler`: an Euler step of the
/// modified Verlet scheme.
template <int D>
void book_water_integration(const WaterParticles<D>& P, const sph::Vec<D>& g, double dt,
                            double dt_previous, bool euler, const FlowZones<D>& zones,
                            const OpenReservoirs<D>& open, WaterImpulseBook<D>& book) {
  using Vec = sph::Vec<D>;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  double mass = 0.0;                    // of the integrated particles
  double walls[D] = {}, chain[D] = {};  // sum m a_wall; sum m (q - v + dt_previous a_own)
  double zone[D] = {};                  // zone particles: sum m (u_end - v) - dt m (...)
  double form[D] = {};                  // sum m a_form
#pragma omp parallel for schedule(static) \
    reduction(+ : mass, walls[:D], chain[:D], zone[:D], form[:D])
  for (std::int64_t a = 0; a < n; ++a) {
    const double m = P.mass[a];
    const Vec& a_own = P.acceleration[a];
    for (int k = 0; k < D; ++k) form[k] += m * P.pressure_form_acceleration[a][k];
    if (P.zone[a] >= 0) {
      const int z = P.zone[a];
      const Vec end = open.owns(z) ? open.velocity_at(z, P.position[a]) : zones.end_velocity(z);
      const Vec driven =
          (end - P.velocity[a]) - dt * (a_own - g - P.wall_acceleration[a] + P.interaction[a]);
      for (int k = 0; k < D; ++k) zone[k] += m * driven[k];
      continue;
    }
    mass += m;
    for (int k = 0; k < D; ++k) walls[k] += m * P.wall_acceleration[a][k];
    if (euler) continue;
    const Vec switched = P.velocity_previous[a] - P.velocity[a] + dt_previous * a_own;
    for (int k = 0; k < D; ++k) chain[k] += m * switched[k];
  }
  book[kWaterGravity] += (dt * mass) * g;
  for (int k = 0; k < D; ++k) {
    book[kWaterWalls][k] += dt * walls[k];
    book[kWaterVerletChain][k] += chain[k];
    book[kWaterInflow][k] += zone[k];
    book[kWaterPressureForm][k] += dt * form[k];
  }
}

}  // namespace porosph::water
