// The seepage laws of porous/seepage_laws.h: every registered law reaches the scene schema (its
// name and its keys, each shown only with it), the term registry (seepage_<name>) and SeepageLaw,
// and gives finite coefficients that fall as the soil loosens. A new law is checked by these
// tests without a line here; its own closed form gets one TEST below (docs/contributing.md).
#include "porous/seepage_laws.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "porous/seepage_law.h"
#include "scene/scene_schema.h"
#include "scene/term_registry.h"

namespace porosph::porous {
namespace {

/// A material of `law` with each required key at 1e-3 (1 mm, 1 mm/s) and the others at their
/// defaults.
scene::SoilMaterial material_of(const SeepageLawSpec& law, double n0 = 0.4) {
  scene::SoilMaterial m;
  m.name = "test";
  m.porosity = n0;
  m.seepage = law.name;
  m.variable_permeability = true;
  for (const scene::KeySpec& key : law.keys) {
    const bool fixed = key.default_value.kind == scene::DefaultValue::Kind::Constant;
    m.seepage_parameters[key.name()] = fixed ? std::stod(key.default_value.toml) : 1e-3;
  }
  return m;
}

TEST(SeepageLaws, EveryLawReachesTheSchemaAndTheTermRegistry) {
  const scene::SceneSchema schema = scene::make_scene_schema();
  const scene::KeySpec* seepage = schema.find_key("soil.materials[].seepage");
  ASSERT_NE(seepage, nullptr);
  const auto terms = scene::make_term_registry();
  for (const SeepageLawSpec& law : seepage_laws()) {
    EXPECT_NE(std::find(seepage->allowed.begin(), seepage->allowed.end(), law.name),
              seepage->allowed.end())
        << law.name;
    EXPECT_FALSE(law.summary.empty()) << law.name;
    for (const scene::KeySpec& key : law.keys) {
      const scene::KeySpec* declared = schema.find_key(key.path);
      ASSERT_NE(declared, nullptr) << key.path;
      ASSERT_TRUE(declared->applies_when.has_value()) << key.path;
      const auto& when = declared->applies_when->values;
      EXPECT_NE(std::find(when.begin(), when.end(), law.name), when.end()) << key.path;
    }
    const bool registered = std::any_of(terms.begin(), terms.end(), [&](const auto& t) {
      return t.phase == "interaction" && t.name == "seepage_" + law.name;
    });
    EXPECT_TRUE(registered) << law.name;
  }
}

TEST(SeepageLaws, EveryLawGivesFiniteCoefficientsThatFallAsTheSoilLoosens) {
  for (const SeepageLawSpec& law : seepage_laws()) {
    const SeepageLaw seepage = SeepageLaw::from_material(material_of(law), 9.81, 1e-6);
    ASSERT_TRUE(seepage.active()) << law.name;
    double last_a = INFINITY, last_b = INFINITY;
    for (double n = 0.25; n <= 0.6; n += 0.05) {
      const SeepageCoefficients c = seepage.coefficients(n);
      EXPECT_TRUE(std::isfinite(c.a) && c.a > 0.0) << law.name << " n " << n;
      EXPECT_TRUE(std::isfinite(c.b) && c.b >= 0.0) << law.name << " n " << n;
      EXPECT_LT(c.a, last_a) << law.name << " n " << n;
      EXPECT_LE(c.b, last_b) << law.name << " n " << n;
      last_a = c.a, last_b = c.b;
    }
  }
}

TEST(SeepageLaws, AMissingOrNonPositiveKeyIsRefusedNamingIt) {
  for (const SeepageLawSpec& law : seepage_laws()) {
    for (const scene::KeySpec& key : law.keys) {
      scene::SoilMaterial m = material_of(law);
      m.seepage_parameters[key.name()] = 0.0;
      try {
        SeepageLaw::from_material(m, 9.81, 1e-6);
        ADD_FAILURE() << law.name << " accepted " << key.name() << " = 0";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(key.name()), std::string::npos) << e.what();
      }
    }
  }
}

// Den Adel (eq. 15) at the rockfill's gravel: the coefficients of porous/permeability.h.
TEST(SeepageLaws, DenAdelIsEq15) {
  const auto laws = seepage_laws();
  scene::SoilMaterial m = material_of(*find_seepage_law(laws, "forchheimer_den_adel"));
  m.seepage_parameters["d15"] = 0.0226;
  const SeepageCoefficients c = SeepageLaw::from_material(m, 9.81, 1e-6).coefficients(0.4);
  const SeepageCoefficients e = forchheimer_den_adel(0.4, 0.0226, 9.81, 1e-6);
  EXPECT_EQ(c.a, e.a);
  EXPECT_EQ(c.b, e.b);
}

// Ergun (1952) for a bed of 2 mm grains at n = 0.4, by hand: a = 150 0.36 / 0.064 1e-6 / (9.81
// 4e-6) = 21.50 s/m, b = 1.75 0.6 / 0.064 / (9.81 0.002) = 836.2 s^2/m^2; its linear term is Den
// Adel's with alpha = 150 and d15 = d (the same Kozeny-Carman form).
TEST(SeepageLaws, ErgunIsItsPackedBedEquation) {
  const auto laws = seepage_laws();
  scene::SoilMaterial m = material_of(*find_seepage_law(laws, "forchheimer_ergun"));
  m.seepage_parameters["grain_diameter"] = 0.002;
  const SeepageCoefficients c = SeepageLaw::from_material(m, 9.81, 1e-6).coefficients(0.4);
  EXPECT_NEAR(c.a, 150.0 * 0.36 / 0.064 * 1e-6 / (9.81 * 4e-6), 1e-12 * c.a);
  EXPECT_NEAR(c.b, 1.75 * 0.6 / 0.064 / (9.81 * 0.002), 1e-12 * c.b);
  EXPECT_NEAR(c.a, 21.50, 0.01);
  EXPECT_NEAR(c.b, 836.2, 0.1);
  EXPECT_NEAR(c.a, forchheimer_den_adel(0.4, 0.002, 9.81, 1e-6, 150.0, 0.4).a, 1e-12 * c.a);
}

}  // namespace
}  // namespace porosph::porous
