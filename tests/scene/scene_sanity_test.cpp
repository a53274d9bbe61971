// "No silent nonsense" (issue 29, scene/scene_sanity.cpp): a scene whose every value is in range
// but whose derived quantities are meaningless (overflow, underflow, an output interval far below
// the time step, a porosity the solver would clamp) is refused at load, naming file:line:key.
#include "scene/scene_sanity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/scene/scene_examples.h"
#include "tests/scene/scene_examples_soil.h"

namespace porosph::scene::test {
namespace {

struct SanityCase {
  const char* label;
  std::string text;
  std::string key;
  std::string marker;   ///< text on the line the error must name ("": line 0)
  std::string message;  ///< a part of the message
};

void expect_refused(const SanityCase& c) {
  SCOPED_TRACE(c.label);
  const SceneError e = error_of(c.text);
  EXPECT_EQ(e.key(), c.key) << e.what();
  EXPECT_EQ(e.line(), c.marker.empty() ? 0 : line_of(c.text, c.marker)) << e.what();
  EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
}

TEST(SceneSanity, MeaninglessCombinationsNameTheirKey) {
  const std::string& c = kWaterColumn2D;
  const std::string& b = kSubmergedBed2D;
  const std::vector<SanityCase> cases = {
      {"a snapshot every step", with(c, "output_interval = 0.05", "output_interval = 1e-300"),
       "run.output_interval", "output_interval", "far below the expected time step ~0.0001 s"},
      {"porosity the solver would clamp", with(b, "porosity = 0.42", "porosity = 0.999"),
       "soil.materials[1].porosity", "porosity = 0.999", "must be in [0.01, 0.99], got 0.999"},
      {"effective_diameter = inf",
       with(b, "effective_diameter = 0.0004", "effective_diameter = inf"),
       "soil.materials[1].effective_diameter", "effective_diameter",
       "must be a finite number, got inf"},
      {"rho0 = inf", with(b, "sound_speed = 15.0", "sound_speed = 15.0\nrho0 = inf"), "water.rho0",
       "rho0", "must be a finite number, got inf"},
      {"Kozeny-Carman without a water viscosity",
       with(b, "sound_speed = 15.0", "sound_speed = 15.0\nviscosity = 0"), "water.viscosity",
       "viscosity = 0", "needs a water viscosity > 0"},
      {"|g| overflows", with(c, "dt0 = 1e-4", "dt0 = 1e-4\ngravity = [1e300, -1e300]"),
       "run.gravity", "gravity", "overflows to inf"},
      {"pressure scale overflows",
       with(c, "sound_speed = 20.0", "sound_speed = 1e160\nrho0 = 1e10"), "water.sound_speed",
       "sound_speed", "rho0 c^2 = inf Pa"},
      {"particle mass underflows", with(c, "dp = 0.01", "dp = 1e-200"), "run.dp",
       "dp =", "particle mass rho0 dp^2 = 0 kg"},
      {"kinematic viscosity overflows",
       with(c, "sound_speed = 20.0", "sound_speed = 20.0\nrho0 = 1e-300\nviscosity = 1e300"),
       "water.viscosity", "viscosity = 1e300", "mu / rho0 = inf"},
      {"P-wave speed overflows",
       with(b, "young_modulus = 1e7\npoisson_ratio = 0.25",
            "young_modulus = 1e305\npoisson_ratio = 0.49999999"),
       "soil.materials[1].young_modulus", "young_modulus", "P-wave speed"},
      {"grain diameter squared underflows",
       with(b, "effective_diameter = 0.0004", "effective_diameter = 1e-200"),
       "soil.materials[1].effective_diameter", "effective_diameter", "its square 0 m^2"},
      {"an integer beyond int", with(c, "dt0 = 1e-4", "dt0 = 1e-4\neuler_every = 9999999999"),
       "run.euler_every", "euler_every", "must be at most 2147483647 in magnitude"},
      {"a huge wall thickness", with(c, "open_faces", "layers = 4294967297\nopen_faces"),
       "walls[0].layers", "layers", "must be at most 2147483647 in magnitude"},
  };
  for (const SanityCase& s : cases) expect_refused(s);
}

TEST(SceneSanity, OverridesAreBlamedOnTheCommandLine) {
  const SceneError e = error_of(kWaterColumn2D, {"run.output_interval=1e-300"});
  EXPECT_EQ(e.file(), "--set");
  EXPECT_EQ(e.key(), "run.output_interval");
}

TEST(SceneSanity, AnOutputIntervalBelowDt0IsFine) {
  // dt0 = 1e-4 is the expected step; an interval down to a tenth of it means "every step".
  const Scene scene = load_scene_text(
      with(kWaterColumn2D, "output_interval = 0.05", "output_interval = 2e-5"), "x.toml");
  EXPECT_DOUBLE_EQ(expected_time_step(scene), 1e-4);
}

/// kWaterColumn2D (dp 0.01) with a flow_rate inflow zone from y = 0.5 to y_max (a sheet
/// running along x), or a velocity zone.
std::string with_inflow(const std::string& y_max, bool flow_rate = true) {
  return kWaterColumn2D + "\n[[water.inflow]]\nmin = [0.0, 0.5]\nmax = [0.1, " + y_max +
         "]\ndirection = [1.0, 0.0]\n" +
         (flow_rate ? "flow_rate = 0.01\ncross_section = 0.04\n" : "velocity = 0.25\n");
}

TEST(SceneSanity, FlowRateZoneMustBeWholeRowsAcrossTheFlow) {
  // 0.045 m across at dp 0.01 holds four rows (0.04 m): the zone would carry 88.9 % of flow_rate.
  expect_refused({"flow_rate zone 4.5 rows across", with_inflow("0.545"), "water.inflow[0].max",
                  "max = [0.1, 0.545]", "carry 88.9 % of flow_rate"});
  // The same over an override of dp: 0.04 m at dp 0.0283 is one row, 70.7 %.
  const SceneError e = error_of(with_inflow("0.54"), {"run.dp=0.028284"});
  EXPECT_EQ(e.key(), "water.inflow[0].max") << e.what();
  EXPECT_NE(std::string(e.what()).find("carry 70.7 % of flow_rate"), std::string::npos) << e.what();
  // Whole rows (four, and two at dp 0.02) pass; a velocity zone prescribes no discharge.
  EXPECT_NO_THROW(load_scene_text(with_inflow("0.54"), "x.toml"));
  EXPECT_NO_THROW(load_scene_text(with(with_inflow("0.54"), "dp = 0.01", "dp = 0.02"), "x.toml"));
  EXPECT_NO_THROW(load_scene_text(with_inflow("0.545", false), "x.toml"));
}

TEST(SceneSanity, ExpectedTimeStepTakesTheSmallestLimit) {
  // h = 0.012 m: cfl h / c = 0.2 * 0.012 / 20 = 1.2e-4 > dt0; gravity 1e9: the force limit
  // c_a sqrt(h / |g|) = 0.25 sqrt(1.2e-11) = 8.66e-7 s.
  const Scene scene = load_scene_text(
      with(kWaterColumn2D, "dt0 = 1e-4", "dt0 = 1e-4\ngravity = [0, -1e9]"), "x.toml");
  EXPECT_NEAR(expected_time_step(scene), 0.25 * std::sqrt(0.012 / 1e9), 1e-12);
}

}  // namespace
}  // namespace porosph::scene::test
