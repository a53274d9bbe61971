// [[water.reservoir]] (scene_flow.cpp): the typed zones, and the errors of `coupler check` naming
// the file, the line and the key (a box with min >= max, a level outside the box along gravity,
// gravity not along one axis, a missing level).
#include <gtest/gtest.h>

#include "tests/scene/scene_examples.h"

namespace porosph::scene::test {
namespace {

const std::string kReservoir = R"([[water.reservoir]]
min = [0.0, 0.0]
max = [0.2, 0.8]
level = 0.4

[[walls]])";

std::string with_reservoir(const std::string& from = "", const std::string& to = "") {
  const std::string r = from.empty() ? kReservoir : with(kReservoir, from, to);
  return with(kWaterColumn2D, "[[walls]]", r);
}

TEST(SceneReservoirs, TypedZones) {
  const Scene s =
      load_scene_text(with_reservoir("level = 0.4", "level = 0.4\nstart_time = 0.5"), "x.toml");
  ASSERT_EQ(s.water->reservoirs.size(), 1u);
  const ReservoirZone& z = s.water->reservoirs[0];
  EXPECT_EQ(z.min, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(z.max, (std::vector<double>{0.2, 0.8}));
  EXPECT_EQ(z.level, 0.4);
  EXPECT_EQ(z.start_time, 0.5);
  EXPECT_EQ(load_scene_text(with_reservoir(), "x.toml").water->reservoirs[0].start_time, 0.0);
  EXPECT_TRUE(load_scene_text(kWaterColumn2D, "x.toml").water->reservoirs.empty());
  // --set reaches the entries.
  const Scene o = load_scene_text(with_reservoir(), "x.toml", {"water.reservoir.0.level=0.3"});
  EXPECT_EQ(o.water->reservoirs[0].level, 0.3);
}

TEST(SceneReservoirs, ErrorsNameFileLineAndKey) {
  const std::vector<ErrorCase> cases = {
      {"level above the box", with_reservoir("level = 0.4", "level = 0.9"),
       "water.reservoir[0].level", "level = 0.9",
       "must lie inside the box along y (between 0 and 0.8), got 0.9"},
      {"level at the box's bottom", with_reservoir("level = 0.4", "level = 0.0"),
       "water.reservoir[0].level", "level = 0.0",
       "must lie inside the box along y (between 0 and 0.8), got 0"},
      {"empty box", with_reservoir("max = [0.2, 0.8]", "max = [0.0, 0.8]"),
       "water.reservoir[0].max", "max = [0.0, 0.8]",
       "must be greater than water.reservoir[0].min in every component; x: 0 <= 0"},
      {"gravity not along one axis",
       with(with_reservoir(), "dt0 = 1e-4", "dt0 = 1e-4\ngravity = [1.0, -9.81]"),
       "water.reservoir[0].level", "level = 0.4",
       "a reservoir needs run.gravity along one axis, e.g. [0.0, -9.81]"},
      {"missing level", with_reservoir("level = 0.4\n", ""), "water.reservoir[0].level", "",
       "required key is missing"},
  };
  for (const ErrorCase& c : cases) expect_error(c);
}

TEST(SceneReservoirs, OpenBoundaryKeysAndTheirErrors) {
  const std::string open = "level = 0.4\nboundary = \"open\"\ndirection = [1.0, 0.0]";
  const Scene s = load_scene_text(with_reservoir("level = 0.4", open), "x.toml");
  EXPECT_EQ(s.water->reservoirs[0].boundary, "open");
  EXPECT_EQ(s.water->reservoirs[0].direction, (std::vector<double>{1.0, 0.0}));
  EXPECT_EQ(load_scene_text(with_reservoir(), "x.toml").water->reservoirs[0].boundary, "surface");
  EXPECT_FALSE(s.water->reservoirs[0].absorbing);
  EXPECT_TRUE(load_scene_text(with_reservoir("level = 0.4", open + "\nabsorbing = true"), "x.toml")
                  .water->reservoirs[0]
                  .absorbing);
  const std::vector<ErrorCase> cases = {
      {"absorbing on a surface reservoir",
       with_reservoir("level = 0.4", "level = 0.4\nabsorbing = true"),
       "water.reservoir[0].absorbing", "absorbing = true", "is for boundary = \"open\" only"},
      {"open without direction", with_reservoir("level = 0.4", "level = 0.4\nboundary = \"open\""),
       "water.reservoir[0].direction", "boundary = \"open\"",
       "an open reservoir needs `direction` (into the domain, e.g. [1.0, 0.0])"},
      {"direction on a surface reservoir",
       with_reservoir("level = 0.4", "level = 0.4\ndirection = [1.0, 0.0]"),
       "water.reservoir[0].direction", "direction = [1.0, 0.0]",
       "`direction` is for boundary = \"open\" only"},
      {"direction along gravity",
       with_reservoir("level = 0.4", with(open, "[1.0, 0.0]", "[0.0, 1.0]")),
       "water.reservoir[0].direction", "direction = [0.0, 1.0]",
       "must point along one axis across gravity, e.g. [1.0, 0.0]"},
      {"open with a start time", with_reservoir("level = 0.4", open + "\nstart_time = 0.2"),
       "water.reservoir[0].start_time", "start_time = 0.2",
       "an open reservoir holds its level from t = 0; leave start_time out"},
      {"buffer thinner than the kernel support",
       with_reservoir("max = [0.2, 0.8]\nlevel = 0.4", "max = [0.01, 0.8]\n" + open),
       "water.reservoir[0].max", "max = [0.01, 0.8]",
       "the open reservoir's buffer holds 1 rows of run.dp = 0.01 m along its direction (0.01 "
       "m), less than the kernel support 2 h = 0.024 m: the water next to the open side would "
       "lack neighbours; widen the box"},
  };
  for (const ErrorCase& c : cases) expect_error(c);
}

}  // namespace
}  // namespace porosph::scene::test
