// What the soil solver reports: the overlap set and diagnostics sent to the coupler each step, the
// non-finite check, and the snapshot fields of soil.h5 (docs/design.md section 6).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"
#include "soil_solver/soil_particles.h"
#include "sph/free_particle_totals.h"
#include "sph/non_finite_report.h"
#include "sph/particle_fields.h"

namespace porosph::soil {

/// The soil particles (free and fixed soil, not walls) inside [lo, hi] (empty bounds: none): their
/// indices into `index` and their id, position, velocity, density, mass, porosity and material
/// into `out`. Fixed soil (a porous bed) reports its material's density and the mass
/// reference density x `volume` it was created with: its soil_walls.h density is a boundary value
/// of the soil's own stress sums, and the interaction needs only its volume m / rho, the same
/// either way (to round-off). Constant values let the state deltas leave fixed particles out
/// (proto/state_delta.h).
template <int D>
void fill_soil_overlap(const SoilParticles<D>& P, double volume, const std::vector<double>& lo,
                       const std::vector<double>& hi, std::vector<std::int32_t>& index,
                       coupling::StepState& out) {
  index.clear();
  out.clear_overlap();
  if (lo.size() != D || hi.size() != D) return;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.material[i] < 0) continue;  // walls; fixed soil (a porous bed) does exchange drag
    const sph::Vec<D>& x = P.position[i];
    bool inside = true;
    for (int k = 0; k < D; ++k) inside = inside && x[k] >= lo[k] && x[k] <= hi[k];
    if (!inside) continue;
    index.push_back(static_cast<std::int32_t>(i));
    out.overlap_id.push_back(P.id[i]);
    for (int k = 0; k < D; ++k) out.overlap_position.push_back(x[k]);
    for (int k = 0; k < D; ++k) out.overlap_velocity.push_back(P.velocity[i][k]);
    const bool fixed = i >= P.n_free;
    out.overlap_density.push_back(fixed ? P.reference_density[i] : P.density[i]);
    out.overlap_mass.push_back(fixed ? P.reference_density[i] * volume : P.mass[i]);
    out.overlap_porosity.push_back(P.porosity[i]);
    out.overlap_material.push_back(static_cast<std::int32_t>(P.material[i]));
    // The kick v^{n+1} = v^n + dt (a + a_int) starts from v^n; its own acceleration is predicted
    // by the latest rates' (the coupler's pairwise implicit drag, porosph.proto). Fixed: at rest.
    for (int k = 0; k < D; ++k) out.overlap_update_base.push_back(fixed ? 0.0 : P.velocity[i][k]);
    for (int k = 0; k < D; ++k)
      out.overlap_update_rate.push_back(fixed ? 0.0 : P.acceleration[i][k]);
  }
}

/// Mass, momentum, kinetic energy and max speed of the free soil (one parallel pass) and the
/// bounding box of the soil that interacts with water, fixed soil included (+inf / -inf: none).
template <int D>
void fill_soil_diagnostics(const SoilParticles<D>& P, std::vector<double>& region_min,
                           std::vector<double>& region_max, coupling::Diagnostics& d) {
  sph::FreeParticleTotals<D> t =
      sph::free_particle_totals<D>(P.position.data(), P.velocity.data(), P.mass.data(), P.n_free);
  for (std::size_t i = P.n_free; i < P.size(); ++i) {  // fixed soil interacts with water too
    if (P.material[i] < 0) continue;
    t.lo = t.lo.cwiseMin(P.position[i]);
    t.hi = t.hi.cwiseMax(P.position[i]);
  }
  region_min.assign(t.lo.data(), t.lo.data() + D);
  region_max.assign(t.hi.data(), t.hi.data() + D);
  d.particle_count = P.size();
  d.free_count = P.n_free;
  d.mass = t.mass;
  d.kinetic_energy = t.kinetic_energy;
  d.max_speed = t.max_speed;
  d.momentum.assign(t.momentum, t.momentum + D);
}

/// "non-finite stress of soil particle 12 (x = ...) at step 3, t = ... s" for the first particle
/// with a non-finite position, velocity, density or stress; std::nullopt if there is none.
template <int D>
std::optional<std::string> find_non_finite_soil(const SoilParticles<D>& P, std::uint64_t step,
                                                double time, std::int64_t* particle_id) {
  const std::int64_t n = static_cast<std::int64_t>(P.size());
  if (P.size() == 0 || (sph::all_finite(P.position.data()->data(), P.size() * D) &&
                        sph::all_finite(P.velocity.data()->data(), P.size() * D) &&
                        sph::all_finite(P.density.data(), P.size()) &&
                        sph::all_finite(P.stress.data()->data(), P.size() * 9))) {
    return std::nullopt;
  }
  std::int64_t first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!P.position[i].allFinite() || !P.velocity[i].allFinite() || !std::isfinite(P.density[i]) ||
        !P.stress[i].allFinite())
      first = std::min(first, i);
  }
  if (first == n) return std::nullopt;
  const char* what = !P.position[first].allFinite()     ? "position"
                     : !P.velocity[first].allFinite()   ? "velocity"
                     : !std::isfinite(P.density[first]) ? "density"
                                                        : "stress";
  if (particle_id != nullptr) *particle_id = P.id[first];
  return sph::non_finite_message<D>(what, P.fixed[first] ? "fixed" : "soil", P.id[first],
                                    P.position[first], P.velocity[first], P.density[first], step,
                                    time);
}

/// Views of the soil.h5 fields of every particle (fixed ones included).
template <int D>
std::vector<io::FieldView> soil_snapshot_fields(const SoilParticles<D>& P) {
  return {sph::packed_field("position", P.position, "m"),
          sph::packed_field("velocity", P.velocity, "m/s"),
          sph::scalar_field("density", P.density, "kg/m^3"),
          // A symmetric 3x3 matrix: its column-major storage equals the row-major layout.
          sph::packed_field("stress", P.stress, "Pa"), sph::scalar_field("porosity", P.porosity),
          sph::scalar_field("plastic_strain", P.plastic_strain),
          sph::packed_field("displacement", P.displacement, "m"),
          sph::scalar_field("saturation", P.saturation), sph::scalar_field("id", P.id),
          sph::scalar_field("material", P.material), sph::scalar_field("fixed", P.fixed)};
}

}  // namespace porosph::soil
