// The soil sums of a water particle beside a wall, renormalised by the wall's share of its kernel
// support (coupling.drag_at_walls = "renormalised", coupler/interaction/wall_kernel_share.h): the
// first water column along a wall then sees the soil's porosity and the same drag as the water
// further in, where the truncated sums see too little soil; the pair forces stay antisymmetric.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupler/interaction/soil_water_interaction.h"
#include "tests/coupler/interaction_fixtures.h"

namespace porosph::testing {
namespace {

using coupler::SoilWaterInteraction;
using coupling::StepState;

constexpr double kDp = 0.01;

/// A 2D scene whose soil and water fill [0.3, 0.5] x [0.3, 0.5] beside a wall of 3 layers on the
/// left, x in [0.27, 0.3]; `acts_on`: the wall's phases (empty: both).
scene::Scene walled_scene(const std::string& drag_at_walls, std::vector<std::string> acts_on) {
  scene::Scene s = two_phase_scene(conductivity_material(1e-3));
  s.coupling.drag_at_walls = drag_at_walls;
  scene::Shape wall;
  wall.kind = scene::Shape::Kind::Box;
  wall.min = {0.27, 0.2};
  wall.max = {0.3, 0.6};
  wall.phases = std::move(acts_on);
  s.walls.push_back(wall);
  scene::Shape block;
  block.kind = scene::Shape::Kind::Box;
  block.min = {0.3, 0.3};
  block.max = {0.5, 0.5};
  s.soil->blocks.push_back(block);
  return s;
}

/// The 20 x 20 lattice of the block, at rest (soil) or seeping upwards at 1 cm/s (water).
StepState lattice(bool soil) {
  StepState out;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const std::vector<double> x = {0.3 + (i + 0.5) * kDp, 0.3 + (j + 0.5) * kDp};
      if (soil)
        add_particle(out, x, {0.0, 0.0}, 1600.0, 1600.0 * kDp * kDp, 0.4, 0);
      else
        add_particle(out, x, {0.0, 0.01}, 1000.0, 1000.0 * kDp * kDp);
    }
  return out;
}

/// Water particle of column i (from the wall), row j.
std::size_t at(int i, int j) { return static_cast<std::size_t>(i * 20 + j); }

TEST(WallKernelShare, FirstColumnBesideAWallSeesTheSoilsPorosityAndDrag) {
  const StepState soil = lattice(true), water = lattice(false);
  for (const std::string mode : {"truncated", "renormalised"}) {
    SoilWaterInteraction interaction(walled_scene(mode, {}), 1);
    interaction.compute(water, soil, 0.0);
    const auto& n = interaction.outputs().water_porosity;
    const auto& a = interaction.water_acceleration();
    // Mid-height (row 10), away from the block's other edges: column 0 touches the wall,
    // column 5 is beyond the kernel's reach of it (2h = 2.4 dp).
    const double drag_wall = a[2 * at(0, 10) + 1], drag_inside = a[2 * at(5, 10) + 1];
    ASSERT_LT(drag_inside, 0.0);  // the drag holds the rising water back
    EXPECT_NEAR(n[at(5, 10)], 0.4, 0.005) << mode;
    if (mode == "truncated") {
      // About a third of the support lies in the wall: porosity ~0.5, drag ~2/3.
      EXPECT_GT(n[at(0, 10)], 0.47);
      EXPECT_LT(drag_wall / drag_inside, 0.8);
    } else {
      // The lattice factor makes the wall and soil sums add up to 1 to round-off on the
      // lattice; 0.5 % covers the kernel sum's own error at the block's corners' distance.
      EXPECT_NEAR(n[at(0, 10)], 0.4, 0.005);
      EXPECT_NEAR(drag_wall / drag_inside, 1.0, 0.005);
    }
    // Antisymmetric pairs: what the water gets the soil gives (1e-12 of the total magnitude).
    const auto& out = interaction.outputs();
    EXPECT_NEAR(out.force_on_water[1] + out.force_on_soil[1], 0.0, 1e-12 * out.force_magnitude_sum)
        << mode;
  }
}

TEST(WallKernelShare, AWallTheSoilPassesThroughIsNotCounted) {
  // A wall acting on water only that lies inside a soil block holds soil: its share must not be
  // divided out (the soil sum is whole there). Here the soil block holds the whole wall.
  scene::Scene s = walled_scene("renormalised", {"water"});
  s.soil->blocks[0].min = {0.2, 0.1};
  s.soil->blocks[0].max = {0.5, 0.7};
  const StepState soil = lattice(true), water = lattice(false);
  SoilWaterInteraction renormalised(s, 1);
  s.coupling.drag_at_walls = "truncated";
  SoilWaterInteraction truncated(s, 1);
  renormalised.compute(water, soil, 0.0);
  truncated.compute(water, soil, 0.0);
  EXPECT_EQ(renormalised.water_acceleration(), truncated.water_acceleration());
  // The same wall outside the soil block (the block as drawn, [0.3, 0.5]) is counted.
  s.soil->blocks[0].min = {0.3, 0.3};
  s.soil->blocks[0].max = {0.5, 0.5};
  s.coupling.drag_at_walls = "renormalised";
  SoilWaterInteraction counted(s, 1);
  counted.compute(water, soil, 0.0);
  EXPECT_NEAR(counted.outputs().water_porosity[at(0, 10)], 0.4, 0.005);
}

/// Water on both sides of a one-layer wall x in [0.4, 0.41] (dp 10 mm), soil on its left only,
/// rows y in [0.3, 0.5]: the water lattice of both sides (left first), or the soil's.
StepState beside_thin_wall(bool soil) {
  StepState out;
  for (int i = 0; i < (soil ? 10 : 19); ++i)
    for (int j = 0; j < 20; ++j) {
      const double x0 = i < 10 ? 0.3 + (i + 0.5) * kDp : 0.41 + (i - 10 + 0.5) * kDp;
      const std::vector<double> x = {x0, 0.3 + (j + 0.5) * kDp};
      if (soil)
        add_particle(out, x, {0.0, 0.0}, 1600.0, 1600.0 * kDp * kDp, 0.4, 0);
      else
        add_particle(out, x, {0.0, 0.01}, 1000.0, 1000.0 * kDp * kDp);
    }
  return out;
}

TEST(WallKernelShare, AThinWallPartsTheWaterFromTheSoilBeyondIt) {
  // water.thin_walls = "separating" (sph/wall_occluders.h): the water right of the wall sees no
  // soil through it, and the water left of it sees the wall as a full support (both sides'
  // fill), so its sums are renormalised as beside a thick wall.
  scene::Scene s = walled_scene("renormalised", {});
  s.walls[0].min = {0.4, 0.2};
  s.walls[0].max = {0.41, 0.6};
  s.soil->blocks[0].max = {0.4, 0.5};
  scene::Shape left = s.soil->blocks[0], right = s.soil->blocks[0];
  right.min = {0.41, 0.3}, right.max = {0.5, 0.5};
  s.water->blocks = {left, right};
  const StepState soil = beside_thin_wall(true), water = beside_thin_wall(false);
  for (const std::string mode : {"separating", "shared"}) {
    s.water->thin_walls = mode;
    SoilWaterInteraction interaction(s, 1);
    interaction.compute(water, soil, 0.0);
    const auto& n = interaction.outputs().water_porosity;
    const auto& a = interaction.water_acceleration();
    const std::size_t beside = at(9, 10), inside = at(4, 10), across = at(10, 10);
    if (mode == "separating") {
      EXPECT_EQ(n[across], 1.0);  // no soil seen through the wall: no drag
      EXPECT_EQ(a[2 * across + 1], 0.0);
      // As beside the thick wall above (0.5 %: the kernel sum's own error).
      EXPECT_NEAR(n[beside], 0.4, 0.005);
      EXPECT_NEAR(a[2 * beside + 1] / a[2 * inside + 1], 1.0, 0.005);
    } else {
      // The shared wall: the soil's sums reach through it (the kernel's tail at 2 dp: 0.25 %).
      EXPECT_LT(n[across], 0.999);
      EXPECT_LT(a[2 * across + 1], 0.0);
    }
  }
}

TEST(WallKernelShare, SceneRejectsAnUnknownMode) {
  EXPECT_THROW(SoilWaterInteraction(walled_scene("sometimes", {}), 1), std::invalid_argument);
}

}  // namespace
}  // namespace porosph::testing
