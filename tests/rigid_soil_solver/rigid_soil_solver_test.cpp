// RigidSoilSolver on a small scene built in code: the lattice of its blocks, the overlap set it
// reports (at rest, no dt limit), the bookkeeping of the interaction with the submerged mass,
// size checks, checkpoints, and its snapshot fields against what the coupler's run.xdmf lists.
#include "rigid_soil_solver/rigid_soil_solver.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "coupler/run_record.h"
#include "scene/scene_loader.h"

namespace porosph::rigid_soil {
namespace {

// Two overlapping soil blocks (the second only adds x in [0.10, 0.14]) of two materials, under
// water. dp = 0.01: the first block is 10 x 5 lattice points, the second adds 4 x 5.
const char* kScene = R"(
[scene]
name = "rigid_skeleton"
[run]
dp = 0.01
dt0 = 1.0e-4
end_time = 0.1
output_interval = 0.01
[domain]
min = [0.0, 0.0]
max = [0.2, 0.2]
[water]
rho0 = 1000.0
sound_speed = 10.0
[[water.blocks]]
shape = "box"
min = [0.0, 0.05]
max = [0.2, 0.1]
[soil]
[[soil.materials]]
name = "sand"
density = 1600.0
porosity = 0.4
young_modulus = 1.0e7
poisson_ratio = 0.3
friction_angle = 30.0
[[soil.materials]]
name = "gravel"
density = 1800.0
saturated_density = 2100.0
porosity = 0.3
young_modulus = 1.0e7
poisson_ratio = 0.3
friction_angle = 35.0
[[soil.blocks]]
shape = "box"
min = [0.0, 0.0]
max = [0.1, 0.05]
material = "sand"
[[soil.blocks]]
shape = "box"
min = [0.05, 0.0]
max = [0.14, 0.05]
material = "gravel"
)";

scene::Scene test_scene() { return scene::load_scene_text(kScene, "rigid_skeleton.toml"); }

/// The whole box: every particle is in the overlap zone.
const std::vector<double> kAllMin = {0.0, 0.0}, kAllMax = {0.2, 0.2};

TEST(RigidSkeleton, FillsEachLatticePointOfTheBlocksOnce) {
  const auto skeleton = build_rigid_skeleton<2>(test_scene());
  ASSERT_EQ(skeleton.size(), 50u + 20u);
  EXPECT_EQ(skeleton.n_free, 0u);
  for (std::size_t i = 0; i < skeleton.size(); ++i) {
    EXPECT_EQ(skeleton.fixed[i], 1);
    EXPECT_EQ(skeleton.id[i], static_cast<std::int64_t>(i));
    const bool gravel = skeleton.position[i][0] > 0.1;
    EXPECT_EQ(skeleton.material[i], gravel ? 1 : 0) << "x = " << skeleton.position[i][0];
    EXPECT_DOUBLE_EQ(skeleton.mass[i], (gravel ? 1800.0 : 1600.0) * 1e-4);
    EXPECT_DOUBLE_EQ(skeleton.porosity[i], gravel ? 0.3 : 0.4);
  }
  EXPECT_DOUBLE_EQ(skeleton.position[0][0], 0.005);
  EXPECT_DOUBLE_EQ(skeleton.position[0][1], 0.005);
}

TEST(RigidSoilSolver, ReportsTheOverlapZoneAtRestWithoutADtLimit) {
  RigidSoilSolver<2> solver(test_scene());
  coupling::StepState state;
  solver.fill_state(state, {}, {});  // before the coupler named a zone: none
  EXPECT_TRUE(state.overlap_id.empty());
  EXPECT_EQ(state.dt_limit, std::numeric_limits<double>::infinity());
  EXPECT_EQ(state.diagnostics.particle_count, 70u);
  EXPECT_EQ(state.diagnostics.free_count, 0u);
  EXPECT_EQ(state.diagnostics.mass, 0.0);
  EXPECT_DOUBLE_EQ(state.region_min[0], 0.005);
  EXPECT_DOUBLE_EQ(state.region_max[0], 0.135);
  EXPECT_DOUBLE_EQ(state.region_max[1], 0.045);

  solver.fill_state(state, {0.0, 0.03}, {0.2, 0.2});  // the top two rows
  ASSERT_EQ(state.overlap_id.size(), 2u * 14u);
  ASSERT_EQ(state.overlap_velocity.size(), 2u * 28u);
  for (double v : state.overlap_velocity) EXPECT_EQ(v, 0.0);
  for (std::size_t k = 0; k < state.overlap_id.size(); ++k) {
    EXPECT_GE(state.overlap_position[2 * k + 1], 0.03);
    EXPECT_TRUE(state.overlap_porosity[k] == 0.4 || state.overlap_porosity[k] == 0.3);
  }
}

TEST(RigidSoilSolver, BooksTheAbsorbedImpulseWithTheSubmergedMassAndNeverMoves) {
  RigidSoilSolver<2> solver(test_scene());
  const auto before = solver.skeleton().position;
  coupling::StepState state;
  solver.fill_state(state, kAllMin, kAllMax);
  const std::size_t n = state.overlap_id.size();
  ASSERT_EQ(n, 70u);
  std::vector<double> acceleration(2 * n), saturation(n);
  for (std::size_t k = 0; k < n; ++k) {
    acceleration[2 * k] = 0.5;
    acceleration[2 * k + 1] = -2.0;
    saturation[k] = k % 2 == 0 ? 1.0 : 0.0;  // even: submerged (>= 0.8), odd: dry
  }
  solver.add_interaction(acceleration);
  solver.set_saturation(saturation);
  const double dt = 1e-3;
  solver.advance(dt);
  EXPECT_EQ(solver.step(), 1u);
  EXPECT_DOUBLE_EQ(solver.time(), dt);
  // r_m = (rho_sat - rho_w) / rho: sand (1600 + 0.4 * 1000 - 1000) / 1600, gravel given 2100.
  const double ratio[2] = {1000.0 / 1600.0, 1100.0 / 1800.0};
  double expected_y = 0.0;
  const auto& S = solver.skeleton();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(state.overlap_id[k]);
    const double submerged_mass = S.mass[i] * (k % 2 == 0 ? ratio[S.material[i]] : 1.0);
    EXPECT_DOUBLE_EQ(S.absorbed_impulse[i][1], submerged_mass * -2.0 * dt) << "particle " << i;
    EXPECT_DOUBLE_EQ(S.absorbed_impulse[i][0], submerged_mass * 0.5 * dt);
    EXPECT_EQ(S.saturation[i], saturation[k]);
    expected_y += submerged_mass * -2.0 * dt;
  }
  EXPECT_NEAR(solver.total_absorbed_impulse()[1], expected_y, 1e-15);
  EXPECT_EQ(S.position, before);

