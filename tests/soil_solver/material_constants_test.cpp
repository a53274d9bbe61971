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
  // Bui et al. 2008 granular column (docs/cases.md): E = 0.84 MPa, nu = 0.3 ->
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

TEST(DruckerPragerConstants, FlowRuleFitForPsiZeroIsSinPhiOverThree) {
  // psi = 0: plane-strain plastic flow keeps s_zz = 0, so sqrt(J2) is the in-plane maximum shear
  // t and I1 = 3 p_in: Mohr-Coulomb t = c cos(phi) - p_in sin(phi) gives alpha_phi = sin(phi) / 3,
  // k_c = c cos(phi). phi 41, c 1.5 kPa: 0.218686 and 1132.06 Pa (eq. 10: 0.204507, 1059.0 Pa).
  const double phi = degrees_to_radians(41.0);
  const auto fit = drucker_prager_plane_strain(phi, 1500.0, 0.0, DilatancyForm::kPlaneStrainFit,
                                               YieldFit::kFlowRule);
  EXPECT_NEAR(fit.alpha_phi, std::sin(phi) / 3.0, 1e-15);
  EXPECT_NEAR(fit.alpha_phi, 0.2186863, 1e-7);
  EXPECT_NEAR(fit.k_c, 1500.0 * std::cos(phi), 1e-11);
  EXPECT_EQ(fit.beta_psi, 0.0);
  const auto eq10 = drucker_prager_plane_strain(phi, 1500.0, 0.0);
  EXPECT_NEAR(eq10.alpha_phi, 0.2045074, 1e-7);
  EXPECT_GT(fit.alpha_phi, 1.06 * eq10.alpha_phi);  // 6.9 % wider cone at psi = 0
}

TEST(DruckerPragerConstants, FlowRuleFitIsEq10ForAssociatedFlow) {
  // psi = phi with the plane-strain-fit beta_psi: the flow rule is associated, and the fit must
  // give eq. 10 back (to round-off).
  for (double deg : {10.0, 29.0, 41.0}) {
    const double phi = degrees_to_radians(deg);
    const auto fit = drucker_prager_plane_strain(phi, 2000.0, phi, DilatancyForm::kPlaneStrainFit,
                                                 YieldFit::kFlowRule);
    const auto eq10 = drucker_prager_plane_strain(phi, 2000.0, phi);
    EXPECT_NEAR(fit.alpha_phi, eq10.alpha_phi, 1e-14) << deg;
    EXPECT_NEAR(fit.k_c, eq10.k_c, 1e-10) << deg;
  }
}

TEST(DruckerPragerConstants, FlowRuleFitPutsThePlaneStrainFailureStateOnTheCone) {
  // phi 35, psi 10, c 5 kPa. A plane-strain state at Mohr-Coulomb failure with the s_zz that the
  // flow rule leaves (eps_dot_zz = 0: s_zz = -2 beta_psi sqrt(J2)): p_in = -40 kPa, t = c cos(phi)
  // - p_in sin(phi). Built in principal axes: sigma_1,3 = p_in +- t, sigma_z = p_in + 1.5 s_zz
  // with s_zz solved from J2 = t^2 + 0.75 s_zz^2. Its yield function must be 0 (round-off).
  const double phi = degrees_to_radians(35.0), psi = degrees_to_radians(10.0), c = 5000.0;
  const auto dp =
      drucker_prager_plane_strain(phi, c, psi, DilatancyForm::kPlaneStrainFit, YieldFit::kFlowRule);
  const double p_in = -40e3, t = c * std::cos(phi) - p_in * std::sin(phi);
  const double sqrt_j2 = t / std::sqrt(1.0 - 3.0 * dp.beta_psi * dp.beta_psi);
  const double s_zz = -2.0 * dp.beta_psi * sqrt_j2;
  const double s1 = p_in + t, s3 = p_in - t, sz = p_in + 1.5 * s_zz;
  const double i1 = s1 + s3 + sz, mean = i1 / 3.0;
  const double j2 =
      0.5 * ((s1 - mean) * (s1 - mean) + (s3 - mean) * (s3 - mean) + (sz - mean) * (sz - mean));
  EXPECT_NEAR(std::sqrt(j2), sqrt_j2, 1e-9 * t);
  EXPECT_NEAR(std::sqrt(j2) + dp.alpha_phi * i1 - dp.k_c, 0.0, 1e-9 * t);
  // The same state against eq. 10's cone: outside (f > 0), the cone is narrower.
  const auto eq10 = drucker_prager_plane_strain(phi, c, psi);
  EXPECT_GT(std::sqrt(j2) + eq10.alpha_phi * i1 - eq10.k_c, 0.01 * t);
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
  // docs/cases.md fluidized_bed sand: E 5 MPa, nu 0.3, phi 22, c 0, psi 0.
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
