// Porosity from the volumetric strain, seed paper eq. 18-20 (section 2.4):
//   eps_v = (V - V0) / V0                     (eq. 18, extension positive)
//   n = V_voids / V = 1 - V_solids / V        (eq. 19)
//   n = (n0 + eps_v) / (1 + eps_v)            (eq. 20, rigid grains: V_solids constant)
// A particle keeps its mass, so V / V0 = rho0 / rho and eps_v = rho0 / rho - 1 (docs/design.md:
// taken from the density it cannot drift the way an integrated strain trace does). rho and rho0
// must be the same kind of density (both saturated, or both dry): the submerged-weight switch
// changes the weight, not the particle volume.
//
// Admissible range. Eq. 20 gives n < 0 once eps_v < -n0 (compressed beyond the volume of the
// grains) and n -> 1 as eps_v -> infinity; the seepage coefficients of permeability.h diverge
// at both ends (a ~ n^-3 at n -> 0; b ~ n^-2; k ~ (1-n)^-2 at n -> 1). The porosity is therefore
// clamped to [min, max] = [0.01, 0.99] by default: no granular packing reaches n = 0.01 (the
// densest random packing of equal spheres has n ~ 0.36, well-graded soils rarely go below ~0.2),
// and at n = 0.99 the "soil" is a dilute suspension whose drag the seepage law does not describe
// anyway. A scene may narrow the range.
#pragma once

#include <algorithm>

namespace porosph::porous {

struct PorosityRange {
  double min = 0.01;
  double max = 0.99;
};

/// eps_v = rho0 / rho - 1 (volumetric strain from the density ratio, extension positive).
inline double volumetric_strain_from_density(double reference_density, double density) {
  return reference_density / density - 1.0;
}

/// n = (n0 + eps_v) / (1 + eps_v) (eq. 20), unclamped; requires eps_v > -1.
inline double porosity_from_volumetric_strain_unclamped(double initial_porosity,
                                                        double volumetric_strain) {
  return (initial_porosity + volumetric_strain) / (1.0 + volumetric_strain);
}

/// Eq. 20 clamped to `range` (also guards eps_v <= -1, where eq. 20 has no meaning: -> range.min).
inline double porosity_from_volumetric_strain(double initial_porosity, double volumetric_strain,
                                              const PorosityRange& range = {}) {
  if (!(volumetric_strain > -1.0)) return range.min;
  return std::clamp(porosity_from_volumetric_strain_unclamped(initial_porosity, volumetric_strain),
                    range.min, range.max);
}

/// Porosity of a particle from its density: eq. 20 with eps_v = rho0 / rho - 1, clamped.
inline double porosity_from_density(double initial_porosity, double reference_density,
                                    double density, const PorosityRange& range = {}) {
  return porosity_from_volumetric_strain(
      initial_porosity, volumetric_strain_from_density(reference_density, density), range);
}

}  // namespace porosph::porous
