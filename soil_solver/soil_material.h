// The constants the elastic-perfectly-plastic Drucker-Prager soil model needs per material
// (seed paper section 2.2: eq. 6 elasticity, eq. 9-11 yield function and plastic potential),
// built from the engineering parameters a scene gives.
#pragma once

#include "soil_solver/drucker_prager_constants.h"
#include "soil_solver/elastic_constants.h"

namespace porosph::soil {

/// Engineering parameters of one soil material, as a scene states them.
struct MaterialParameters {
  double young = 0.0;                ///< E [Pa]
  double poisson = 0.0;              ///< nu [-]
  double friction_angle_deg = 0.0;   ///< phi [degrees]
  double cohesion = 0.0;             ///< c [Pa]
  double dilatancy_angle_deg = 0.0;  ///< psi [degrees]
  DilatancyForm dilatancy_form = DilatancyForm::kPlaneStrainFit;
  YieldFit yield_fit = YieldFit::kSeedPaperEq10;
};

/// What the constitutive functions use: K, G and the Drucker-Prager constants.
struct Material {
  double bulk_modulus = 0.0;   ///< K [Pa]
  double shear_modulus = 0.0;  ///< G [Pa]
  double alpha_phi = 0.0;      ///< yield-function friction coefficient, eq. 10 [-]
  double k_c = 0.0;            ///< yield-function cohesion term, eq. 10 [Pa]
  double beta_psi = 0.0;       ///< plastic-potential dilatancy coefficient [-]
};

/// Material from E, nu, phi, c, psi (throws std::invalid_argument on inadmissible values).
inline Material make_material(const MaterialParameters& p) {
  const ElasticConstants e = elastic_from_young_poisson(p.young, p.poisson);
  const DruckerPragerConstants dp = drucker_prager_plane_strain(
      degrees_to_radians(p.friction_angle_deg), p.cohesion,
      degrees_to_radians(p.dilatancy_angle_deg), p.dilatancy_form, p.yield_fit);
  Material m;
  m.bulk_modulus = e.bulk_modulus;
  m.shear_modulus = e.shear_modulus;
  m.alpha_phi = dp.alpha_phi;
  m.k_c = dp.k_c;
  m.beta_psi = dp.beta_psi;
  return m;
}

}  // namespace porosph::soil
