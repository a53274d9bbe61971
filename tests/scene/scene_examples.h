// Small scenes shared by the scene tests, and helpers to edit them and find lines in them.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "scene/scene_loader.h"

namespace porosph::scene::test {

/// A 2D water column at rest in a container open at the top: every required key and a few
/// optional ones, everything else left at its default.
inline const std::string kWaterColumn2D = R"(# A 2D water column at rest in a container.
[scene]
name = "water_column"
description = "Water column at rest"

[run]
end_time = 0.5
output_interval = 0.05
dp = 0.01
dt0 = 1e-4

[domain]
min = [-0.1, -0.1]
max = [1.1, 1.5]

[water]
sound_speed = 20.0

[[water.blocks]]
shape = "box"
min = [0, 0]
max = [0.5, 0.4]
label = "column"

[[walls]]
shape = "container"
min = [0.0, 0.0]
max = [1.0, 1.0]
open_faces = ["y+"]

[[observables]]
name = "height"
kind = "max_height"
direction = [0.0, 2.0]
)";

/// A 3D box of water with a polygon-free geometry, a box wall and every observable kind.
inline const std::string kWaterBox3D = R"([scene]
name = "box-3d"

[run]
dimension = 3
end_time = 1
output_interval = 0.1
dp = 0.02
dt0 = 2e-4
periodic = [true, false, false]
kernel = "wendland_c2"

[domain]
min = [0, 0, 0]
max = [1, 1, 1]

[water]
sound_speed = 30
viscosity = 0

[[water.blocks]]
shape = "box"
min = [0, 0, 0]
max = [1, 0.5, 0.3]

[[walls]]
shape = "box"
min = [-0.06, -0.06, -0.06]
max = [1.06, 1.06, 0.0]
remove_at = 0.5

[[observables]]
name = "front"
kind = "front_position"
direction = [1, 0, 0]
origin = [0, 0, 0.1]

[[observables]]
name = "p_bottom"
kind = "pressure_at"
point = [0.5, 0.5, 0.01]

[[observables]]
name = "vmax"
kind = "max_speed"

[[observables]]
name = "ek"
kind = "kinetic_energy"

[[observables]]
name = "count"
kind = "particle_count"
)";

/// `text` with the first occurrence of `from` replaced by `to` (the test fails if absent).
inline std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "example has no '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// 1-based line of the first occurrence of `marker` in `text` (0 if absent).
inline int line_of(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return 0;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

/// The SceneError thrown by loading `text` as "x.toml" (the test fails if none is thrown).
inline SceneError error_of(const std::string& text,
                           const std::vector<std::string>& overrides = {}) {
  try {
    load_scene_text(text, "x.toml", overrides);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError thrown";
  return SceneError("", 0, "", "");
}

/// One scene with exactly one mistake and the error it must give.
struct ErrorCase {
  const char* label;
  std::string text;    ///< the scene with one mistake
  std::string key;     ///< key named in the error
  std::string marker;  ///< text on the reported line ("" : no line, e.g. a missing key)
  std::string message;
};

/// Loading `c.text` as "x.toml" throws exactly "x.toml:LINE: key 'KEY': MESSAGE", LINE being the
/// line of the marker (none for an empty marker).
inline void expect_error(const ErrorCase& c) {
  SCOPED_TRACE(c.label);
  const SceneError e = error_of(c.text);
  const int line = c.marker.empty() ? 0 : line_of(c.text, c.marker);
  ASSERT_TRUE(c.marker.empty() || line > 0) << "marker not in the text: " << c.marker;
  const std::string expected = "x.toml" + (line > 0 ? ":" + std::to_string(line) : "") + ": key '" +
                               c.key + "': " + c.message;
  EXPECT_EQ(std::string(e.what()), expected);
  EXPECT_EQ(e.file(), "x.toml");
  EXPECT_EQ(e.line(), line);
  EXPECT_EQ(e.key(), c.key);
}

/// `text` without the part from the first `from` up to (not including) the next `up_to`.
inline std::string erase(std::string text, const std::string& from, const std::string& up_to) {
  const auto begin = text.find(from);
  const auto end = text.find(up_to, begin);
  EXPECT_NE(end, std::string::npos) << from << " ... " << up_to;
  if (begin == std::string::npos || end == std::string::npos) return text;
  return text.erase(begin, end - begin);
}

}  // namespace porosph::scene::test
