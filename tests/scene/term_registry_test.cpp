// The term registry (scene/term_registry.h) is the one place that decides the physics: its keys
// are the schema's, its switches follow the scene, a misspelt switch is a defect, and
// docs/terms.md is rendered from it.
#include "scene/term_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "scene/scene_schema.h"
#include "tests/scene/scene_examples.h"
#include "tests/scene/scene_examples_soil.h"

namespace porosph::scene::test {
namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(TermRegistry, DocsMatchTheRegistry) {
  const std::string path = std::string(POROSPH_SOURCE_DIR) + "/docs/terms.md";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << path
                  << "; generate it with: build/bin/coupler schema --terms > docs/terms.md";
  std::ostringstream docs;
  docs << in.rdbuf();
  EXPECT_EQ(docs.str(), term_reference_markdown())
      << path << " is out of date with scene/terms_*.cpp. Regenerate it with\n"
      << "  build/bin/coupler schema --terms > docs/terms.md";
}

TEST(TermRegistry, NamesAreUniquePerPhaseAndEachKeyIsDeclaredOnceInTheSchema) {
  const SceneSchema schema = make_scene_schema();
  std::set<std::string> names;
  for (const TermSpec& term : make_term_registry()) {
    EXPECT_TRUE(names.insert(term.phase + "/" + term.name).second) << term.name;
    EXPECT_TRUE(term.phase == "water" || term.phase == "soil" || term.phase == "interaction");
    EXPECT_FALSE(term.summary.empty()) << term.name;
    EXPECT_FALSE(term.runs_when.empty()) << term.name;
    EXPECT_TRUE(term.active) << term.name;
    for (const KeySpec& key : term.keys) {
      const auto count = std::count_if(schema.keys.begin(), schema.keys.end(),
                                       [&key](const KeySpec& k) { return k.path == key.path; });
      EXPECT_EQ(count, 1) << key.path << " of " << term.name;
    }
  }
  // The keys of a table stay together: the reference lists them under their table.
  std::map<std::string, std::vector<std::size_t>> rows;
  for (std::size_t i = 0; i < schema.keys.size(); ++i) rows[schema.keys[i].table()].push_back(i);
  for (const auto& [table, at] : rows)
    EXPECT_EQ(at.back() - at.front() + 1, at.size()) << table << " keys are not together";
}

TEST(TermRegistry, AMisspeltSwitchIsADefectNotOff) {
  const Scene s = load_scene_text(kWaterColumn2D, "column.toml");
  const TermSwitches on(s, "water");
  EXPECT_TRUE(on("continuity"));
  EXPECT_THROW(on("morris_viscocity"), std::logic_error);
  EXPECT_THROW(TermSwitches(s, "air"), std::logic_error);
}

TEST(TermRegistry, SwitchesFollowTheScene) {
  const Scene defaults = load_scene_text(kWaterColumn2D, "column.toml");
  const auto terms = active_terms(defaults, "water");
  for (const char* name :
       {"continuity", "pressure_gradient", "gravity", "morris_viscosity", "artificial_viscosity",
        "artificial_viscosity_at_walls_normal", "density_diffusion", "walls_no_slip"})
    EXPECT_TRUE(has(terms, name)) << name;
  EXPECT_FALSE(has(terms, "walls_free_slip"));
  EXPECT_FALSE(has(terms, "artificial_viscosity_at_walls"));  // "full" is opt-in (docs/terms.md)
  EXPECT_FALSE(has(terms, "periodic"));
  EXPECT_TRUE(active_terms(defaults, "soil").empty());         // no soil in the scene
  EXPECT_TRUE(active_terms(defaults, "interaction").empty());  // nothing to exchange

  const Scene off =
      load_scene_text(kWaterColumn2D, "column.toml",
                      {"water.viscosity=0", "water.alpha=0", "water.density_diffusion=0",
                       "water.wall_condition=\"free_slip\""});
  const auto fewer = active_terms(off, "water");
  for (const char* name :
       {"morris_viscosity", "artificial_viscosity", "artificial_viscosity_at_walls",
        "artificial_viscosity_at_walls_normal", "density_diffusion", "walls_no_slip"})
    EXPECT_FALSE(has(fewer, name)) << name;
  EXPECT_TRUE(has(fewer, "walls_free_slip"));

  const Scene full = load_scene_text(kWaterColumn2D, "column.toml",
                                     {"water.artificial_viscosity_at_walls=\"full\""});
  EXPECT_TRUE(has(active_terms(full, "water"), "artificial_viscosity_at_walls"));
  EXPECT_FALSE(has(active_terms(full, "water"), "artificial_viscosity_at_walls_normal"));
  const Scene none = load_scene_text(kWaterColumn2D, "column.toml",
                                     {"water.artificial_viscosity_at_walls=\"none\""});
  EXPECT_FALSE(has(active_terms(none, "water"), "artificial_viscosity_at_walls"));
  EXPECT_FALSE(has(active_terms(none, "water"), "artificial_viscosity_at_walls_normal"));
  EXPECT_TRUE(has(active_terms(none, "water"), "artificial_viscosity"));
}

TEST(TermRegistry, TheCoupledBedExchangesItsSeepageLaw) {
  const Scene s = load_scene_text(kSubmergedBed2D, "bed.toml");
  const auto exchange = active_terms(s, "interaction");
  EXPECT_TRUE(has(exchange, "saturation"));
  EXPECT_TRUE(has(exchange, "submerged_density"));
  for (const char* name : {"seepage_force", "seepage_forchheimer_den_adel",
                           "seepage_darcy_kozeny_carman", "fixed_bed", "implicit_drag"})
    EXPECT_TRUE(has(exchange, name)) << name;
  EXPECT_FALSE(has(exchange, "seepage_darcy_conductivity"));
  const auto soil = active_terms(s, "soil");
  EXPECT_TRUE(has(soil, "drucker_prager_return"));
  // The fixed gravel is held like a wall: its stress continues the weight unless asked for the
  // linear continuation (an option, docs/soil.md, Walls).
  EXPECT_FALSE(has(soil, "wall_stress_linear_continuation"));
  const Scene linear =
      load_scene_text(kSubmergedBed2D, "bed.toml", {"soil.wall_stress_continuation=\"linear\""});
  EXPECT_TRUE(has(active_terms(linear, "soil"), "wall_stress_linear_continuation"));
}

}  // namespace
}  // namespace porosph::scene::test
