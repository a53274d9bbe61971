// Internal to the schema declaration (scene_schema*.cpp): the fluent builder each key is declared
// with, and the functions that add one theme of tables and keys to the schema.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/scene_schema.h"

namespace porosph::scene::schema_detail {

/// Fluent builder so each key reads as one sentence.
class Key {
 public:
  Key(std::string path, ValueType type) {
    spec_.path = std::move(path);
    spec_.type = type;
  }
  Key& unit(std::string u) {
    spec_.unit = std::move(u);
    return *this;
  }
  Key& required() {
    spec_.default_value = DefaultValue::required();
    return *this;
  }
  /// May be absent; nothing is filled in (the typed Scene holds its "not given" value).
  Key& optional() {
    spec_.default_value = DefaultValue::optional();
    return *this;
  }
  Key& fallback(std::string toml) {
    spec_.default_value = DefaultValue::constant(std::move(toml));
    return *this;
  }
  Key& fallback_per_dimension(std::string toml_2d, std::string toml_3d) {
    spec_.default_value = DefaultValue::per_dimension(std::move(toml_2d), std::move(toml_3d));
    return *this;
  }
  /// Filled in from the rest of the scene; the rule must exist in scene_validate.cpp.
  Key& derived(std::string rule) {
    spec_.default_value = DefaultValue::derived(std::move(rule));
    return *this;
  }
  Key& above(double v) {
    spec_.min = Bound{v, false};
    return *this;
  }
  Key& at_least(double v) {
    spec_.min = Bound{v, true};
    return *this;
  }
  Key& below(double v) {
    spec_.max = Bound{v, false};
    return *this;
  }
  Key& at_most(double v) {
    spec_.max = Bound{v, true};
    return *this;
  }
  Key& one_of(std::vector<std::string> values) {
    spec_.allowed = std::move(values);
    return *this;
  }
  Key& format(StringFormat f) {
    spec_.format = f;
    return *this;
  }
  Key& vector_length(int n) {
    spec_.vector_length = n;
    return *this;
  }
  Key& min_count(int n) {
    spec_.min_count = n;
    return *this;
  }
  Key& only_when(std::string key, std::vector<std::string> values) {
    spec_.applies_when = Condition{std::move(key), std::move(values)};
    return *this;
  }
  KeySpec doc(std::string description) {
    spec_.description = std::move(description);
    return spec_;
  }

 private:
  KeySpec spec_;
};

using T = ValueType;

/// [scene], [run], [domain] (scene_schema.cpp).
void add_scene_and_run(SceneSchema& s);
/// [water], [[water.blocks]] (scene_schema.cpp).
void add_water(SceneSchema& s);
/// [[water.inflow]], [[water.outflow]] (scene_flow.cpp).
void add_flow_zones(SceneSchema& s);
/// [coupling] (scene_flow.cpp).
void add_coupling(SceneSchema& s);
/// [soil], [[soil.materials]], [[soil.blocks]] (scene_schema_soil.cpp).
void add_soil(SceneSchema& s);
/// [[soil.loads]] (scene_soil_loads.cpp).
void add_soil_loads(SceneSchema& s);
/// The region keys every filled block has: shape (box | polygon), min, max, vertices, for the
/// array table `table` (e.g. "water.blocks[]") (scene_schema_shared.cpp).
void add_filled_region_keys(SceneSchema& s, const std::string& table);
/// The required box keys min, max [m] of a zone table (inflow, outflow, load boxes), e.g.
/// "water.inflow[]" (scene_schema_shared.cpp).
void add_zone_box_keys(SceneSchema& s, const std::string& table);
/// [[walls]], [[observables]] (scene_schema_shared.cpp).
void add_walls_and_observables(SceneSchema& s);

}  // namespace porosph::scene::schema_detail
