// Geostatic initial stress: sigma_v = -rho g depth, sigma_h = K0 sigma_v, "up" from gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "soil_solver/drucker_prager_constants.h"
#include "soil_solver/geostatic_stress.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using V2 = sph::Vec<2>;
using V3 = sph::Vec<3>;

constexpr double kRoundOff = 1e-12;  // relative

TEST(GeostaticStress, K0Values) {
  // Jaky: 1 - sin 22 deg = 1 - 0.374607 = 0.625393; elastic: 0.3 / 0.7 = 0.428571.
  EXPECT_NEAR(k0_jaky(degrees_to_radians(22.0)), 0.6253934, 1e-7);
  EXPECT_NEAR(k0_elastic(0.3), 0.3 / 0.7, kRoundOff);
}

TEST(GeostaticStress, GravityAlongMinusYAndMinusX) {
  // Fluidised-bed sand, submerged density 1810 - 1000 = 810, 20 mm below the surface:
  //   sigma_v = -810 * 9.81 * 0.02 = -158.922 Pa, sigma_h = 0.625393 * sigma_v.
  const double rho = 810.0, k0 = k0_jaky(degrees_to_radians(22.0));
  const double sv = -810.0 * 9.81 * 0.02;
  // y up (gravity -y), surface at y = 0.05, particle at y = 0.03.
  const Matrix3d sy =
      geostatic_stress_at<2>(V2(0.01, 0.03), V2(0.0, 0.05), V2(0.0, -9.81), rho, k0);
  EXPECT_NEAR(sy(1, 1), sv, kRoundOff * 160.0);
  EXPECT_NEAR(sy(0, 0), k0 * sv, kRoundOff * 160.0);
  EXPECT_NEAR(sy(2, 2), k0 * sv, kRoundOff * 160.0);  // out of plane is horizontal too
  EXPECT_NEAR(sy(0, 1), 0.0, kRoundOff * 160.0);
  // x up (the original fluidised-bed input: gravity along -x), surface at x = 0.05.
  const Matrix3d sx =
      geostatic_stress_at<2>(V2(0.03, 0.01), V2(0.05, 0.0), V2(-9.81, 0.0), rho, k0);
  EXPECT_NEAR(sx(0, 0), sv, kRoundOff * 160.0);
  EXPECT_NEAR(sx(1, 1), k0 * sv, kRoundOff * 160.0);
  EXPECT_NEAR(sx(2, 2), k0 * sv, kRoundOff * 160.0);
  // Above the surface: stress-free.
  EXPECT_EQ(geostatic_stress_at<2>(V2(0.0, 0.06), V2(0.0, 0.05), V2(0.0, -9.81), rho, k0),
            Matrix3d::Zero());
}

TEST(GeostaticStress, TiltedGravityIn3D) {
  // Gravity along -(1, 1, 1)/sqrt 3: up is a principal direction with sigma_v, the trace is
  // sigma_v (1 + 2 K0), and the depth is measured along up.
  const V3 g = -9.81 / std::sqrt(3.0) * V3(1.0, 1.0, 1.0);
  const V3 up = up_direction<3>(g);
  EXPECT_NEAR(depth_below<3>(V3(-0.1 * up), V3::Zero(), g), 0.1, kRoundOff);
  const double sv = vertical_geostatic_stress(2000.0, 9.81, 0.1), k0 = 0.5;
  EXPECT_NEAR(sv, -1962.0, kRoundOff * 1962.0);
  const Matrix3d s = geostatic_stress<3>(g, sv, k0);
  EXPECT_TRUE((s * up).isApprox(sv * up, kRoundOff));
  EXPECT_NEAR(s.trace(), sv * (1.0 + 2.0 * k0), kRoundOff * 1962.0);
  EXPECT_THROW(up_direction<3>(V3::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace porosph::soil