  // A command without accelerations (e.g. no water near) books nothing more.
  solver.fill_state(state, kAllMin, kAllMax);
  solver.set_saturation({});
  solver.advance(dt);
  EXPECT_NEAR(solver.total_absorbed_impulse()[1], expected_y, 1e-15);
  EXPECT_EQ(S.saturation[0], 0.0);
}

TEST(RigidSoilSolver, RejectsArraysOfTheWrongSizeAndReportsNonFiniteImpulse) {
  RigidSoilSolver<2> solver(test_scene());
  coupling::StepState state;
  solver.fill_state(state, kAllMin, kAllMax);
  EXPECT_THROW(solver.add_interaction(std::vector<double>(3, 0.0)), std::invalid_argument);
  EXPECT_THROW(solver.set_saturation(std::vector<double>(3, 0.0)), std::invalid_argument);
  EXPECT_FALSE(solver.find_non_finite(nullptr));
  std::vector<double> acceleration(2 * state.overlap_id.size(), 0.0);
  acceleration[2 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  solver.add_interaction(acceleration);
  solver.advance(1e-3);
  std::int64_t bad = -1;
  const auto problem = solver.find_non_finite(&bad);
  ASSERT_TRUE(problem);
  EXPECT_EQ(bad, state.overlap_id[5]);
  EXPECT_NE(problem->find("absorbed impulse"), std::string::npos) << *problem;
}

TEST(RigidSoilSolver, ContinuesFromItsCheckpoint) {
  const auto scene = test_scene();
  RigidSoilSolver<2> first(scene), second(scene);
  coupling::StepState state;
  first.fill_state(state, kAllMin, kAllMax);
  first.add_interaction(std::vector<double>(2 * state.overlap_id.size(), -1.0));
  first.set_saturation(std::vector<double>(state.overlap_id.size(), 0.9));
  first.advance(2e-3);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("porosph-rigid-checkpoint-" + std::to_string(getpid()) + ".h5"))
                               .string();
  {
    io::CheckpointWriter out(path);
    first.write_checkpoint(out);
    out.commit();
  }
  second.restore_checkpoint(io::CheckpointReader(path));
  std::filesystem::remove(path);
  EXPECT_EQ(second.step(), 1u);
  EXPECT_EQ(second.time(), first.time());
  EXPECT_EQ(second.total_absorbed_impulse(), first.total_absorbed_impulse());
  EXPECT_EQ(second.skeleton().saturation, first.skeleton().saturation);
  EXPECT_NE(first.total_absorbed_impulse()[1], 0.0);
}

// Every field the coupler's run.xdmf lists for the soil phase is in the snapshot with the width
// it declares, so ParaView reads a rigid-skeleton run like a soil_solver run.
TEST(RigidSoilSolver, WritesEverySoilFieldTheCouplersIndexLists) {
  RigidSoilSolver<2> solver(test_scene());
  const auto fields = solver.snapshot_fields();
  const auto find = [&](const std::string& name) {
    return std::find_if(fields.begin(), fields.end(),
                        [&](const io::FieldView& f) { return f.name == name; });
  };
  ASSERT_NE(find("position"), fields.end());
  EXPECT_EQ(find("position")->cols, 2u);
  for (const io::XdmfField& listed : coupler::snapshot_fields_of_phase("soil", 2)) {
    const auto it = find(listed.name);
    ASSERT_NE(it, fields.end()) << listed.name;
    EXPECT_EQ(it->cols, listed.cols) << listed.name;
    EXPECT_EQ(it->rows, 70u) << listed.name;
  }
  EXPECT_NE(find("absorbed_impulse"), fields.end());
}

}  // namespace
}  // namespace porosph::rigid_soil
