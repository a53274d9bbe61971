// No solver reaches into another (issue 24): the source files of each solver folder include no
// header of another solver or of the coupler, and its CMakeLists.txt links no other solver's or
// the coupler's library; porous/ (what they share) includes neither. What the phases share lives
// in porous/, sph/, scene/, io/ and proto/ (the solver SDK). The test reads the tree it was built
// from (POROSPH_SOURCE_DIR) and fails naming the file, the line and the offending include.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace porosph::porous {
namespace {

namespace fs = std::filesystem;

struct Boundary {
  std::string folder;                     ///< a solver, or porous/
  std::vector<std::string> foreign;       ///< folders it must not include from
  std::vector<std::string> foreign_libs;  ///< CMake targets it must not link
};

const std::vector<Boundary>& boundaries() {
  static const std::vector<Boundary> all = {
      {"fluid_solver",
       {"soil_solver/", "rigid_soil_solver/", "coupler/"},
       {"porosph_soil", "porosph_rigid_soil", "porosph_interaction", "porosph_coupler",
        "porosph_coupler_core"}},
      {"soil_solver",
       {"fluid_solver/", "rigid_soil_solver/", "coupler/"},
       {"porosph_water", "porosph_rigid_soil", "porosph_interaction", "porosph_coupler",
        "porosph_coupler_core"}},
      {"rigid_soil_solver",
       {"fluid_solver/", "soil_solver/", "coupler/"},
       {"porosph_water", "porosph_soil", "porosph_interaction", "porosph_coupler",
        "porosph_coupler_core"}},
      {"porous",
       {"fluid_solver/", "soil_solver/", "rigid_soil_solver/", "coupler/"},
       {"porosph_water", "porosph_soil", "porosph_rigid_soil", "porosph_interaction",
        "porosph_coupler", "porosph_coupler_core"}},
  };
  return all;
}

/// True if `word` occurs in `line` as a whole CMake target name (not as a prefix of a longer one,
/// e.g. porosph_soil in porosph_soil_model).
bool names_target(const std::string& line, const std::string& word) {
  for (std::size_t at = line.find(word); at != std::string::npos; at = line.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    const bool before = at == 0 || !(std::isalnum(line[at - 1]) || line[at - 1] == '_');
    const bool after = end == line.size() || !(std::isalnum(line[end]) || line[end] == '_');
    if (before && after) return true;
  }
  return false;
}

TEST(SolverBoundaries, NoSolverIncludesOrLinksAnotherSolverOrTheCoupler) {
  const fs::path root = POROSPH_SOURCE_DIR;
  int files = 0;
  for (const Boundary& b : boundaries()) {
    ASSERT_TRUE(fs::is_directory(root / b.folder)) << b.folder;
    for (const auto& entry : fs::recursive_directory_iterator(root / b.folder)) {
      const fs::path& p = entry.path();
      const std::string ext = p.extension().string();
      const bool source = ext == ".h" || ext == ".cpp" || ext == ".cu" || ext == ".hpp";
      const bool cmake = p.filename() == "CMakeLists.txt";
      if (!entry.is_regular_file() || !(source || cmake)) continue;
      ++files;
      std::ifstream in(p);
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        const std::string where =
            p.lexically_relative(root).string() + ":" + std::to_string(number) + ": " + line;
        if (source && line.rfind("#include \"", 0) == 0) {
          for (const std::string& f : b.foreign)
            EXPECT_NE(line.compare(10, f.size(), f), 0) << where;
        }
        if (cmake && line.find('#') != 0) {
          for (const std::string& lib : b.foreign_libs)
            EXPECT_FALSE(names_target(line, lib)) << where;
        }
      }
    }
  }
  EXPECT_GT(files, 40);  // the folders were found and read
}

TEST(SolverBoundaries, TheTargetMatchIsWholeWord) {
  EXPECT_TRUE(names_target("  LIBS porosph_soil)", "porosph_soil"));
  EXPECT_FALSE(names_target("  LIBS porosph_soil_model)", "porosph_soil"));
  EXPECT_FALSE(names_target("porosph_soil2", "porosph_soil"));
}

}  // namespace
}  // namespace porosph::porous
