// `coupler check` (coupler/scene_check.h, in process) fed a few hundred mutated scenes, starting
// from cases/*/*.toml: numbers set to 0, -1, 1e300, 1e-300, huge integers, nan, inf; values of the
// wrong type; keys deleted; tables duplicated. None may crash or throw: every answer is exit 0 or 2
// with a reason, and none with a non-finite value passes (issue 29).
#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <regex>
#include <sstream>

#include "coupler/scene_check.h"

namespace porosph::coupler {
namespace {

namespace fs = std::filesystem;

/// Where a value sits: a key of a table or an element of an array.
struct Slot {
  toml::table* table = nullptr;
  std::string key;
  toml::array* array = nullptr;
  std::size_t index = 0;
};

void collect(toml::node& node, std::vector<Slot>& slots) {
  if (toml::table* table = node.as_table()) {
    for (auto& [key, child] : *table) {
      slots.push_back({table, std::string(key.str()), nullptr, 0});
      collect(child, slots);
    }
  } else if (toml::array* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) {
      slots.push_back({nullptr, "", array, i});
      collect(*array->get(i), slots);
    }
  }
}

/// Puts `value` where `slot` is.
template <class V>
void put(const Slot& slot, V&& value) {
  if (slot.table)
    slot.table->insert_or_assign(slot.key, std::forward<V>(value));
  else
    slot.array->replace(slot.array->cbegin() + static_cast<std::ptrdiff_t>(slot.index),
                        std::forward<V>(value));
}

void erase(const Slot& slot) {
  if (slot.table)
    slot.table->erase(slot.key);
  else
    slot.array->erase(slot.array->cbegin() + static_cast<std::ptrdiff_t>(slot.index));
}

/// Mutation `kind` of the value at `slot`; returns whether it put a non-finite number there.
bool mutate(const Slot& slot, int kind) {
  const double inf = std::numeric_limits<double>::infinity();
  switch (kind) {
    case 0:
      put(slot, int64_t{0});
      return false;
    case 1:
      put(slot, int64_t{-1});
      return false;
    case 2:
      put(slot, 1e300);
      return false;
    case 3:
      put(slot, 1e-300);
      return false;
    case 4:
      put(slot, std::numeric_limits<int64_t>::max());
      return false;
    case 5:
      put(slot, std::numeric_limits<int64_t>::min());
      return false;
    case 6:
      put(slot, std::numeric_limits<double>::quiet_NaN());
      return true;
    case 7:
      put(slot, inf);
      return true;
    case 8:
      put(slot, -inf);
      return true;
    case 9:
      put(slot, std::string("fuzz"));
      return false;
    case 10:
      put(slot, true);
      return false;
    case 11:
      put(slot, toml::array{});
      return false;
    case 12:
      put(slot, toml::table{});
      return false;
    case 13:
      put(slot, -1e300);
      return false;
    default:
      erase(slot);
      return false;
  }
}

constexpr int kMutationKinds = 15;

/// A value written as nan or inf (not inside a string) in a TOML text.
bool has_non_finite(const std::string& toml_text) {
  static const std::regex pattern(R"((=|,|\[)\s*[+-]?(nan|inf)\b)");
  std::istringstream lines(toml_text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line[0] == '#') continue;
    if (std::regex_search(line, pattern)) return true;
  }
  return false;
}

struct Outcome {
  int code = -1;
  std::string out, err;
};

Outcome check_text(const std::string& text, const fs::path& dir) {
  const fs::path file = dir / "scene.toml";
  std::ofstream(file) << text;
  CheckOptions options;
  options.scene_path = file.string();
  options.out_dir = (dir / "out").string();
  std::ostringstream out, err;
  Outcome outcome;
  try {
    outcome.code = check_scene(options, out, err);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "exception escaped check_scene: " << e.what() << "\n" << text;
  }
  outcome.out = out.str();
  outcome.err = err.str();
  return outcome;
}

std::vector<fs::path> case_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::recursive_directory_iterator(POROSPH_SOURCE_DIR "/cases"))
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string text_of(const toml::table& root) {
  std::ostringstream text;
  text << toml::toml_formatter(root) << "\n";
  return text.str();
}

TEST(CheckFuzz, MutatedCaseScenesExitZeroOrTwoAndNoNonFiniteValuePasses) {
  const fs::path dir =
      fs::temp_directory_path() / ("porosph_check_fuzz_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::mt19937 random(29);
  const auto scenes = case_scenes();
  ASSERT_FALSE(scenes.empty());
  // ~24 mutations per scene, a few hundred in all; a nightly run raises the total with
  // POROSPH_CHECK_FUZZ_SCENES (e.g. 10000).
  const char* env = std::getenv("POROSPH_CHECK_FUZZ_SCENES");
  const int per_scene =
      env != nullptr ? std::max(1, std::atoi(env) / static_cast<int>(scenes.size()) + 1) : 24;
  int tried = 0, passed = 0;
  for (const fs::path& scene : scenes) {
    const toml::table original = toml::parse_file(scene.string());
    std::vector<Slot> slots;
    toml::table probe = original;
    collect(probe, slots);
    for (int i = 0; i < per_scene; ++i) {
      toml::table copy = original;
      std::vector<Slot> copy_slots;
      collect(copy, copy_slots);
      const std::size_t at = random() % copy_slots.size();
      const int kind = static_cast<int>(random() % kMutationKinds);
      const bool non_finite = mutate(copy_slots[at], kind);
      const std::string text = text_of(copy);
      SCOPED_TRACE(scene.string() + ", mutation " + std::to_string(kind) + ":\n" + text);
      const Outcome outcome = check_text(text, dir);
      ++tried;
      ASSERT_TRUE(outcome.code == 0 || outcome.code == 2) << outcome.code << outcome.err;
      if (outcome.code == 2) {
        EXPECT_NE(outcome.err.find("coupler: "), std::string::npos) << outcome.err;
        continue;
      }
      ++passed;
      EXPECT_FALSE(non_finite) << "a non-finite value passed check";
      EXPECT_FALSE(has_non_finite(outcome.out)) << outcome.out;
    }
    // A duplicated table is a TOML error: exit 2, not a crash.
    const std::string text = text_of(original);
    const Outcome duplicated = check_text(text + "\n[run]\ndp = 0.01\n", dir);
    EXPECT_EQ(duplicated.code, 2) << duplicated.err;
    ++tried;
  }
  EXPECT_GE(tried, 200);
  EXPECT_GT(passed, 0);  // some mutations are harmless: the fuzz does not just break the syntax
  fs::remove_all(dir);
}

TEST(CheckFuzz, TheCaseScenesPassUnchanged) {
  const fs::path dir =
      fs::temp_directory_path() / ("porosph_check_cases_" + std::to_string(getpid()));
  fs::create_directories(dir);
  for (const fs::path& scene : case_scenes()) {
    CheckOptions options;
    options.scene_path = scene.string();
    options.out_dir = (dir / "out").string();
    std::ostringstream out, err;
    EXPECT_EQ(check_scene(options, out, err), 0) << scene << ": " << err.str();
    EXPECT_NE(out.str().find("# size: ~"), std::string::npos) << out.str();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace porosph::coupler
