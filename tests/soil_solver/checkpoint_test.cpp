// SoilSolver::write_checkpoint / restore_checkpoint: a collapsing granular column (plastic flow,
// stress filter, walls) continues bit for bit after a restore.
#include <gtest/gtest.h>

#include "scene/scene_loader.h"
#include "soil_solver/soil_solver.h"
#include "tests/support/solver_checkpoint_check.h"

namespace porosph::soil {
namespace {

TEST(SoilCheckpoint, GranularCollapseContinuesBitForBit) {
  const auto scene = scene::load_scene_file(
      std::string(POROSPH_SOURCE_DIR) + "/cases/granular_collapse/scene.toml", {"run.dp=0.005"});
  SoilSolver<2> first(scene), second(scene);
  porosph::testing::expect_checkpoint_continues_exactly(first, second, 50, 50, scene.run.dt0);
  double plastic = 0.0;
  for (double p : second.particles().plastic_strain) plastic += p;
  EXPECT_GE(plastic, 0.0);
}

}  // namespace
}  // namespace porosph::soil
