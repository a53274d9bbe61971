// The run size estimate and gate (coupler/run_size.h) and the coupler's run-time watch
// (coupler/run_watch.h): issue 29, "no silent nonsense".
#include "coupler/run_size.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "coupler/run_watch.h"
#include "coupler/scene_check.h"
#include "scene/scene_loader.h"

namespace porosph::coupler {
namespace {

const std::string kDamBreak = POROSPH_SOURCE_DIR "/cases/dam_break/scene.toml";

scene::Scene dam_break(const std::vector<std::string>& overrides = {}) {
  return scene::load_scene_file(kDamBreak, overrides);
}

MachineLimits big_machine() { return {1e12, 1e13, "/"}; }

TEST(RunSize, CountsTheLatticeOfBlocksAndWalls) {
  // The dam break's run.json says 4928 particles: 40 x 80 water, 1728 in the container walls.
  const RunSizeEstimate size = estimate_run_size(dam_break());
  ASSERT_EQ(size.phases.size(), 1u);
  EXPECT_EQ(size.phases[0].free_particles, 3200);
  EXPECT_EQ(size.phases[0].wall_particles, 1728);
  EXPECT_EQ(size.particles, 4928);
  EXPECT_EQ(size.snapshots, 51);  // end_time 0.2 / output_interval 0.004, plus t = 0
  EXPECT_DOUBLE_EQ(size.output_bytes, 51 * 4928 * 65.0);
  EXPECT_GT(size.memory_bytes, 4928 * 3000.0);
  EXPECT_EQ(run_size_problem(dam_break(), size, big_machine()), "");
}

TEST(RunSize, ATinyDpIsRefusedForMemoryNamingRunDp) {
  const scene::Scene scene = dam_break({"run.dp=1e-6"});
  const RunSizeEstimate size = estimate_run_size(scene);
  EXPECT_GT(size.particles, 6e9);  // 57 mm x 114 mm at 1 um, and the walls
  EXPECT_TRUE(std::isfinite(size.memory_bytes));
  const std::string problem = run_size_problem(scene, size, {64e9, 1e13, "/"});
  EXPECT_EQ(problem.rfind("--set: key 'run.dp': ", 0), 0u) << problem;
  EXPECT_NE(problem.find("of memory; this machine has 64 GB"), std::string::npos) << problem;
  EXPECT_NE(problem.find("--force-size"), std::string::npos) << problem;
  EXPECT_EQ(size_gate(scene, "", true), "");  // --force-size
}

TEST(RunSize, TooManySnapshotsNameTheLineOfOutputInterval) {
  const scene::Scene scene = dam_break({"run.end_time=100"});
  const std::string problem = run_size_problem(scene, estimate_run_size(scene), big_machine());
  // output_interval is on line 13 of the dam break scene (and was not overridden).
  EXPECT_EQ(problem.rfind(kDamBreak + ":13: key 'run.output_interval': ", 0), 0u) << problem;
  EXPECT_NE(problem.find("snapshots"), std::string::npos) << problem;
}

TEST(RunSize, OutputsBeyondTheFreeDiskAreRefused) {
  const scene::Scene scene = dam_break();
  const std::string problem = run_size_problem(scene, estimate_run_size(scene), {1e12, 1e6, "/x"});
  EXPECT_NE(problem.find("of disk; /x has 1 MB free"), std::string::npos) << problem;
}

TEST(RunSize, MachineLimitsAreMeasured) {
  const MachineLimits limits = machine_limits("/nonexistent/run/dir");
  EXPECT_GT(limits.memory_bytes, 1e8);
  EXPECT_GT(limits.disk_free_bytes, 0.0);
  EXPECT_EQ(limits.disk_path, "/");  // the nearest directory that exists
}

TEST(RunWatch, MachWarnsOnceAndKeepsTheMaximum) {
  MachRecord record;
  EXPECT_EQ(note_mach(record, 1.0, 20.0, 0.1, 10), "");  // Mach 0.05
  const std::string warning = note_mach(record, 3.0, 20.0, 0.2, 20);
  EXPECT_NE(warning.find("Mach 0.15"), std::string::npos) << warning;
  EXPECT_EQ(note_mach(record, 4.0, 20.0, 0.3, 30), "");  // once
  EXPECT_EQ(note_mach(record, 2.0, 20.0, 0.4, 40), "");
  EXPECT_DOUBLE_EQ(record.max, 0.2);
  EXPECT_DOUBLE_EQ(record.time, 0.3);
  EXPECT_EQ(record.step, 30u);
}

TEST(RunWatch, NonFiniteObservablesAreNamedUnlessEmptyByDesign) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  scene::Observable front{"front", "front_position", "water", {1, 0}, {0, 0}, {}, "", {}, {}};
  EXPECT_EQ(observable_problem(front, 0.3, 100), "");
  EXPECT_EQ(observable_problem(front, inf, 100),
            "observable 'front' (front_position of the "
            "water) is inf");
  EXPECT_NE(observable_problem(front, nan, 100), "");  // the whole phase has particles
  EXPECT_EQ(observable_problem(front, nan, 0), "");    // no free particle left
  scene::Observable in_box = front;
  in_box.region_min = {0, 0};
  in_box.region_max = {1, 1};
  EXPECT_EQ(observable_problem(in_box, nan, 100), "");  // an empty region
  scene::Observable probe{"p", "pressure_at", "water", {}, {}, {0.1, 0.1}, "", {}, {}};
  EXPECT_EQ(observable_problem(probe, nan, 100), "");  // no particle near the point
  EXPECT_NE(observable_problem(probe, -inf, 100), "");
  scene::Observable energy{"ek", "kinetic_energy", "water", {}, {}, {}, "", {}, {}};
  EXPECT_NE(observable_problem(energy, nan, 0), "");
}

}  // namespace
}  // namespace porosph::coupler
