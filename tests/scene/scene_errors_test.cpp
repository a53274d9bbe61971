// Every kind of scene error names the file, the line and the key, with a message saying what is
// wrong. Each case edits the valid example so exactly one thing is wrong.
#include <gtest/gtest.h>

#include "tests/scene/scene_examples.h"

namespace porosph::scene::test {
namespace {

/// `text` up to (not including) `marker`.
std::string before(const std::string& text, const std::string& marker) {
  EXPECT_NE(text.find(marker), std::string::npos) << marker;
  return text.substr(0, text.find(marker));
}

std::vector<ErrorCase> error_cases() {
  const std::string& c = kWaterColumn2D;
  const std::string& b = kWaterBox3D;
  const std::string dt0 = "dt0 = 1e-4";
  const std::string block = "max = [0.5, 0.4]";
  return {
      {"unknown key, with suggestion", with(c, "dp = 0.01", "dpp = 0.01"), "run.dpp",
       "dpp =", "unknown key (did you mean 'run.dp'?)"},
      {"unknown key in an array-of-tables entry", with(c, "open_faces", "open_face"),
       "walls[0].open_face", "open_face =", "unknown key (did you mean 'walls[0].open_faces'?)"},
      {"unknown table", c + "\n[sediment]\nd50 = 1\n", "sediment", "[sediment]", "unknown key"},
      {"wrong type", with(c, "dp = 0.01", "dp = \"fine\""), "run.dp",
       "dp =", "expected a float, got a string"},
      {"float for an integer", with(c, dt0, dt0 + "\neuler_every = 2.5"), "run.euler_every",
       "euler_every", "expected an integer, got a float"},
      {"table expected", "water = 3\n" + erase(c, "[water]", "[[walls]]"), "water", "water = 3",
       "expected a table ([water]), got an integer"},
      {"out of range, open bound", with(c, "dp = 0.01", "dp = -0.1"), "run.dp",
       "dp =", "must be > 0, got -0.1"},
      // TOML's nan and inf pass every "x < min" test; a non-finite value is an error of its own.
      {"nan", with(c, "dp = 0.01", "dp = nan"), "run.dp",
       "dp =", "must be a finite number, got nan"},
      {"inf", with(c, dt0, dt0 + "\ncfl = inf"), "run.cfl", "cfl",
       "must be a finite number, got inf"},
      {"-inf in a vector", with(c, "dp = 0.01", "dp = 0.01\ngravity = [0.0, -inf]"), "run.gravity",
       "gravity", "component 1: must be a finite number, got -inf"},
      {"out of range, closed interval", with(c, dt0, dt0 + "\nh_factor = 3.5"), "run.h_factor",
       "h_factor", "must be in [1, 3], got 3.5"},
      {"out of range, half-open interval", with(c, dt0, dt0 + "\ncfl = 0"), "run.cfl", "cfl",
       "must be in (0, 1], got 0"},
      {"dimension out of range", with(c, dt0, dt0 + "\ndimension = 4"), "run.dimension",
       "dimension", "must be in [2, 3], got 4"},
      {"wrong vector length", with(c, "min = [-0.1, -0.1]", "min = [-0.1, -0.1, 0]"), "domain.min",
       "min = [-0.1, -0.1, 0]", "expected 2 components (run.dimension = 2), got 3"},
      {"wrong bool vector length", with(c, dt0, dt0 + "\nperiodic = [true]"), "run.periodic",
       "periodic", "expected 2 components (run.dimension = 2), got 1"},
      {"wrong vector component", with(c, "max = [1.1, 1.5]", "max = [1.1, \"top\"]"), "domain.max",
       "max = [1.1, \"top\"]", "component 1: expected a number, got a string"},
      {"missing required key", with(c, dt0 + "\n", ""), "run.dt0", "", "required key is missing"},
      {"missing required key in an entry", with(c, block + "\n", ""), "water.blocks[0].max", "",
       "required key is missing"},
      {"missing required table", erase(c, "[domain]", "[water]"), "domain", "",
       "required table is missing"},
      {"bad enum", with(c, dt0, dt0 + "\nkernel = \"cubic\""), "run.kernel", "kernel",
       "must be 'cubic_spline' or 'wendland_c2', got 'cubic'"},
      {"bad enum, with suggestion", with(c, "shape = \"box\"", "shape = \"boxx\""),
       "water.blocks[0].shape", "shape = \"boxx\"",
       "must be 'box' or 'polygon', got 'boxx' (did you mean 'box'?)"},
      {"bad list entry", with(c, "[\"y+\"]", "[\"y+\", \"top\"]"), "walls[0].open_faces",
       "open_faces", "entry 1: must be 'x-', 'x+', 'y-', 'y+', 'z-' or 'z+', got 'top'"},
      {"bad scene name", with(c, "\"water_column\"", "\"water column\""), "scene.name",
       "name = \"water column\"",
       "must be an identifier (letters, digits, '_', '-'; not starting with a digit), got "
       "'water column'"},
      {"bad observable name", with(c, "\"height\"", "\"2nd\""), "observables[0].name",
       "name = \"2nd\"",
       "must be an identifier (letters, digits, '_'; not starting with a digit), got '2nd'"},
      {"key not applicable to the shape",
       with(c, block, block + "\nvertices = [[0, 0], [1, 0], [0, 1]]"), "water.blocks[0].vertices",
       "vertices", "only allowed when shape is 'polygon'"},
      {"key not applicable to the kind",
       with(c, "direction = [0.0, 2.0]", "direction = [0.0, 2.0]\npoint = [0, 0]"),
       "observables[0].point", "point", "only allowed when kind is 'pressure_at'"},
      {"too few polygon vertices",
       with(with(c, "shape = \"box\"", "shape = \"polygon\""), "min = [0, 0]\n" + block,
            "vertices = [[0, 0], [1, 0]]"),
       "water.blocks[0].vertices", "vertices", "expected at least 3 entries, got 2"},
      {"zero-area polygon",
       with(with(c, "shape = \"box\"", "shape = \"polygon\""), "min = [0, 0]\n" + block,
            "vertices = [[0, 0], [0.5, 0], [1, 0]]"),
       "water.blocks[0].vertices", "vertices", "polygon has zero area"},
      {"min not below max", with(c, block, "max = [0.5, 0]"), "water.blocks[0].max",
       "max = [0.5, 0]", "must be greater than water.blocks[0].min in every component; y: 0 <= 0"},
      {"domain min not below max", with(c, "max = [1.1, 1.5]", "max = [-0.2, 1.5]"), "domain.max",
       "max = [-0.2, 1.5]", "must be greater than domain.min in every component; x: -0.2 <= -0.1"},
      {"block outside the domain", with(c, block, "max = [0.5, 1.6]"), "water.blocks[0].max",
       "max = [0.5, 1.6]", "lies outside the domain: y = 1.6 not in [-0.1, 1.5]"},
      {"polygon in 3D",
       with(b, "shape = \"box\"\nmin = [0, 0, 0]\nmax = [1, 0.5, 0.3]",
            "shape = \"polygon\"\nvertices = [[0, 0], [1, 0], [0, 1]]"),
       "water.blocks[0].shape", "shape = \"polygon\"",
       "polygon shapes exist only in 2D (run.dimension = 3)"},
      {"z face in 2D", with(c, "[\"y+\"]", "[\"y+\", \"z+\"]"), "walls[0].open_faces", "open_faces",
       "face 'z+' needs a z axis (run.dimension = 2)"},
      {"duplicate face", with(c, "[\"y+\"]", "[\"y+\", \"y+\"]"), "walls[0].open_faces",
       "open_faces", "face 'y+' is listed twice"},
      {"duplicate observable name",
       c + "\n[[observables]]\nname = \"height\"\nkind = \"max_speed\"\n", "observables[1].name",
       "name = \"height\"\nkind = \"max_speed\"",
       "duplicate observable name 'height' (also observables[0])"},
      {"observable shadows a built-in column",
       c + "\n[[observables]]\nname = \"water_particles\"\nkind = \"particle_count\"\n",
       "observables[1].name", "name = \"water_particles\"",
       "observable name 'water_particles' is a built-in column of timeseries.csv; choose another "
       "name"},
      {"zero direction", with(c, "[0.0, 2.0]", "[0.0, 0.0]"), "observables[0].direction",
       "direction", "must not be the zero vector"},
      {"direction missing",
       with(with(c, "direction = [0.0, 2.0]\n", ""), "\"max_height\"", "\"front_position\""),
       "observables[0].direction", "", "required key is missing"},
      {"phase unknown", with(c, "kind = \"max_height\"", "kind = \"max_height\"\nphase = \"air\""),
       "observables[0].phase", "phase", "must be 'water' or 'soil', got 'air'"},
      {"phase not in the scene",
       with(c, "kind = \"max_height\"", "kind = \"max_height\"\nphase = \"soil\""),
       "observables[0].phase", "phase",
       "phase 'soil' is not in the scene (it has no [soil] table)"},
      {"no phase", before(erase(c, "[water]", "[[walls]]"), "[[observables]]"), "water", "",
       "the scene has no phase; add a [water] or a [soil] table"},
      {"water without blocks", erase(c, "[[water.blocks]]", "[[walls]]"), "water.blocks", "",
       "at least one [[water.blocks]] entry is required"},
  };
}

TEST(SceneErrors, NameFileLineKeyAndProblem) {
  for (const ErrorCase& c : error_cases()) expect_error(c);
}

TEST(SceneErrors, SyntaxErrorGivesTheParserLine) {
  const std::string text = with(kWaterColumn2D, "dp = 0.01", "dp = = 0.01");
  const SceneError e = error_of(text);
  EXPECT_EQ(e.file(), "x.toml");
  EXPECT_EQ(e.line(), line_of(text, "dp = = 0.01"));
  EXPECT_EQ(e.key(), "");
  const std::string prefix = "x.toml:" + std::to_string(e.line()) + ": TOML syntax error: ";
  EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix) << e.what();
}

TEST(SceneErrors, WallsMayExtendOutsideTheDomain) {
  // The same change that is an error for a water block (see "block outside the domain").
  const std::string text = with(kWaterColumn2D, "max = [1.0, 1.0]", "max = [2.0, 2.0]");
  EXPECT_EQ(load_scene_text(text, "x.toml").walls[0].max, (std::vector<double>{2.0, 2.0}));
}

TEST(SceneErrors, BlocksMayTouchTheDomainWithinTolerance) {
  // Within the documented 1e-9 m tolerance: accepted; 1e-6 m beyond it: rejected.
  const std::string touching =
      with(kWaterColumn2D, "max = [0.5, 0.4]", "max = [0.5, 1.5000000001]");
  EXPECT_NO_THROW(load_scene_text(touching, "x.toml"));
  const std::string beyond = with(kWaterColumn2D, "max = [0.5, 0.4]", "max = [0.5, 1.500001]");
  EXPECT_EQ(error_of(beyond).key(), "water.blocks[0].max");
}

}  // namespace
}  // namespace porosph::scene::test
