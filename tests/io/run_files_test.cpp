// io::water_snapshot_path: water.h5, or fluid.h5 of a run written before the phase had one name.
#include "io/run_files.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/io/scratch_dir.h"

namespace porosph::io {
namespace {

using test::ScratchDir;

void touch(const std::string& path) { std::ofstream(path) << "x"; }

TEST(RunFiles, WaterSnapshotsAreWaterH5UnlessOnlyTheFormerNameIsThere) {
  ScratchDir dir;
  const std::string run = dir.path().string();
  EXPECT_EQ(water_snapshot_path(run), dir.file("water.h5"));  // none: the current name
  touch(dir.file("fluid.h5"));
  EXPECT_EQ(water_snapshot_path(run), dir.file("fluid.h5"));  // an older run
  touch(dir.file("water.h5"));
  EXPECT_EQ(water_snapshot_path(run), dir.file("water.h5"));  // both: the current one wins
}

}  // namespace
}  // namespace porosph::io
