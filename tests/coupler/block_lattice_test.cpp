// Bodies of one phase that overlap are refused at check (coupler/block_lattice.h; issue 24,
// hardening): exit 2, both blocks and their lines named; blocks that only touch pass.
#include "coupler/block_lattice.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "coupler/scene_check.h"

namespace porosph::coupler {
namespace {

/// 1-based line of the n-th (0-based) line of `path` that starts with `table`.
int line_of(const std::string& path, const std::string& table, int n) {
  std::ifstream in(path);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
    if (line.rfind(table, 0) == 0 && n-- == 0) return number;
  return -1;
}

int check(const std::string& scene, const std::vector<std::string>& overrides, std::string& err) {
  CheckOptions options;
  options.scene_path = scene;
  options.overrides = overrides;
  options.out_dir = ::testing::TempDir() + "block_lattice_out";
  std::ostringstream out, error;
  const int code = check_scene(options, out, error);
  err = error.str();
  return code;
}

TEST(BlockLattice, OverlappingWaterBlocksAreRefusedNamingBothLines) {
  const std::string weir = POROSPH_SOURCE_DIR "/cases/seepage_weir/scene.toml";
  std::string err;
  ASSERT_EQ(check(weir, {}, err), 0) << err;  // its blocks touch at y = 0.2: no shared point
  // The upstream pool reaching 5 cm down into the water of the sand layer.
  EXPECT_EQ(check(weir, {"water.blocks[1].min=[0.0, 0.15]"}, err), 2);
  const int first = line_of(weir, "[[water.blocks]]", 0);
  const int second = line_of(weir, "[[water.blocks]]", 1);
  EXPECT_NE(err.find("scene.toml:" + std::to_string(second) +
                     ": key 'water.blocks[1]': overlaps "
                     "water.blocks[0] 'in the sand' (line " +
                     std::to_string(first) + ")"),
            std::string::npos)
      << err;
}

TEST(BlockLattice, OverlappingSoilBlocksAreRefusedToo) {
  const std::string heave = POROSPH_SOURCE_DIR "/cases/hydraulic_heave/scene.toml";
  std::string err;
  ASSERT_EQ(check(heave, {}, err), 0) << err;  // sand, gap, sand and gravel touch
  EXPECT_EQ(check(heave, {"soil.blocks[1].min=[-0.02, 0.0]"}, err), 2);  // the gap into the sand
  EXPECT_NE(err.find("key 'soil.blocks[1]': overlaps soil.blocks[0] 'sand_downstream'"),
            std::string::npos)
      << err;
}

TEST(BlockLattice, ABlockThinnerThanDpAndADomainNarrowerThanTheSupportAreRefused) {
  const std::string weir = POROSPH_SOURCE_DIR "/cases/seepage_weir/scene.toml";
  std::string err;
  // The downstream pool 0.1 mm high: no lattice point at dp 10 mm.
  EXPECT_EQ(check(weir, {"water.blocks[2].max=[1.2, 0.2001]"}, err), 2);
  EXPECT_NE(err.find("scene.toml:" + std::to_string(line_of(weir, "[[water.blocks]]", 2)) +
                     ": key 'water.blocks[2]': holds no particle at run.dp = 0.01 m"),
            std::string::npos)
      << err;
  // dp 0.3 m: 2 h = 0.72 m against a domain about 0.5 m high.
  EXPECT_EQ(check(weir, {"run.dp=0.3"}, err), 2);
  EXPECT_NE(err.find("key 'run.dp': gives a kernel support 2 h = 2 run.h_factor dp = 0.72 m "
                     "wider than the domain along y"),
            std::string::npos)
      << err;
}

}  // namespace
}  // namespace porosph::coupler
