// Scenes with soil: a soil-only and a coupled scene load into the typed Scene with every documented
// default filled in, elastic constants converted both ways, new wall and observable keys read.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/scene/scene_examples.h"
#include "tests/scene/scene_examples_soil.h"

namespace porosph::scene::test {
namespace {

using Doubles = std::vector<double>;
using Strings = std::vector<std::string>;

/// Relative tolerance of the elastic conversions: each is 3-5 floating-point operations without
/// severe cancellation for these materials (3K - 2G loses at most a factor 3), so a few ulp
/// (~1.1e-16 each) at most; 1e-14 leaves a margin and still catches any wrong formula.
constexpr double kConversionTolerance = 1e-14;

void expect_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, std::fabs(expected) * kConversionTolerance);
}

TEST(SceneSoil, GranularColumnGetsEveryDefault) {
  const Scene s = load_scene_text(kGranularColumn2D, "column.toml");
  EXPECT_FALSE(s.has_water());
  ASSERT_TRUE(s.has_soil());
  EXPECT_EQ(s.phases(), (Strings{"soil"}));
  EXPECT_EQ(s.run.max_steps, 0);  // default: no step limit

  // [soil] defaults, exactly as documented.
  const SoilPhase& soil = *s.soil;
  EXPECT_EQ(soil.solver, "");
  EXPECT_EQ(soil.wall_condition, "no_slip");
  EXPECT_EQ(soil.alpha, 0.1);
  EXPECT_EQ(soil.beta, 0.1);
  EXPECT_EQ(soil.artificial_stress_epsilon, 0.5);
  EXPECT_EQ(soil.artificial_stress_exponent, 2.55);
  EXPECT_EQ(soil.sound_speed, 0.0);
  EXPECT_EQ(soil.initial_stress, "geostatic");  // given
  EXPECT_EQ(soil.k0, "jaky");
  EXPECT_EQ(soil.damping_duration, 0.0);
  EXPECT_EQ(soil.damping_coefficient, 0.02);

  // [[soil.materials]] defaults; the given E, nu exactly, the derived K, G to the conversion
  // tolerance.
  ASSERT_EQ(soil.materials.size(), 1u);
  const SoilMaterial& m = soil.materials[0];
  EXPECT_EQ(m.name, "aluminium_bars");
  EXPECT_EQ(m.density, 2650.0);
  EXPECT_EQ(m.saturated_density, 0.0);  // not given
  EXPECT_EQ(m.porosity, 0.4);
  EXPECT_EQ(m.young_modulus, 0.84e6);
  EXPECT_EQ(m.poisson_ratio, 0.3);
  expect_relative(m.bulk_modulus, 0.7e6);          // 0.84e6 / (3 (1 - 0.6))
  expect_relative(m.shear_modulus, 0.84e6 / 2.6);  // 0.84e6 / (2 (1 + 0.3))
  EXPECT_EQ(m.cohesion, 0.0);
  EXPECT_EQ(m.friction_angle_deg, 19.8);
  EXPECT_EQ(m.dilatancy_angle_deg, 0.0);
  EXPECT_FALSE(m.artificial_stress);
  EXPECT_FALSE(m.fixed);
  EXPECT_EQ(m.seepage, "none");
  EXPECT_TRUE(m.seepage_parameters.empty());  // no law, no law keys
  EXPECT_TRUE(m.variable_permeability);
  EXPECT_FALSE(m.wet_cohesion_loss);

  ASSERT_EQ(soil.blocks.size(), 1u);
  EXPECT_EQ(soil.blocks[0].kind, Shape::Kind::Box);
  EXPECT_EQ(soil.blocks[0].material, "aluminium_bars");
  EXPECT_EQ(soil.blocks[0].max, (Doubles{0.2, 0.1}));
  EXPECT_EQ(soil.material_index("aluminium_bars"), 0);
  EXPECT_EQ(soil.material_index("sand"), -1);
  // sound_speed 0: from the only material, the P-wave speed sqrt((K + 4 G / 3) / rho) with
  // K = E / (3 (1 - 2 nu)) = 0.7 MPa, G = E / (2 (1 + nu)) = 0.84e6 / 2.6: 20.66 m/s.
  EXPECT_NEAR(soil.effective_sound_speed(), std::sqrt((0.7e6 + 4.0 / 3.0 * 0.84e6 / 2.6) / 2650.0),
              1e-9);

  // The wall acts on every phase present (here: soil) with each phase's own condition.
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].phases, (Strings{"soil"}));
  EXPECT_EQ(s.walls[0].condition, "default");

  // Observables: the phase defaults to soil when there is no water; region only when given.
  ASSERT_EQ(s.observables.size(), 3u);
  for (const Observable& o : s.observables) EXPECT_EQ(o.phase, "soil") << o.name;
  EXPECT_EQ(s.observables[0].direction, (Doubles{1.0, 0.0}));
  EXPECT_TRUE(s.observables[0].region_min.empty());
  EXPECT_TRUE(s.observables[0].region_max.empty());
  EXPECT_EQ(s.observables[1].kind, "max_displacement");
  EXPECT_EQ(s.observables[1].field, "");
  EXPECT_EQ(s.observables[2].kind, "mean_field");
  EXPECT_EQ(s.observables[2].field, "stress_yy");
  EXPECT_EQ(s.observables[2].region_min, (Doubles{0.0, 0.0}));
  EXPECT_EQ(s.observables[2].region_max, (Doubles{0.05, 0.01}));
}

