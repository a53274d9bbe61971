// WaterSolver::write_checkpoint / restore_checkpoint: the dam break (walls, Verlet with Euler
// steps, density diffusion) and an inflow channel (zone particles born, ids, mass counters)
// continue bit for bit after a restore.
#include <gtest/gtest.h>

#include "fluid_solver/water_solver.h"
#include "scene/scene_loader.h"
#include "tests/support/solver_checkpoint_check.h"

namespace porosph::water {
namespace {

TEST(WaterCheckpoint, DamBreakContinuesBitForBit) {
  const auto scene = scene::load_scene_file(
      std::string(POROSPH_SOURCE_DIR) + "/cases/dam_break/scene.toml", {"run.dp=0.004"});
  WaterSolver<2> first(scene), second(scene);
  // 45 steps: past an Euler step (every 40) and a re-sort by cell (every 20) on both sides.
  porosph::testing::expect_checkpoint_continues_exactly(first, second, 45, 45, scene.run.dt0);
}

TEST(WaterCheckpoint, InflowZoneBirthsContinueBitForBit) {
  // The zone 6 mm deep (three rows, 2.5 h at this dp). With the scene's 12 mm zone the first row
  // crosses only after the 2.2 m/s push has built the pressure that shrinks the step, and the
  // steps after the checkpoint then saw no second row. The first row is handed over after dp / 2
  // of travel; 400 steps after the checkpoint see the second (60 births in all).
  auto overrides = std::vector<std::string>{"run.dp=0.002",
                                            "soil.damping_duration=0.0",
                                            "water.inflow.0.start_time=0.0",
                                            "water.inflow.0.ramp_time=0.0",
                                            "water.inflow.0.flow_rate=0.05",
                                            "water.inflow.0.min=[0.0, -0.006]",
                                            "water.blocks.0.min=[0.0, -0.006]"};
  const auto scene = scene::load_scene_file(
      std::string(POROSPH_SOURCE_DIR) + "/cases/fluidized_bed/scene.toml", overrides);
  WaterSolver<2> first(scene), second(scene);
  coupling::StepState state;
  for (int i = 0; i < 400 && first.born_count() == 0; ++i) {
    porosph::testing::step_alone(first, state, scene.run.dt0);
  }
  ASSERT_GT(first.born_count(), 0u) << "particles born before the checkpoint";
  porosph::testing::expect_checkpoint_continues_exactly(first, second, 10, 400, scene.run.dt0);
  EXPECT_GT(first.born_count(), 30u) << "particles born after the checkpoint";
  EXPECT_EQ(second.born_count(), first.born_count());
  EXPECT_EQ(second.removed_count(), first.removed_count());
}

}  // namespace
}  // namespace porosph::water
