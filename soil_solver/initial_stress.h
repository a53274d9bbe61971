// Geostatic initial stress of the free soil particles, column by column (geostatic_stress.h):
//   sigma_v(i) = -|g| (sum over the particles j above i in its column of rho_j^s dp
//                      +  rho_i^s dp / 2)
// with rho^s = rho r the density that carries the particle's weight (r = P.weight_ratio: the
// submerged ratio (rho_sat - rho_w) / rho_dry for a particle that starts under water, see
// mark_initially_submerged(), else 1): the effective stress of seed eq. 16, the pore water
// carrying its own hydrostatic pressure.
//   sigma(i)   = K0(i) sigma_v delta + (1 - K0(i)) sigma_v u (x) u,   u = -g / |g|
// A column is the set of particles whose position, projected onto the plane normal to gravity,
// falls in the same dp-wide bin (centred on the lattice); on the fill lattice those are the
// particles stacked above each other dp apart, so the sum is the weight of the soil above i per
// unit area, layer by layer (different materials and densities stack correctly). Fixed particles
// carry nothing. "Up" comes from the gravity vector only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "soil_solver/geostatic_stress.h"
#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "sph/geometry.h"

namespace porosph::soil {

/// D - 1 unit vectors spanning the plane normal to `up` (unit).
template <int D>
std::vector<sph::Vec<D>> horizontal_basis(const sph::Vec<D>& up) {
  std::vector<sph::Vec<D>> basis;
  for (int axis = 0; axis < D && static_cast<int>(basis.size()) < D - 1; ++axis) {
    sph::Vec<D> e = sph::Vec<D>::Unit(axis);
    e -= e.dot(up) * up;  // Gram-Schmidt against up and the vectors found so far
    for (const auto& b : basis) e -= e.dot(b) * b;
    if (e.norm() > 1e-6) basis.push_back(e.normalized());
  }
  return basis;
}

/// Gives the free soil particles that start inside a water block (scene water.blocks) the
/// submerged weight ratio from t = 0: the coupler's first saturation comes only with the first
/// step, and the geostatic stress and the first step's weight must already be those of a
/// submerged particle (else a submerged column starts with the stress of its dry weight and
/// jumps up off its floor: 60 % too much stress at n = 0.4, measured on cases/consolidation).
template <int D>
void mark_initially_submerged(const std::vector<scene::Shape>& water_blocks,
                              const SoilParams<D>& params, SoilParticles<D>& P) {
  for (std::size_t i = 0; i < P.n_free; ++i) {
    for (const scene::Shape& block : water_blocks) {
      if (!sph::inside_shape<D>(block, P.position[i], params.dp)) continue;
      P.weight_ratio[i] = params.materials[P.material[i]].submerged_ratio;
      break;
    }
  }
}

/// Sets the stress of the free particles of P to the geostatic state (see above).
template <int D>
void apply_geostatic_stress(const SoilParams<D>& params, SoilParticles<D>& P) {
  const sph::Vec<D> up = up_direction<D>(params.gravity);
  const double g = params.gravity.norm();
  const std::vector<sph::Vec<D>> basis = horizontal_basis<D>(up);
  // Column key -> (height, particle) of its particles.
  std::map<std::vector<long>, std::vector<std::pair<double, std::size_t>>> columns;
  std::vector<long> key(basis.size());
  // Offsets from the first particle: on the lattice they are whole multiples of dp, far from the
  // rounding boundaries (lattice centres sit at half spacings of the block corner).
  const sph::Vec<D> origin = P.n_free > 0 ? P.position[0] : sph::Vec<D>::Zero();
  for (std::size_t i = 0; i < P.n_free; ++i) {
    for (std::size_t k = 0; k < basis.size(); ++k)
      key[k] = std::lround((P.position[i] - origin).dot(basis[k]) / params.dp);
    columns[key].emplace_back(P.position[i].dot(up), i);
  }
  for (auto& [column_key, members] : columns) {
    std::sort(members.begin(), members.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });  // top first
    double weight_above = 0.0;  // sum of rho dp above, per unit area [kg/m^2]
    for (const auto& [height, i] : members) {
      const double rho_weight = P.density[i] * P.weight_ratio[i];
      const double sigma_v = -g * (weight_above + 0.5 * rho_weight * params.dp);
      P.stress[i] =
          geostatic_stress<D>(params.gravity, sigma_v, params.materials[P.material[i]].k0);
      weight_above += rho_weight * params.dp;
    }
  }
}

}  // namespace porosph::soil
