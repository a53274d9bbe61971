// The coupler's feedback from observables to solvers (coupler/observable_feedback.h): one value per
// wall or load, the observable's latest value where one is named, 0 elsewhere and for NaN, and
// nothing at all where no wall moves or no load takes a force.
#include "coupler/observable_feedback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace porosph::coupler {
namespace {

TEST(ObservableFeedback, EachMovingWallGetsItsObservableAndTheOthersZero) {
  scene::Scene s;
  s.walls.resize(3);
  std::vector<double> speeds = {9.0};
  wall_speeds_from(s, {{"v", -1e-3}}, speeds);
  EXPECT_TRUE(speeds.empty());  // no wall moves: nothing sent
  s.walls[1].moves_with = "v";
  s.walls[2].moves_with = "gone";
  wall_speeds_from(s, {{"v", -1e-3}, {"gone", std::numeric_limits<double>::quiet_NaN()}}, speeds);
  EXPECT_EQ(speeds, (std::vector<double>{0.0, -1e-3, 0.0}));  // NaN holds the wall still
}

TEST(ObservableFeedback, EachLoadTakingAForceGetsItsObservable) {
  scene::Scene s;
  std::vector<double> forces = {1.0};
  load_forces_from(s, {{"f", 3.0}}, forces);
  EXPECT_TRUE(forces.empty());  // no soil
  s.soil = scene::SoilPhase{};
  s.soil->loads.resize(2);
  load_forces_from(s, {{"f", 3.0}}, forces);
  EXPECT_TRUE(forces.empty());  // no load takes one
  s.soil->loads[0].plus_force_from = "f";
  load_forces_from(s, {{"f", 42.5}}, forces);
  EXPECT_EQ(forces, (std::vector<double>{42.5, 0.0}));
  load_forces_from(s, {}, forces);  // not measured yet
  EXPECT_EQ(forces, (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace porosph::coupler
