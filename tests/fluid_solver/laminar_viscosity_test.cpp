// The laminar viscosity laws (fluid_solver/laminar_viscosity.h): the code and the registry name the
// same laws, and every law is dissipative and exchanges momentum in equal and opposite parts. The
// decay rate each law gives a Taylor-Green vortex: VerificationCases (tests/cases).
#include "fluid_solver/laminar_viscosity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "scene/scene_schema.h"
#include "scene/term_registry.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

TEST(LaminarViscosity, TheRegistryAndTheCodeNameTheSameLaws) {
  const scene::SceneSchema schema = scene::make_scene_schema();
  const scene::KeySpec* key = schema.find_key("water.laminar_viscosity");
  ASSERT_NE(key, nullptr);
  EXPECT_EQ(key->allowed, laminar_viscosity_law_names());
  // Each law's term is registered for the water as <law>_viscosity, selected by its value.
  for (const std::string& law : laminar_viscosity_law_names()) {
    const auto registry = scene::make_term_registry();
    const auto term = std::find_if(registry.begin(), registry.end(), [&](const auto& t) {
      return t.phase == "water" && t.name == law + "_viscosity";
    });
    ASSERT_NE(term, registry.end()) << law;
    ASSERT_TRUE(term->choice.has_value()) << law;
    EXPECT_EQ(term->choice->value, law);
  }
  EXPECT_EQ(laminar_viscosity_law_names().front(), "morris");  // the default
}

TEST(LaminarViscosity, AnUnknownLawIsRefusedAndNoneMeansNoTerm) {
  EXPECT_THROW(visit_laminar_viscosity<int>("morriss", [](auto) { return 0; }),
               std::invalid_argument);
  const bool none = visit_laminar_viscosity<bool>(
      "", [](auto law) { return std::is_same_v<decltype(law), NoLaminarViscosity>; });
  EXPECT_TRUE(none);
  const bool morris = visit_laminar_viscosity<bool>(
      "morris", [](auto law) { return std::is_same_v<decltype(law), MorrisViscosity>; });
  EXPECT_TRUE(morris);
}

// A pair of water particles with unequal masses and densities (1 % apart, as weak compressibility
// gives), F_ab < 0 as for any kernel inside its support.
TEST(LaminarViscosity, EveryLawOpposesTheRelativeVelocityAndConservesMomentum) {
  const LaminarViscosityConstants water{1e-3, 1000.0};
  const double m_a = 0.1, m_b = 0.13, rho_a = 1004.0, rho_b = 996.0, factor = -2.5e7;
  const Vec2 v_ab(0.3, -0.2);
  std::apply(
      [&](auto... law) {
        const auto check = [&](auto l) {
          using Law = decltype(l);
          const Vec2 on_a = Law::template acceleration<2>(
              water, LaminarPair<2>{m_b, rho_a, rho_b, 1.0 / rho_a, 1.0 / rho_b, factor, v_ab});
          const Vec2 on_b = Law::template acceleration<2>(
              water, LaminarPair<2>{m_a, rho_b, rho_a, 1.0 / rho_b, 1.0 / rho_a, factor, -v_ab});
          EXPECT_LT(on_a.dot(v_ab), 0.0) << Law::kName;  // dissipative
          const Vec2 net = m_a * on_a + m_b * on_b;
          EXPECT_LT(net.norm(), 1e-12 * m_a * on_a.norm()) << Law::kName;
        };
        (check(law), ...);
      },
      LaminarViscosityLaws{});
}

// Lo & Shao (2002) by hand: m_b 4 (mu / rho0) / (rho_a + rho_b) F = 0.13 * 4e-6 / 2000 * -2.5e7
// = -6.5e-3 1/s, times v_ab = (0.3, -0.2) m/s. Against Morris's m_b 2 mu / (rho_a rho_b) F its
// ratio is 2 rho_a rho_b / (rho0 (rho_a + rho_b)) = 0.999984: the two agree to the pair's
// density variation squared.
TEST(LaminarViscosity, LoShaoByHand) {
  const LaminarViscosityConstants water{1e-3, 1000.0};
  const LaminarPair<2> pair{0.13,        1004.0, 996.0,          1.0 / 1004.0,
                            1.0 / 996.0, -2.5e7, Vec2(0.3, -0.2)};
  const Vec2 a = LoShaoViscosity::acceleration<2>(water, pair);
  EXPECT_NEAR(a.x(), -1.95e-3, 1e-15);
  EXPECT_NEAR(a.y(), 1.3e-3, 1e-15);
  const Vec2 morris = MorrisViscosity::acceleration<2>(water, pair);
  EXPECT_NEAR(a.x() / morris.x(), 0.999984, 1e-12);
}

}  // namespace
}  // namespace porosph::water
