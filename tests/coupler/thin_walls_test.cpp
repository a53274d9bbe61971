// Walls too thin to separate two bodies of water (coupler/thin_walls.h, docs/water-in-soil.md
// section 2): the heave's 1 cm sheet pile is one layer at dp 10 mm, where with water.thin_walls =
// "shared" the case's water passed through it (docs/validation-studies.md), and four at its own
// dp 2.5 mm. The layer count itself is tested in tests/sph/wall_occluders_test.cpp.
#include "coupler/thin_walls.h"

#include <gtest/gtest.h>

#include <sstream>

#include "coupler/scene_check.h"
#include "scene/scene_loader.h"

namespace porosph::coupler {
namespace {

const std::string kHeave = POROSPH_SOURCE_DIR "/cases/hydraulic_heave/scene.toml";

TEST(ThinWalls, TheHeavesPileIsTooThinAtCoarseSpacings) {
  const auto coarse = thin_wall_warnings(
      scene::load_scene_file(kHeave, {"run.dp=0.01", "water.thin_walls=\"shared\""}));
  ASSERT_EQ(coarse.size(), 1u);
  EXPECT_NE(coarse[0].find("walls[1] 'sheet_pile'"), std::string::npos) << coarse[0];
  EXPECT_NE(coarse[0].find("is 1 particle layer thick along x"), std::string::npos) << coarse[0];
  EXPECT_NE(coarse[0].find("needs 4"), std::string::npos) << coarse[0];
  EXPECT_EQ(thin_wall_warnings(
                scene::load_scene_file(kHeave, {"run.dp=0.005", "water.thin_walls=\"shared\""}))
                .size(),
            1u);
  // The case's own spacing: four layers; the tank is a container (water on one side only).
  EXPECT_TRUE(
      thin_wall_warnings(scene::load_scene_file(kHeave, {"water.thin_walls=\"shared\""})).empty());
  // The default fills the pile on both sides (sph/wall_occluders.h): nothing to warn about.
  EXPECT_TRUE(thin_wall_warnings(scene::load_scene_file(kHeave, {"run.dp=0.01"})).empty());
}

TEST(ThinWalls, CheckPrintsTheWarningAndStillAcceptsTheScene) {
  CheckOptions options;
  options.scene_path = kHeave;
  options.overrides = {"run.dp=0.01", "water.thin_walls=\"shared\""};
  std::ostringstream out, err;
  EXPECT_EQ(check_scene(options, out, err), 0) << err.str();
  EXPECT_NE(err.str().find("coupler: warning: walls[1] 'sheet_pile'"), std::string::npos)
      << err.str();
}

}  // namespace
}  // namespace porosph::coupler
