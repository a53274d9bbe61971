// One soil and one water particle: the interaction accelerations against eq. 13-17 computed by
// hand (the seepage laws, the sign, variable permeability, the submerged switch, the damping stage)
// and the pair search at the kernel support and across a periodic face.
// Tolerance 1e-12 relative: the hand formulas and the code evaluate the same expressions in a
// different order, so they agree to a few ulps (~1e-15); 1e-12 leaves room for that and nothing
// else (a wrong coefficient, density or kernel value is off by far more).
#include <gtest/gtest.h>

#include "coupler/interaction/soil_water_interaction.h"
#include "porous/seepage_law.h"
#include "porous/submerged_density.h"
#include "tests/coupler/interaction_fixtures.h"

namespace porosph::testing {
namespace {

using coupler::SoilWaterInteraction;
using coupling::StepState;

constexpr double kTol = 1e-12;
constexpr double kG = 9.81, kNu = 1e-6, kRhoW = 1000.0, kH = 0.012;
constexpr double kRhoSoil = 1600.0, kRhoWater = 1002.0;  // current densities of the two particles
const double kVolume = 1e-4;                             // dp^2 for both particles

struct PairResult {
  coupler::InteractionSummary summary;
  std::vector<double> soil_a, water_a, saturation;
};

/// Soil at (0.5, 0.5) with velocity v_s and porosity n, water at (0.5 + r, 0.5) with velocity v_w.
PairResult one_pair(const scene::Scene& scene, double r, const std::vector<double>& v_w,
                    const std::vector<double>& v_s, double porosity = 0.4, double time = 1.0) {
  StepState water, soil;
  add_particle(soil, {0.5, 0.5}, v_s, kRhoSoil, kRhoSoil * kVolume, porosity, 0);
  add_particle(water, {0.5 + r, 0.5}, v_w, kRhoWater, kRhoWater * kVolume);
  SoilWaterInteraction interaction(scene);
  PairResult out;
  out.summary = interaction.compute(water, soil, time);
  out.soil_a = interaction.soil_acceleration();
  out.water_a = interaction.water_acceleration();
  out.saturation = interaction.saturation();
  return out;
}

/// Eq. 16 / 17 for one pair with the seepage force f (soil not submerged: rho^s = rho).
void expect_pair_accelerations(const PairResult& p, const double f[2], double r, double rho_s) {
  const double w = cubic_spline_2d(r, kH);
  ASSERT_EQ(p.summary.pair_count, 1u);
  ASSERT_EQ(p.soil_a.size(), 2u);
  ASSERT_EQ(p.water_a.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(relative(p.soil_a[k], kVolume * f[k] * w / rho_s), kTol) << "soil, axis " << k;
    EXPECT_LT(relative(p.water_a[k], -kVolume * f[k] * w / kRhoWater), kTol) << "water, axis " << k;
  }
}

TEST(SeepagePair, DarcyKozenyCarmanMatchesEq13To16) {
  const double r = 0.7 * kH;
  const auto p = one_pair(two_phase_scene(kozeny_carman_material()), r, {0.0, 0.01}, {0.0, 0.0});
  const double a = 1.0 / kozeny_carman_k(0.4, 1e-3, kG, kNu);  // eq. 14: k = 9.69e-3 m/s
  const double f[2] = {0.0, kRhoW * kG * a * 0.01};            // eq. 13, b = 0
  expect_pair_accelerations(p, f, r, kRhoSoil);
  // Water moving up through still soil pushes the soil up and is slowed.
  EXPECT_GT(p.soil_a[1], 0.0);
  EXPECT_LT(p.water_a[1], 0.0);
}

TEST(SeepagePair, DarcyConductivityMatchesEq13) {
  const double r = 1.3 * kH;
  const auto p =
      one_pair(two_phase_scene(conductivity_material(2e-3)), r, {0.0, 0.02}, {0.0, -0.01});
  const double f[2] = {0.0, kRhoW * kG / 2e-3 * 0.03};  // v_r = 0.02 - (-0.01)
  expect_pair_accelerations(p, f, r, kRhoSoil);
}

TEST(SeepagePair, ForchheimerDenAdelMatchesEq13And15) {
  const double r = 0.4 * kH;
  const auto p = one_pair(two_phase_scene(den_adel_material(5e-3)), r, {0.03, 0.05}, {0.0, 0.01});
  const double n = 0.4, d15 = 5e-3;
  const double a = 150.0 * (1 - n) * (1 - n) / (n * n * n) * kNu / (kG * d15 * d15);  // 3.44 s/m
  const double b = 0.4 / (n * n) / (kG * d15);                                        // 51 s^2/m^2
  const double vr[2] = {0.03, 0.04}, speed = 0.05;
  const double f[2] = {kRhoW * kG * (a + b * speed) * vr[0], kRhoW * kG * (a + b * speed) * vr[1]};
  expect_pair_accelerations(p, f, r, kRhoSoil);
  // The quadratic term is a real part of this force (b |v_r| / a = 0.74), so it is tested.
  EXPECT_GT(b * speed / a, 0.5);
}

TEST(SeepagePair, NoneGivesNoForceButSaturation) {
  scene::SoilMaterial m = kozeny_carman_material();
  m.seepage = "none";
  const double r = 0.5 * kH;
  const auto p = one_pair(two_phase_scene(m), r, {0.0, 1.0}, {0.0, 0.0});
  EXPECT_EQ(p.summary.pair_count, 1u);
  ASSERT_EQ(p.soil_a.size(), 2u);
  EXPECT_EQ(p.soil_a[1], 0.0);
  EXPECT_EQ(p.water_a[1], 0.0);
  ASSERT_EQ(p.saturation.size(), 1u);
  EXPECT_LT(relative(p.saturation[0], kVolume * cubic_spline_2d(r, kH)), kTol);
  EXPECT_EQ(p.summary.dt_limit, std::numeric_limits<double>::infinity());
}

TEST(SeepagePair, VariablePermeabilityUsesTheParticlePorosity) {
  const double r = 0.9 * kH, n_particle = 0.45;
  for (bool variable : {false, true}) {
    scene::SoilMaterial m = kozeny_carman_material(0.4);
    m.variable_permeability = variable;
    const auto p = one_pair(two_phase_scene(m), r, {0.0, 0.01}, {0.0, 0.0}, n_particle);
    const double n = variable ? n_particle : 0.4;
    const double f[2] = {0.0, kRhoW * kG / kozeny_carman_k(n, 1e-3, kG, kNu) * 0.01};
    SCOPED_TRACE(variable ? "variable" : "fixed at n0");
    expect_pair_accelerations(p, f, r, kRhoSoil);
  }
  // Darcy with a given conductivity: k follows the Kozeny-Carman porosity function.
  scene::SoilMaterial m = conductivity_material(1e-3);
  m.variable_permeability = true;
  const auto p = one_pair(two_phase_scene(m), r, {0.0, 0.01}, {0.0, 0.0}, n_particle);
  const double shape = [](double n) { return n * n * n / ((1 - n) * (1 - n)); }(n_particle) /
                       (0.4 * 0.4 * 0.4 / (0.6 * 0.6));
  const double f[2] = {0.0, kRhoW * kG / (1e-3 * shape) * 0.01};
  expect_pair_accelerations(p, f, r, kRhoSoil);
}

TEST(SeepagePair, SubmergedRuleSwitchesTheSoilDensityAtTheThreshold) {
  const double r = 0.2 * kH;
  const double s = kVolume * cubic_spline_2d(r, kH);  // the one water particle's volume fraction
  scene::SoilMaterial m = kozeny_carman_material();
  const double f[2] = {0.0, kRhoW * kG / kozeny_carman_k(0.4, 1e-3, kG, kNu) * 0.01};
  // rho_sat not given: rho_dry + n0 rho_w = 2000, r_m = (2000 - 1000) / 1600; given: 2100.
  for (double saturated : {0.0, 2100.0}) {
    m.saturated_density = saturated;
    const double r_m = ((saturated > 0 ? saturated : 1600.0 + 0.4 * kRhoW) - kRhoW) / 1600.0;
    EXPECT_LT(relative(porous::submerged_density_ratio(m, kRhoW), r_m), kTol);
    scene::Scene scene = two_phase_scene(m);
    scene.coupling.submerged_saturation = s * (1.0 + 1e-9);  // just above s: not submerged
    expect_pair_accelerations(one_pair(scene, r, {0.0, 0.01}, {0.0, 0.0}), f, r, kRhoSoil);
    scene.coupling.submerged_saturation = s * (1.0 - 1e-9);  // just below s: submerged
    expect_pair_accelerations(one_pair(scene, r, {0.0, 0.01}, {0.0, 0.0}), f, r, kRhoSoil * r_m);
  }
  EXPECT_EQ(porous::submerged_density(1600.0, 0.79, 0.8, 0.625), 1600.0);
  EXPECT_EQ(porous::submerged_density(1600.0, 0.8, 0.8, 0.625), 1000.0);
}

TEST(SeepagePair, DampingStageSendsSaturationOnly) {
  scene::Scene scene = two_phase_scene(kozeny_carman_material());
  scene.soil->damping_duration = 0.5;
  const double r = 0.6 * kH;
  const auto during = one_pair(scene, r, {0.0, 0.01}, {0.0, 0.0}, 0.4, 0.49);
  EXPECT_TRUE(during.soil_a.empty());
  EXPECT_TRUE(during.water_a.empty());
  ASSERT_EQ(during.saturation.size(), 1u);
  EXPECT_LT(relative(during.saturation[0], kVolume * cubic_spline_2d(r, kH)), kTol);
  const auto after = one_pair(scene, r, {0.0, 0.01}, {0.0, 0.0}, 0.4, 0.5);
  EXPECT_EQ(after.soil_a.size(), 2u);
}

TEST(SeepagePair, TimeStepLimitIsEq21WithTheInteraction) {
  const double r = 0.7 * kH;
  const auto p = one_pair(two_phase_scene(kozeny_carman_material()), r, {0.0, 0.01}, {0.0, 0.0});
  const double a_max = std::max(std::abs(p.soil_a[1]), std::abs(p.water_a[1]));
  EXPECT_LT(relative(p.summary.max_acceleration, a_max), kTol);
  EXPECT_LT(relative(p.summary.dt_limit, 0.25 * std::sqrt(kH / a_max)), kTol);
}

TEST(SeepagePair, PairsEndAtTheKernelSupport) {
  const scene::Scene scene = two_phase_scene(kozeny_carman_material());
  EXPECT_EQ(one_pair(scene, 2.0 * kH * (1.0 - 1e-6), {0.0, 0.01}, {0.0, 0.0}).summary.pair_count,
            1u);
  const auto beyond = one_pair(scene, 2.0 * kH * (1.0 + 1e-9), {0.0, 0.01}, {0.0, 0.0});
  EXPECT_EQ(beyond.summary.pair_count, 0u);
  EXPECT_EQ(beyond.soil_a[1], 0.0);
  EXPECT_EQ(beyond.saturation[0], 0.0);
}

/// A pair across the x faces of a periodic box of length L: found once, with the same force as
/// the same pair in the interior.
void expect_pair_across_face_once(double length) {
  scene::Scene scene = two_phase_scene(kozeny_carman_material());
  scene.run.periodic = {true, false};
  scene.domain.max = {length, 1.0};
  const double r = 0.01;
  StepState water, soil;
  add_particle(soil, {0.004, 0.5}, {0.0, 0.0}, kRhoSoil, kRhoSoil * kVolume, 0.4, 0);
  add_particle(water, {length - 0.006, 0.5}, {0.0, 0.01}, kRhoWater, kRhoWater * kVolume);
  SoilWaterInteraction interaction(scene);
  PairResult p;
  p.summary = interaction.compute(water, soil, 1.0);
  p.soil_a = interaction.soil_acceleration();
  p.water_a = interaction.water_acceleration();
  const double f[2] = {0.0, kRhoW * kG / kozeny_carman_k(0.4, 1e-3, kG, kNu) * 0.01};
  expect_pair_accelerations(p, f, r, kRhoSoil);
}

TEST(SeepagePair, PairAcrossAPeriodicFaceIsFoundOnce) {
  SCOPED_TRACE("41 cells along x");
  expect_pair_across_face_once(1.0);
  SCOPED_TRACE("2 cells along x (the stencil must not visit a cell twice)");
  expect_pair_across_face_once(0.05);
}

TEST(SeepagePair, IncompleteSeepageLawIsRefused) {
  scene::Scene scene = two_phase_scene(kozeny_carman_material());
  scene.water->viscosity = 0.0;  // Kozeny-Carman needs nu > 0
  EXPECT_THROW(SoilWaterInteraction{scene}, std::invalid_argument);
  scene = two_phase_scene(kozeny_carman_material());
  scene.soil.reset();
  EXPECT_THROW(SoilWaterInteraction{scene}, std::invalid_argument);
}

TEST(SeepagePair, BadOverlapArraysNameThePhase) {
  SoilWaterInteraction interaction(two_phase_scene(kozeny_carman_material()));
  StepState water, soil;
  add_particle(soil, {0.5, 0.5}, {0.0, 0.0}, kRhoSoil, 0.16, 0.4, 3);  // material 3 of 1
  add_particle(water, {0.5, 0.5}, {0.0, 0.0}, kRhoWater, 0.1);
  try {
    interaction.compute(water, soil, 1.0);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("material index 3"), std::string::npos) << e.what();
  }
  soil.overlap_material[0] = 0;
  water.overlap_mass.clear();
  EXPECT_THROW(interaction.compute(water, soil, 1.0), std::runtime_error);
}

}  // namespace
}  // namespace porosph::testing
