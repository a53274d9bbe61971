// The submerged (buoyant) density rho^s of seed eq. 16 (Gholami Korzani et al., the effective
// stress approach of section 2.3): a soil particle that is fully submerged carries its submerged
// unit weight, one that is not its total unit weight:
//   rho_i^s = rho_i r_m   when s_i >= s_sub (submerged),   rho_i^s = rho_i   otherwise,
//   r_m = (rho_sat - rho_w) / rho_dry,
// rho_dry = material.density, rho_sat = material.saturated_density or, when that is not given (0),
// rho_dry + n0 rho_w (pores full of water), s_i = sum_a V_a W_ia the kernel-weighted water volume
// fraction around the particle (computed by the coupler, sent to the soil solver as its
// "saturation") and s_sub = coupling.submerged_saturation. The soil solver applies the same rule
// to the particle's weight and the coupler to the seepage term of eq. 16.
#pragma once

#include "scene/scene.h"

namespace porosph::porous {

/// r_m = (rho_sat - rho_w) / rho_dry of material `m` in water of density `water_density`.
inline double submerged_density_ratio(const scene::SoilMaterial& m, double water_density) {
  const double saturated =
      m.saturated_density > 0.0 ? m.saturated_density : m.density + m.porosity * water_density;
  return (saturated - water_density) / m.density;
}

/// rho^s: `density` x `submerged_ratio` (r_m) when `saturation` >= `submerged_saturation`, else
/// `density`.
inline double submerged_density(double density, double saturation, double submerged_saturation,
                                double submerged_ratio) {
  return saturation >= submerged_saturation ? density * submerged_ratio : density;
}

}  // namespace porosph::porous
