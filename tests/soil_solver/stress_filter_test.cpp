// The periodic soil stress filter (stress_filter.h) on a hand-made block of soil particles: which
// fields each weighting keeps, the row-to-row pattern it removes, the material boundary and the
// return onto the yield cone.
#include <gtest/gtest.h>

#include <cmath>

#include "soil_solver/stress_filter.h"
#include "sph/kernels.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using Vec2 = sph::Vec<2>;

constexpr double kDp = 0.01, kH = 0.012, kRho = 2000.0;
constexpr int kColumns = 16, kRows = 12;

MaterialParameters sand(double cohesion) {
  MaterialParameters p;
  p.young = 10e6;
  p.poisson = 0.3;
  p.friction_angle_deg = 35.0;
  p.cohesion = cohesion;
  return p;
}

SoilParams<2> params_with_two_materials() {
  SoilParams<2> params;
  params.dp = kDp;
  params.h = kH;
  for (double cohesion : {2000.0, 0.0}) {
    SoilMaterialConstants c;
    c.model = make_material(sand(cohesion));
    c.wet_model = make_material(sand(0.0));
    params.materials.push_back(c);
  }
  return params;
}

// A kColumns x kRows lattice block (free surface on top and all around), one material.
SoilParticles<2> block() {
  SoilParticles<2> P;
  P.for_each_array([&](auto& a) { a.resize(kColumns * kRows); });
  P.n_free = P.size();
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * kColumns + i);
      P.position[k] = Vec2((i + 0.5) * kDp, (j + 0.5) * kDp);
      P.density[k] = kRho;
      P.mass[k] = kRho * kDp * kDp;
      P.material[k] = 0;
      P.wet[k] = 0;
    }
  return P;
}

// Geostatic stress of the block, compression negative: sigma_y = -rho g (H - y), sigma_x =
// sigma_z = 0.5 sigma_y (inside the phi 35 cone: sqrt(J2) / |p| = 0.433 < 3 alpha_phi = 0.545).
Matrix3d geostatic(const Vec2& x) {
  const double sigma_y = -kRho * 9.81 * (kRows * kDp - x.y());
  return Eigen::Vector3d(0.5 * sigma_y, sigma_y, 0.5 * sigma_y).asDiagonal();
}

void filter(StressFilterKind kind, const SoilParams<2>& params, SoilParticles<2>& P) {
  sph::NeighbourList<2> nl;
  nl.build(P.position.data(), P.size(), P.n_free, 2.0 * kH, sph::DomainBox<2>{});
  std::vector<Matrix3d> scratch;
  filter_soil_stress(kind, nl, sph::CubicSpline<2>(kH), params, P, scratch);
}

double largest_change(const SoilParticles<2>& P, int row) {
  double change = 0.0;
  for (int i = 0; i < kColumns; ++i) {
    const std::size_t k = static_cast<std::size_t>(row * kColumns + i);
    change = std::max(change, (P.stress[k] - geostatic(P.position[k])).norm());
  }
  return change;
}

TEST(StressFilter, MlsKeepsALinearStressEverywhereShepardOnlyInside) {
  const SoilParams<2> params = params_with_two_materials();
  const double scale = kRho * 9.81 * kRows * kDp;  // stress at the base, 2.35 kPa
  for (StressFilterKind kind : {StressFilterKind::Mls, StressFilterKind::Shepard}) {
    SoilParticles<2> P = block();
    for (std::size_t k = 0; k < P.size(); ++k) P.stress[k] = geostatic(P.position[k]);
    filter(kind, params, P);
    if (kind == StressFilterKind::Mls) {
      // First-order consistency: exact for a linear field up to round-off of the 3x3 solve.
      for (int row = 0; row < kRows; ++row) EXPECT_LE(largest_change(P, row), 1e-10 * scale);
    } else {
      // Interior rows (full support, 3 rows from every face) keep it to round-off: the lattice
      // is symmetric, so the kernel's first moment vanishes.
      for (int row = 3; row < kRows - 3; ++row) EXPECT_LE(largest_change(P, row), 1e-10 * scale);
      // The top row (own sigma_y = -rho g dp / 2 = -98 Pa) takes the stress of the rows below:
      // by hand its Shepard average depth is ~1 dp, twice its own, so the change is ~100 Pa.
      const double top = largest_change(P, kRows - 1);
      EXPECT_GT(top, 0.5 * kRho * 9.81 * 0.5 * kDp);
    }
  }
}