TEST(SceneSoil, CoupledSceneHasBothPhases) {
  const Scene s = load_scene_text(kSubmergedBed2D, "bed.toml");
  ASSERT_TRUE(s.has_water());
  ASSERT_TRUE(s.has_soil());
  EXPECT_EQ(s.phases(), (Strings{"water", "soil"}));
  EXPECT_EQ(s.run.max_steps, 5000);
  EXPECT_EQ(s.run.c_a, 0.005);

  const SoilPhase& soil = *s.soil;
  EXPECT_EQ(soil.solver, "my_soil_solver");
  EXPECT_EQ(soil.wall_condition, "free_slip");
  EXPECT_EQ(soil.alpha, 0.2);
  EXPECT_EQ(soil.beta, 0.0);
  EXPECT_EQ(soil.artificial_stress_epsilon, 0.3);
  EXPECT_EQ(soil.artificial_stress_exponent, 4.0);
  EXPECT_EQ(soil.initial_stress, "none");
  EXPECT_EQ(soil.k0, "elastic");
  EXPECT_EQ(soil.damping_duration, 0.05);
  EXPECT_EQ(soil.damping_coefficient, 0.05);
  EXPECT_EQ(soil.effective_sound_speed(), 40.0);  // given: used as is
  // The stiffest material is the sand: K + 4G/3 = 1e7 / 1.5 + 4/3 * 1e7 / 2.5 = 12 MPa over
  // 1500 kg/m^3 (gravel: (5e6 + 4e6) / 1700 is smaller).
  EXPECT_NEAR(soil.stiffest_sound_speed(), std::sqrt(12e6 / 1500.0), 1e-9);

  ASSERT_EQ(soil.materials.size(), 2u);
  const SoilMaterial& gravel = soil.materials[0];
  EXPECT_EQ(gravel.saturated_density, 2050.0);
  EXPECT_EQ(gravel.porosity, 0.35);
  EXPECT_TRUE(gravel.fixed);
  EXPECT_EQ(gravel.seepage, "forchheimer_den_adel");
  EXPECT_EQ(gravel.seepage_parameter("d15"), 0.01);
  EXPECT_EQ(gravel.seepage_parameter("den_adel_alpha"), 150.0);  // defaults filled for Forchheimer
  EXPECT_EQ(gravel.seepage_parameter("den_adel_beta"), 0.4);
  EXPECT_TRUE(gravel.variable_permeability);
  EXPECT_EQ(gravel.seepage_parameters.size(), 3u);  // its law's keys only
  const SoilMaterial& sand = soil.materials[1];
  EXPECT_EQ(sand.cohesion, 500.0);
  EXPECT_EQ(sand.friction_angle_deg, 32.0);
  EXPECT_EQ(sand.dilatancy_angle_deg, 2.0);
  EXPECT_TRUE(sand.artificial_stress);
  EXPECT_EQ(sand.seepage, "darcy_kozeny_carman");
  EXPECT_EQ(sand.seepage_parameter("effective_diameter"), 0.0004);
  EXPECT_FALSE(sand.variable_permeability);
  EXPECT_TRUE(sand.wet_cohesion_loss);
  EXPECT_EQ(soil.material_index("sand"), 1);

  ASSERT_EQ(soil.blocks.size(), 2u);
  EXPECT_EQ(soil.blocks[0].material, "gravel");
  EXPECT_EQ(soil.blocks[1].kind, Shape::Kind::Polygon);
  EXPECT_EQ(soil.blocks[1].material, "sand");
  EXPECT_EQ(soil.blocks[1].label, "mound");
  EXPECT_EQ(s.water->blocks[0].material, "");  // water blocks have none

  ASSERT_EQ(s.walls.size(), 2u);
  EXPECT_EQ(s.walls[0].phases, (Strings{"water", "soil"}));  // default: every phase present
  EXPECT_EQ(s.walls[0].condition, "default");
  EXPECT_EQ(s.walls[1].phases, (Strings{"water"}));
  EXPECT_EQ(s.walls[1].condition, "free_slip");

  ASSERT_EQ(s.observables.size(), 3u);
  EXPECT_EQ(s.observables[0].phase, "soil");
  EXPECT_EQ(s.observables[0].field, "porosity");
  EXPECT_EQ(s.observables[0].region_min, (Doubles{0.1, 0.05}));
  EXPECT_EQ(s.observables[0].region_max, (Doubles{0.3, 0.15}));
  EXPECT_EQ(s.observables[1].phase, "water");  // default with water present
  EXPECT_EQ(s.observables[2].phase, "water");
}

