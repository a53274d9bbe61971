// Elastic constants and plane-strain Drucker-Prager constants (seed paper eq. 10) against hand
// calculations.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "soil_solver/drucker_prager_constants.h"
#include "soil_solver/elastic_constants.h"
#include "soil_solver/soil_material.h"

namespace porosph::soil {
namespace {

// Relative tolerance for closed-form values evaluated in double precision: a few ulps of
// tan/sqrt/sin, far below any physical meaning.
constexpr double kClosedForm = 1e-13;

TEST(ElasticConstants, YoungPoissonToBulkShearAndBack) {
  // Bui et al. 2008 granular column (CASES.md): E = 0.84 MPa, nu = 0.3 ->
  // K = 0.84e6 / (3 * 0.4) = 0.7 MPa, G = 0.84e6 / 2.6 = 323076.923... Pa.
  const ElasticConstants e = elastic_from_young_poisson(0.84e6, 0.3);
  EXPECT_NEAR(e.bulk_modulus, 0.7e6, 0.7e6 * kClosedForm);
  EXPECT_NEAR(e.shear_modulus, 323076.92307692306, 3.3e5 * kClosedForm);
  const ElasticConstants back = elastic_from_bulk_shear(e.bulk_modulus, e.shear_modulus);
  EXPECT_NEAR(back.young, 0.84e6, 0.84e6 * kClosedForm);
  EXPECT_NEAR(back.poisson, 0.3, 0.3 * kClosedForm);
}

TEST(ElasticConstants, RejectsInadmissibleValues) {
  EXPECT_THROW(elastic_from_young_poisson(-1.0, 0.3), std::invalid_argument);
  EXPECT_THROW(elastic_from_young_poisson(1e6, 0.5), std::invalid_argument);
  EXPECT_THROW(elastic_from_young_poisson(1e6, -1.0), std::invalid_argument);
  EXPECT_THROW(elastic_from_bulk_shear(0.0, 1e6), std::invalid_argument);
}

TEST(DruckerPragerConstants, Phi30Cohesion10kPaMatchHandValues) {
  // tan 30 = 1/sqrt(3), tan^2 = 1/3, 9 + 12/3 = 13:
  //   alpha = (1/sqrt 3) / sqrt 13 = 1/sqrt(39) = 0.16012815380508713
  //   k_c   = 3 * 10000 / sqrt 13  = 8320.502943378437 Pa
  const DruckerPragerConstants dp =
      drucker_prager_plane_strain(degrees_to_radians(30.0), 10e3, 0.0);
  EXPECT_NEAR(dp.alpha_phi, 0.16012815380508713, 0.16 * kClosedForm);
  EXPECT_NEAR(dp.k_c, 8320.502943378437, 8320.5 * kClosedForm);
  EXPECT_EQ(dp.beta_psi, 0.0);  // psi = 0: plastically incompressible in both forms
  // The apex of the cone (I1 = k_c / alpha) is the Mohr-Coulomb one: mean stress c cot(phi).
  EXPECT_NEAR(dp.k_c / dp.alpha_phi / 3.0, 10e3 / std::tan(degrees_to_radians(30.0)),
              17320.5 * kClosedForm);
}

TEST(DruckerPragerConstants, DilatancyForms) {
  const double phi = degrees_to_radians(30.0), psi = degrees_to_radians(10.0);
  // Plane-strain fit: psi = phi gives associated flow, beta_psi == alpha_phi.
  const DruckerPragerConstants assoc = drucker_prager_plane_strain(phi, 0.0, phi);
  EXPECT_DOUBLE_EQ(assoc.beta_psi, assoc.alpha_phi);
  // psi = 10 deg: tan 10 = 0.17632698070846498, sqrt(9 + 12 tan^2) = 3.0615509875729920:
  const double t = 0.17632698070846498;
  const DruckerPragerConstants fit = drucker_prager_plane_strain(phi, 0.0, psi);
  EXPECT_NEAR(fit.beta_psi, t / std::sqrt(9.0 + 12.0 * t * t), 0.06 * kClosedForm);
  EXPECT_NEAR(fit.beta_psi, 0.0575940, 1e-7);  // hand value to the 7 digits written
  // Literal eq. 11: beta = 3 sin(10 deg) = 0.5209445330007912.
  const DruckerPragerConstants lit =
      drucker_prager_plane_strain(phi, 0.0, psi, DilatancyForm::kSeedPaperEq11);
  EXPECT_NEAR(lit.beta_psi, 0.5209445330007912, 0.52 * kClosedForm);
}

TEST(DruckerPragerConstants, RejectsInadmissibleAngles) {
  EXPECT_THROW(drucker_prager_plane_strain(degrees_to_radians(90.0), 0.0, 0.0),
               std::invalid_argument);
  EXPECT_THROW(drucker_prager_plane_strain(degrees_to_radians(20.0), 0.0, degrees_to_radians(25.0)),
               std::invalid_argument);
  EXPECT_THROW(drucker_prager_plane_strain(degrees_to_radians(20.0), -1.0, 0.0),
               std::invalid_argument);
}

TEST(SoilMaterial, FluidisedBedSand) {
  // CASES.md fluidized_bed sand: E 5 MPa, nu 0.3, phi 22, c 0, psi 0.
  // K = 5e6 / 1.2 = 4166666.67 Pa, G = 5e6 / 2.6 = 1923076.92 Pa,
  // alpha = tan 22 / sqrt(9 + 12 tan^2 22) = 0.40402623 / 3.31041482 = 0.122047008473322.
  MaterialParameters p;
  p.young = 5e6;
  p.poisson = 0.3;
  p.friction_angle_deg = 22.0;
  const Material m = make_material(p);
  EXPECT_NEAR(m.bulk_modulus, 5e6 / 1.2, 4.2e6 * kClosedForm);
  EXPECT_NEAR(m.shear_modulus, 5e6 / 2.6, 1.9e6 * kClosedForm);
  EXPECT_NEAR(m.alpha_phi, 0.122047008473322, 0.12 * kClosedForm);
  EXPECT_EQ(m.k_c, 0.0);
  EXPECT_EQ(m.beta_psi, 0.0);
}

}  // namespace
}  // namespace porosph::soil
