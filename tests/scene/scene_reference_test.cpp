// docs/scene.md is exactly the reference rendered from the schema, and the reference covers every
// key of the schema.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scene/scene_loader.h"
#include "scene/scene_schema.h"

namespace porosph::scene::test {
namespace {

TEST(SceneReference, DocsMatchTheSchema) {
  const std::string path = std::string(POROSPH_SOURCE_DIR) + "/docs/scene.md";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << path
                  << "; generate it with: build/bin/coupler schema --markdown > docs/scene.md";
  std::ostringstream docs;
  docs << in.rdbuf();
  const std::string expected = scene_reference_markdown();
  if (docs.str() != expected) {
    const std::string fresh = ::testing::TempDir() + "scene.md";
    std::ofstream(fresh, std::ios::binary) << expected;
    FAIL() << path << " is out of date with scene/scene_schema.cpp. Regenerate it with\n"
           << "  build/bin/coupler schema --markdown > docs/scene.md\n"
           << "(the expected content was also written to " << fresh << ")";
  }
}

TEST(SceneReference, EveryKeyHasARowUnderItsTable) {
  const SceneSchema schema = make_scene_schema();
  const std::string md = scene_reference_markdown();
  for (const TableSpec& table : schema.tables) {
    const std::string heading =
        table.array ? "## [[" + table.header_name() + "]]" : "## [" + table.header_name() + "]";
    const auto table_at = md.find(heading + "\n");
    ASSERT_NE(table_at, std::string::npos) << heading;
    const auto next_table = md.find("\n## ", table_at + 1);
    for (const KeySpec& key : schema.keys) {
      if (key.table() != table.path) continue;
      const auto row = md.find("| `" + key.name() + "` |", table_at);
      EXPECT_TRUE(row != std::string::npos && row < next_table) << key.path;
      EXPECT_FALSE(key.description.empty()) << key.path;
    }
  }
}

}  // namespace
}  // namespace porosph::scene::test
