// The soil porosity the coupler computes for each water overlap particle (StepCommand.porosity,
// docs/water-in-soil.md): n_a = 1 - sum_i V_i (1 - n_i) W_ia is the soil's n0 deep inside a soil
// lattice, 1 in free water, in between at the soil's edge; also in the damping stage (no forces),
// and empty when no soil is near.
#include <gtest/gtest.h>

#include "coupler/interaction/soil_water_interaction.h"
#include "tests/coupler/interaction_fixtures.h"

namespace porosph::testing {
namespace {

using coupler::SoilWaterInteraction;
using coupling::StepState;

/// A 20 x 20 soil lattice (dp 0.01) filling [0.3, 0.5]^2, porosity n0, at rest.
StepState soil_block(double n0) {
  StepState soil;
  const double dp = 0.01, density = 1600.0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      add_particle(soil, {0.3 + (i + 0.5) * dp, 0.3 + (j + 0.5) * dp}, {0.0, 0.0}, density,
                   density * dp * dp, n0, 0);
  return soil;
}

/// Water particles: the block's centre, its edge (on the boundary line), just outside the kernel
/// support of it, far away.
StepState water_probes() {
  StepState water;
  const double m = 1000.0 * 1e-4;
  for (const auto& x : std::vector<std::vector<double>>{
           {0.4, 0.4}, {0.4, 0.3}, {0.4, 0.3 - 0.005 - 0.024 - 1e-9}, {0.9, 0.9}})
    add_particle(water, x, {0.0, 0.01}, 1000.0, m);
  return water;
}

TEST(WaterPorosity, IsTheSoilsPorosityInsideAndOneInFreeWater) {
  scene::Scene s = two_phase_scene(kozeny_carman_material(0.4));
  for (double damping : {0.0, 1.0}) {  // with forces, and in the damping stage (saturation only)
    s.soil->damping_duration = damping;
    SoilWaterInteraction interaction(s, 1);
    const StepState soil = soil_block(0.4), water = water_probes();
    interaction.compute(water, soil, 0.0);
    const std::vector<double>& n = interaction.outputs().water_porosity;
    ASSERT_EQ(n.size(), 4u);
    EXPECT_NEAR(n[0], 0.4, 0.01) << "inside the lattice: n0 to the kernel sum's error";
    EXPECT_GT(n[1], 0.55);  // on the edge: about half the support in soil, n ~ (1 + n0) / 2
    EXPECT_LT(n[1], 0.85);
    EXPECT_EQ(n[2], 1.0);  // beyond 2h of every soil particle
    EXPECT_EQ(n[3], 1.0);
    std::vector<double> command;
    interaction.hand_over_porosity(command);
    EXPECT_EQ(command.size(), 4u);
  }
}

TEST(WaterPorosity, NoSoilNearGivesNone) {
  const scene::Scene s = two_phase_scene(kozeny_carman_material(0.4));
  SoilWaterInteraction interaction(s, 1);
  interaction.compute(water_probes(), StepState{}, 0.0);
  EXPECT_TRUE(interaction.outputs().water_porosity.empty());
}

}  // namespace
}  // namespace porosph::testing
