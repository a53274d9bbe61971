// Porosity from volumetric strain (seed paper eq. 18-20) and the seepage coefficients of
// eq. 14 (Kozeny-Carman) and eq. 15 (Den Adel), against hand calculations.
#include <gtest/gtest.h>

#include "porous/permeability.h"
#include "porous/porosity.h"

namespace porosph::porous {
namespace {

constexpr double kClosedForm = 1e-13;  // relative; a handful of flops

TEST(Porosity, Eq20ForKnownVolumetricStrains) {
  // n0 = 0.46: eps_v = 0.1  -> 0.56 / 1.1  = 0.509090909...
  //            eps_v = -0.05 -> 0.41 / 0.95 = 0.431578947...
  //            eps_v = 0    -> n0
  EXPECT_NEAR(porosity_from_volumetric_strain(0.46, 0.1), 0.56 / 1.1, kClosedForm);
  EXPECT_NEAR(porosity_from_volumetric_strain(0.46, 0.1), 0.5090909091, 1e-10);
  EXPECT_NEAR(porosity_from_volumetric_strain(0.46, -0.05), 0.4315789474, 1e-10);
  EXPECT_DOUBLE_EQ(porosity_from_volumetric_strain(0.46, 0.0), 0.46);
  // The fluidised bed expands from n0 = 0.46 to n = 0.51 at eps_v = (n - n0) / (1 - n) = 0.05/0.49.
  EXPECT_NEAR(porosity_from_volumetric_strain(0.46, 0.05 / 0.49), 0.51, kClosedForm);
}

TEST(Porosity, FromDensityRatio) {
  // A particle whose density fell from 1810 to 1810 / 1.1 has grown by 10 % in volume.
  EXPECT_NEAR(volumetric_strain_from_density(1810.0, 1810.0 / 1.1), 0.1, kClosedForm);
  EXPECT_NEAR(porosity_from_density(0.46, 1810.0, 1810.0 / 1.1), 0.56 / 1.1, kClosedForm);
}

TEST(Porosity, ClampedToThePhysicalRange) {
  // eps_v = -0.5 < -n0: eq. 20 gives -0.04 / 0.5 = -0.08 (negative porosity) -> clamped 0.01.
  EXPECT_NEAR(porosity_from_volumetric_strain_unclamped(0.46, -0.5), -0.08, kClosedForm);
  EXPECT_DOUBLE_EQ(porosity_from_volumetric_strain(0.46, -0.5), 0.01);
  EXPECT_DOUBLE_EQ(porosity_from_volumetric_strain(0.46, -1.0), 0.01);  // eq. 20 undefined
  // eps_v = 100: 100.46 / 101 = 0.99465 -> 0.99.
  EXPECT_DOUBLE_EQ(porosity_from_volumetric_strain(0.46, 100.0), 0.99);
  const PorosityRange narrow{0.3, 0.6};
  EXPECT_DOUBLE_EQ(porosity_from_volumetric_strain(0.46, 0.5, narrow), 0.6);  // 0.96/1.5 = 0.64
}

TEST(Permeability, KozenyCarmanForTheFluidisedBedSand) {
  // docs/cases.md fluidized_bed sand: d_e = 0.5125 mm, n = 0.46, nu = 1e-6 m^2/s, g = 9.81 m/s^2.
  //   n^3 = 0.097336, (1 - n)^2 = 0.2916, ratio = 0.33379973
  //   g / nu d_e^2 = 9.81e6 * 2.62656e-7 = 2.57665781 m/s
  //   k = 0.33379973 * 2.57665781 / 180 = 4.77826e-3 m/s,  a = 1/k = 209.281 s/m.
  const double k = kozeny_carman_conductivity(0.46, 0.5125e-3, 9.81, 1e-6);
  EXPECT_NEAR(k, 4.778264838e-3, 1e-12);
  const SeepageCoefficients c = darcy_kozeny_carman(0.46, 0.5125e-3, 9.81, 1e-6);
  EXPECT_NEAR(c.a, 209.2809909, 1e-6);
  EXPECT_EQ(c.b, 0.0);
  // Variable permeability: the expanded bed (n = 0.51) is more permeable.
  EXPECT_GT(kozeny_carman_conductivity(0.51, 0.5125e-3, 9.81, 1e-6), k);
  EXPECT_NEAR(darcy_constant(0.05).a, 20.0, kClosedForm);
}

TEST(Permeability, DenAdelForTheRockfillGravel) {
  // docs/cases.md rockfill gravel: n = 0.41, d15 = 26 mm, alpha 150, beta 0.4, nu 1e-6, g 9.81:
  //   a = 150 * 0.59^2 / 0.41^3 * 1e-6 / (9.81 * 0.026^2) = 150 * 0.3481 / 0.068921 * 1.50792e-4
  //     = 0.114243 s/m
  //   b = 0.4 / 0.41^2 / (9.81 * 0.026) = 0.4 / 0.1681 / 0.25506 = 9.32932 s^2/m^2
  const SeepageCoefficients c = forchheimer_den_adel(0.41, 0.026, 9.81, 1e-6);
  EXPECT_NEAR(c.a, 0.1142425817, 1e-10);
  EXPECT_NEAR(c.b, 9.329318554, 1e-8);
}

}  // namespace
}  // namespace porosph::porous
