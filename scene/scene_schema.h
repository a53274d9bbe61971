// The scene schema: every TOML table and key a scene may contain, declared once (scene_schema.cpp).
//
// The loader validates a scene against it (scene_validate.cpp) and scene_reference_markdown()
// renders it as docs/scene.md (scene_markdown.cpp), so the reference can never drift from the code.
// The keys a physics term owns are declared with the term (scene/term_registry.h, terms_*.cpp) and
// added by add_term_keys(). The rest is split by theme: scene_schema.cpp ([scene], [run], [domain],
// [water]), scene_schema_soil.cpp ([soil] and its materials and blocks), scene_schema_shared.cpp
// ([[walls]], [[observables]]); scene_schema_builder.h holds the fluent builder they share. Adding
// a phase means adding its TableSpecs and KeySpecs plus its conversion to the typed Scene
// (scene_build.cpp, scene_soil.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace porosph::scene {

/// Value types a scene key can hold.
enum class ValueType {
  Int,         ///< TOML integer
  Float,       ///< TOML float (an integer is accepted)
  Bool,        ///< TOML boolean
  String,      ///< TOML string
  Vector,      ///< array of `run.dimension` numbers (or vector_length, if set)
  VectorList,  ///< array of vectors
  StringList,  ///< array of strings
  BoolVector,  ///< array of `run.dimension` booleans
};

/// Extra constraint on the text of a String key.
enum class StringFormat {
  Any,
  Identifier,  ///< [A-Za-z_][A-Za-z0-9_]*
  Name,        ///< [A-Za-z_][A-Za-z0-9_-]*  (scene names: also hyphens)
};

/// A key's default. Constant and per-dimension defaults are written in TOML syntax.
struct DefaultValue {
  /// Required: must be given. Constant / PerDimension: filled in when absent. Optional: may be
  /// absent and then stays absent (the typed Scene holds its "not given" value). Derived: filled
  /// in from the rest of the scene by a rule of the loader (scene_validate.cpp), `rule` says which.
  enum class Kind { Required, Constant, PerDimension, Optional, Derived };
  Kind kind = Kind::Required;
  std::string toml;     ///< Constant
  std::string toml_2d;  ///< PerDimension, run.dimension = 2
  std::string toml_3d;  ///< PerDimension, run.dimension = 3
  std::string rule;     ///< Derived: the rule in words, as shown in the reference

  static DefaultValue required() { return {}; }
  static DefaultValue constant(std::string text) {
    return {Kind::Constant, std::move(text), {}, {}, {}};
  }
  static DefaultValue per_dimension(std::string text_2d, std::string text_3d) {
    return {Kind::PerDimension, {}, std::move(text_2d), std::move(text_3d), {}};
  }
  static DefaultValue optional() { return {Kind::Optional, {}, {}, {}, {}}; }
  static DefaultValue derived(std::string rule) {
    return {Kind::Derived, {}, {}, {}, std::move(rule)};
  }
  /// The default in TOML syntax for the given dimension.
  const std::string& text(int dimension) const {
    return kind == Kind::Constant ? toml : (dimension == 3 ? toml_3d : toml_2d);
  }
};

/// A closed or open numeric bound.
struct Bound {
  double value = 0.0;
  bool inclusive = true;
};

/// "Only when sibling key `key` has one of `values`" (e.g. min/max only when shape is box).
struct Condition {
  std::string key;
  std::vector<std::string> values;
};

/// One key of the scene.
struct KeySpec {
  std::string path;  ///< dotted, array-of-table elements as `walls[].min`
  ValueType type = ValueType::Float;
  std::string unit;  ///< SI unit, "" for dimensionless / not a quantity
  DefaultValue default_value;
  std::optional<Bound> min;  ///< numeric range (Int, Float, each Vector component)
  std::optional<Bound> max;
  std::vector<std::string> allowed;  ///< String / StringList: allowed values (empty: any)
  StringFormat format = StringFormat::Any;
  int vector_length = 0;                  ///< Vector / VectorList entries: 0 = run.dimension
  int min_count = 0;                      ///< VectorList / StringList: minimum number of entries
  std::optional<Condition> applies_when;  ///< key allowed (and required / defaulted) only then
  std::string description;

  /// Last path segment, e.g. "min" for `walls[].min`.
  std::string name() const;
  /// Path of the table holding the key, e.g. "walls[]" for `walls[].min`.
  std::string table() const;
};

/// One TOML table or array of tables.
struct TableSpec {
  std::string path;       ///< "run", "water", "walls[]", "water.blocks[]"
  bool array = false;     ///< [[path]] (array of tables)
  bool required = false;  ///< must be present (for an array: at least one entry), if its parent is
  std::string description;

  /// Path as written in a TOML header: "run", "walls", "water.blocks".
  std::string header_name() const;
};

struct SceneSchema {
  std::vector<TableSpec> tables;  ///< in documentation order; parents before children
  std::vector<KeySpec> keys;      ///< in documentation order, grouped by table

  const TableSpec* find_table(const std::string& path) const;
  const KeySpec* find_key(const std::string& path) const;
  /// Names (last segment) of the keys and sub-tables directly inside table `path` ("" = root).
  std::vector<std::string> child_names(const std::string& path) const;
};

/// The schema of every scene key (the single declaration of keys, units, defaults and ranges).
SceneSchema make_scene_schema();

/// "int", "float", ... as shown in the reference.
std::string type_name(ValueType type);

}  // namespace porosph::scene
