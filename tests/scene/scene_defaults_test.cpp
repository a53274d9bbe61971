// A valid scene loads into the typed Scene with every documented default filled in.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "tests/scene/scene_examples.h"

namespace porosph::scene::test {
namespace {

using Doubles = std::vector<double>;

TEST(SceneDefaults, MinimalWaterColumnGetsEveryDefault) {
  const Scene s = load_scene_text(kWaterColumn2D, "column.toml");
  EXPECT_EQ(s.name, "water_column");
  EXPECT_EQ(s.description, "Water column at rest");
  EXPECT_EQ(s.source_path, "column.toml");

  // Values given in the file (integers accepted for floats: block min is [0, 0]).
  EXPECT_EQ(s.run.end_time, 0.5);
  EXPECT_EQ(s.run.output_interval, 0.05);
  EXPECT_EQ(s.run.dp, 0.01);
  EXPECT_EQ(s.run.dt0, 1e-4);
  EXPECT_EQ(s.domain.min, (Doubles{-0.1, -0.1}));
  EXPECT_EQ(s.domain.max, (Doubles{1.1, 1.5}));

  // [run] defaults, exactly as documented.
  EXPECT_EQ(s.run.dimension, 2);
  EXPECT_EQ(s.run.h_factor, 1.2);
  EXPECT_EQ(s.h(), 1.2 * 0.01);
  EXPECT_EQ(s.run.cfl, 0.2);
  EXPECT_EQ(s.run.c_a, 0.25);
  EXPECT_EQ(s.run.viscous_coefficient, 0.125);
  EXPECT_TRUE(s.run.dt_smoothing);
  EXPECT_EQ(s.run.euler_every, 40);
  EXPECT_EQ(s.run.solver_timeout, 60.0);
  EXPECT_EQ(s.run.gravity, (Doubles{0.0, -9.81}));
  EXPECT_EQ(s.run.periodic, (std::vector<bool>{false, false}));
  EXPECT_EQ(s.run.kernel, "cubic_spline");

  // [water] defaults.
  ASSERT_TRUE(s.has_water());
  const WaterPhase& w = *s.water;
  EXPECT_EQ(w.rho0, 1000.0);
  EXPECT_EQ(w.sound_speed, 20.0);
  EXPECT_EQ(w.viscosity, 1e-3);
  EXPECT_EQ(w.alpha, 0.05);
  EXPECT_EQ(w.beta, 0.0);
  EXPECT_EQ(w.gamma, 7.0);
  EXPECT_EQ(w.density_filter_every, 0);
  EXPECT_TRUE(w.hydrostatic_initial);
  EXPECT_EQ(w.wall_condition, "no_slip");
  EXPECT_EQ(w.solver, "");
  ASSERT_EQ(w.blocks.size(), 1u);
  EXPECT_EQ(w.blocks[0].kind, Shape::Kind::Box);
  EXPECT_EQ(w.blocks[0].min, (Doubles{0.0, 0.0}));
  EXPECT_EQ(w.blocks[0].max, (Doubles{0.5, 0.4}));
  EXPECT_EQ(w.blocks[0].label, "column");

  // [[walls]]: container with the default 3 layers, never removed.
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].kind, Shape::Kind::Container);
  EXPECT_EQ(s.walls[0].layers, 3);
  EXPECT_EQ(s.walls[0].open_faces, (std::vector<std::string>{"y+"}));
  EXPECT_EQ(s.walls[0].label, "");
  EXPECT_EQ(s.walls[0].remove_at, -1.0);

  // [[observables]]: phase defaults to water, origin to zeros, direction normalised ([0, 2] ->
  // [0, 1] exactly: 2 / sqrt(4) has no rounding).
  ASSERT_EQ(s.observables.size(), 1u);
  EXPECT_EQ(s.observables[0].name, "height");
  EXPECT_EQ(s.observables[0].kind, "max_height");
  EXPECT_EQ(s.observables[0].phase, "water");
  EXPECT_EQ(s.observables[0].direction, (Doubles{0.0, 1.0}));
  EXPECT_EQ(s.observables[0].origin, (Doubles{0.0, 0.0}));
  EXPECT_TRUE(s.observables[0].point.empty());