TEST(StressFilter, RemovesTheRowToRowPattern) {
  // sigma_y alternating by +-1 kPa from row to row on a uniform -5 kPa state. In the interior
  // one pass leaves sum_k (-1)^k W_k V / sum_k W_k V = 0.152 of the amplitude (cubic spline,
  // h = 1.2 dp, by hand over the 7 x 7 lattice neighbourhood); we allow 0.2.
  const SoilParams<2> params = params_with_two_materials();
  for (StressFilterKind kind : {StressFilterKind::Mls, StressFilterKind::Shepard}) {
    SoilParticles<2> P = block();
    for (std::size_t k = 0; k < P.size(); ++k) {
      const int row = static_cast<int>(k) / kColumns;
      P.stress[k] = -5e3 * Matrix3d::Identity();
      P.stress[k](1, 1) += (row % 2 == 0 ? 1e3 : -1e3);
    }
    filter(kind, params, P);
    for (int row = 3; row < kRows - 3; ++row) {
      const std::size_t k = static_cast<std::size_t>(row * kColumns + kColumns / 2);
      EXPECT_LE(std::abs(P.stress[k](1, 1) + 5e3), 0.2e3) << "row " << row;
      EXPECT_GE(std::abs(P.stress[k](1, 1) + 5e3), 0.1e3) << "row " << row;  // 0.152 kPa
    }
  }
}

TEST(StressFilter, StaysWithinOneMaterial) {
  // Left half material 0 at -10 kPa, right half material 1 at -2 kPa (isotropic, inside both
  // cones): each particle keeps its material's stress exactly, next to the boundary too.
  const SoilParams<2> params = params_with_two_materials();
  for (StressFilterKind kind : {StressFilterKind::Mls, StressFilterKind::Shepard}) {
    SoilParticles<2> P = block();
    for (std::size_t k = 0; k < P.size(); ++k) {
      P.material[k] = (static_cast<int>(k) % kColumns) < kColumns / 2 ? 0 : 1;
      P.stress[k] = (P.material[k] == 0 ? -10e3 : -2e3) * Matrix3d::Identity();
    }
    filter(kind, params, P);
    for (std::size_t k = 0; k < P.size(); ++k) {
      const double expected = P.material[k] == 0 ? -10e3 : -2e3;
      EXPECT_LE((P.stress[k] - expected * Matrix3d::Identity()).norm(), 1e-9 * 10e3) << k;
    }
  }
}

TEST(StressFilter, ReturnsAWetParticleOntoItsCohesionlessCone) {
  // Uniform state p = -2 kPa with deviator diag(+1.732, -1.732, 0) kPa, sqrt(J2) = 1.732 kPa;
  // phi 35: alpha_phi = tan 35 / sqrt(9 + 12 tan^2 35) = 0.1815, k_c = 0.7777 c. Dry (c = 2 kPa):
  // capacity k_c - alpha_phi I1 = 1.555 + 1.089 = 2.644 kPa, inside. Wet (c = 0): 1.089 kPa,
  // outside. The wet particle ends on its own cone (f = 0 to round-off, same p); a dry one keeps
  // the state.
  const SoilParams<2> params = params_with_two_materials();
  SoilParticles<2> P = block();
  Matrix3d state = -2e3 * Matrix3d::Identity();
  state(0, 0) += 1e3 * std::sqrt(3.0);
  state(1, 1) -= 1e3 * std::sqrt(3.0);
  const std::size_t wet = 5 * kColumns + 8, dry = 5 * kColumns + 3;
  for (std::size_t k = 0; k < P.size(); ++k) P.stress[k] = state;
  P.wet[wet] = 1;
  const Material& dry_model = params.materials[0].model;
  const Material& wet_model = params.materials[0].wet_model;
  ASSERT_LT(yield_function(dry_model, state), 0.0);
  ASSERT_GT(yield_function(wet_model, state), 0.0);
  filter(StressFilterKind::Mls, params, P);
  EXPECT_NEAR(yield_function(wet_model, P.stress[wet]), 0.0, 1e-9 * 2e3);
  EXPECT_NEAR(P.stress[wet].trace(), state.trace(), 1e-9 * 6e3);  // scaled back at constant p
  EXPECT_LE((P.stress[dry] - state).norm(), 1e-9 * 6e3);
}

}  // namespace
}  // namespace porosph::soil