TEST(SceneSoil, BulkAndShearGiveYoungAndPoisson) {
  // Gravel: K = 5 MPa, G = 3 MPa -> E = 9 K G / (3 K + G) = 135e12 / 18e6 = 7.5 MPa,
  // nu = (3 K - 2 G) / (2 (3 K + G)) = 9e6 / 36e6 = 0.25.
  const SoilMaterial gravel = load_scene_text(kSubmergedBed2D, "x.toml").soil->materials[0];
  EXPECT_EQ(gravel.bulk_modulus, 5e6);
  EXPECT_EQ(gravel.shear_modulus, 3e6);
  expect_relative(gravel.young_modulus, 7.5e6);
  expect_relative(gravel.poisson_ratio, 0.25);
}

TEST(SceneSoil, ElasticConversionsAreInverse) {
  // E, nu -> K, G, written back as the K, G pair of the same material -> the original E, nu.
  const SoilMaterial given = load_scene_text(kGranularColumn2D, "x.toml").soil->materials[0];
  char pair[128];
  std::snprintf(pair, sizeof pair, "bulk_modulus = %.17g\nshear_modulus = %.17g",
                given.bulk_modulus, given.shear_modulus);
  const std::string text =
      with(kGranularColumn2D, "young_modulus = 0.84e6\npoisson_ratio = 0.3", pair);
  const SoilMaterial back = load_scene_text(text, "x.toml").soil->materials[0];
  EXPECT_EQ(back.bulk_modulus, given.bulk_modulus);
  EXPECT_EQ(back.shear_modulus, given.shear_modulus);
  expect_relative(back.young_modulus, 0.84e6);
  expect_relative(back.poisson_ratio, 0.3);
}

TEST(SceneSoil, SeepageParametersFollowTheLaw) {
  // Switching the sand to Darcy with a conductivity: the diameter must go, the conductivity come.
  const std::string text =
      with(kSubmergedBed2D, "seepage = \"darcy_kozeny_carman\"\neffective_diameter = 0.0004",
           "seepage = \"darcy_conductivity\"\nhydraulic_conductivity = 1e-4");
  const SoilMaterial sand = load_scene_text(text, "x.toml").soil->materials[1];
  EXPECT_EQ(sand.seepage, "darcy_conductivity");
  EXPECT_EQ(sand.seepage_parameter("hydraulic_conductivity"), 1e-4);
  EXPECT_EQ(sand.seepage_parameters.count("effective_diameter"), 0u);
  // Overrides reach the new keys.
  const Scene s = load_scene_text(kSubmergedBed2D, "x.toml",
                                  {"soil.materials[0].den_adel_alpha=200", "run.max_steps=10",
                                   "walls[1].phases=[\"soil\", \"water\"]"});
  EXPECT_EQ(s.soil->materials[0].seepage_parameter("den_adel_alpha"), 200.0);
  EXPECT_EQ(s.run.max_steps, 10);
  EXPECT_EQ(s.walls[1].phases, (Strings{"soil", "water"}));
}

TEST(SceneSoil, WaterScenesKeepTheirDefaults) {
  // Adding soil keys changed nothing for a water-only scene: walls act on water, observables
  // measure water, no soil phase.
  const Scene s = load_scene_text(kWaterColumn2D, "x.toml");
  EXPECT_FALSE(s.has_soil());
  EXPECT_EQ(s.phases(), (Strings{"water"}));
  EXPECT_EQ(s.walls[0].phases, (Strings{"water"}));
  EXPECT_EQ(s.observables[0].phase, "water");
  EXPECT_EQ(s.run.max_steps, 0);
}

TEST(SceneSoil, ResolvedTomlKeepsOnlyTheGivenElasticPair) {
  const std::string resolved = load_scene_text(kSubmergedBed2D, "x.toml").resolved_toml;
  const auto count = [&resolved](const std::string& word) {
    std::size_t n = 0;
    for (auto at = resolved.find(word); at != std::string::npos; at = resolved.find(word, at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(count("young_modulus"), 1u) << resolved;  // sand only
  EXPECT_EQ(count("bulk_modulus"), 1u) << resolved;   // gravel only
  EXPECT_EQ(count("saturated_density"), 1u) << resolved;
  EXPECT_EQ(count("den_adel_alpha = 150.0"), 1u) << resolved;  // filled for gravel only
  EXPECT_EQ(count("phases = [ 'water', 'soil' ]"), 1u) << resolved;
  EXPECT_EQ(count("max_steps = 5000"), 1u) << resolved;
}

}  // namespace
}  // namespace porosph::scene::test