  EXPECT_EQ(s.phases(), (std::vector<std::string>{"water"}));
}

TEST(SceneDefaults, ThreeDimensionalDefaultsHaveThreeComponents) {
  const Scene s = load_scene_text(kWaterBox3D, "box.toml");
  EXPECT_EQ(s.name, "box-3d");
  EXPECT_EQ(s.description, "");
  EXPECT_EQ(s.run.dimension, 3);
  EXPECT_EQ(s.run.gravity, (Doubles{0.0, 0.0, -9.81}));
  EXPECT_EQ(s.run.periodic, (std::vector<bool>{true, false, false}));
  EXPECT_EQ(s.run.kernel, "wendland_c2");
  EXPECT_EQ(s.run.end_time, 1.0);
  EXPECT_EQ(s.water->viscosity, 0.0);
  EXPECT_EQ(s.water->sound_speed, 30.0);
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].kind, Shape::Kind::Box);
  EXPECT_EQ(s.walls[0].remove_at, 0.5);
  EXPECT_TRUE(s.walls[0].open_faces.empty());  // not a container: no faces
  ASSERT_EQ(s.observables.size(), 5u);
  EXPECT_EQ(s.observables[0].direction, (Doubles{1.0, 0.0, 0.0}));
  EXPECT_EQ(s.observables[0].origin, (Doubles{0.0, 0.0, 0.1}));
  EXPECT_EQ(s.observables[1].point, (Doubles{0.5, 0.5, 0.01}));
  EXPECT_TRUE(s.observables[2].direction.empty());
  EXPECT_TRUE(s.observables[2].origin.empty());  // origin applies to front/height only
}

TEST(SceneDefaults, PolygonBlocksAndWallsIn2D) {
  const std::string text = with(with(kWaterColumn2D, R"(shape = "box"
min = [0, 0]
max = [0.5, 0.4])",
                                     R"(shape = "polygon"
vertices = [[0, 0], [0.5, 0], [0.5, 0.4], [0, 0.2]])"),
                                "[[observables]]", R"([[walls]]
shape = "polygon"
vertices = [[1, 0], [2, 0], [1, 1]]
label = "ramp"

[[observables]])");
  const Scene s = load_scene_text(text, "poly.toml");
  ASSERT_EQ(s.water->blocks.size(), 1u);
  EXPECT_EQ(s.water->blocks[0].kind, Shape::Kind::Polygon);
  EXPECT_EQ(s.water->blocks[0].vertices,
            (std::vector<Doubles>{{0, 0}, {0.5, 0}, {0.5, 0.4}, {0, 0.2}}));
  EXPECT_TRUE(s.water->blocks[0].min.empty());
  ASSERT_EQ(s.walls.size(), 2u);
  EXPECT_EQ(s.walls[1].kind, Shape::Kind::Polygon);
  EXPECT_EQ(s.walls[1].label, "ramp");
  EXPECT_EQ(s.walls[1].vertices.size(), 3u);
}

TEST(SceneDefaults, LoadsFromFile) {
  const std::string path = ::testing::TempDir() + "porosph_scene_column.toml";
  std::ofstream(path) << kWaterColumn2D;
  const Scene s = load_scene_file(path);
  EXPECT_EQ(s.source_path, path);
  EXPECT_EQ(s.name, "water_column");
  std::remove(path.c_str());
}

TEST(SceneDefaults, MissingFileIsASceneErrorNamingThePath) {
  const std::string path = "/nonexistent/dir/scene.toml";
  try {
    load_scene_file(path);
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace porosph::scene::test
