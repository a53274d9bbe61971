// Internals of the scene loader, shared by its translation units (not part of the public API).
//
// Pipeline (scene_loader.cpp): parse TOML -> apply_overrides -> validate_against_schema (types,
// ranges, unknown keys, defaults filled in) -> check_scene_consistency (relations between keys)
// -> build_scene (typed Scene) -> promote_integers (resolved TOML).
#pragma once

#include <toml++/toml.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_schema.h"

namespace porosph::scene {

using NodePtr = std::unique_ptr<toml::node>;

/// The phases a scene can have, each a top-level table, in the order Scene::phases() reports them.
inline constexpr std::array<const char*, 2> kPhaseNames = {"water", "soil"};

/// Source name given to values parsed from `--set` overrides; errors in them name this file.
inline const std::string kOverrideSource = "--set";

/// Turns a problem at a TOML node into a SceneError naming the right file and line: the scene file
/// and the node's line, "--set" (line 0) for a value from an override, line 0 for a missing key
/// or a filled-in default.
class ErrorContext {
 public:
  explicit ErrorContext(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const toml::node* node, const std::string& key,
                         const std::string& message) const;

 private:
  std::string file_;
};

// ---- text helpers (scene_text.cpp) ----

/// Shortest text that reads back as the same double ("0.1", "-9.81", "1e-05").
std::string format_number(double value);
/// "a float", "an integer", "a string", ... for the message "expected X, got Y".
std::string node_type_phrase(const toml::node& node);
/// " (did you mean 'x'?)" for the candidate closest to `word` by edit distance, or "" if none is
/// close. `prefix` is prepended to the suggestion (e.g. "run.").
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates,
                         const std::string& prefix = "");
/// "'a', 'b' or 'c'" for {a, b, c}.
std::string quoted_list(const std::vector<std::string>& values);
/// "x", "y", "z" for axis 0, 1, 2.
const char* axis_name(std::size_t axis);
/// Concrete key path: join("walls[1]", "max") == "walls[1].max", join("", "run") == "run".
std::string join_key(const std::string& parent, const std::string& name);
/// The TOML value written in `text` (e.g. "0.1", "[1, 2]", "\"x\""), its source named `source`.
/// Returns nullptr if `text` is not a TOML value.
NodePtr parse_toml_value(const std::string& text, const std::string& source);

// ---- reading a validated, default-filled table (scene_build.cpp) ----

/// The numbers of an array node (empty for nullptr or a non-array).
std::vector<double> vector_of(const toml::node* node);
/// The strings of an array node (empty for nullptr or a non-array).
std::vector<std::string> strings_of(const toml::node* node);
/// The string at `name` in `table`, or "" if absent.
std::string text_of(const toml::table& table, const std::string& name);
/// A block or wall table as a Shape.
Shape shape_of(const toml::table& table);
/// Every table of an array of tables as a Shape (none for nullptr).
std::vector<Shape> shapes_of(const toml::array* array);

/// Relations inside one block or wall table (scene_consistency.cpp): min < max, inside the domain
/// (blocks), polygons only in 2D with non-zero area, container faces.
class ShapeChecker {
 public:
  ShapeChecker(const ErrorContext& errors, int dimension, const toml::table& domain)
      : errors_(errors), dimension_(dimension), domain_(domain) {}

  /// Checks the shape table `shape` (concrete key `key`, e.g. "walls[2]").
  void check(const toml::table& shape, const std::string& key, bool inside_domain) const;
  /// max > min in every component, else an error at max.
  void ordered(const toml::node* min, const toml::node* max, const std::string& max_key,
               const std::string& min_key) const;

 private:
  void within_domain(const toml::node* node, const std::string& key,
                     const std::string& where = "") const;
  void polygon(const toml::table& shape, const std::string& key, bool inside_domain) const;
  void faces(const toml::table& shape, const std::string& key) const;

  const ErrorContext& errors_;
  int dimension_;
  const toml::table& domain_;
};

// ---- the soil phase (scene_soil.cpp) ----

/// Relations inside [soil]: unique material names, exactly one elastic pair per material,
/// dilatancy <= friction, blocks inside the domain and naming a known material.
void check_soil_consistency(const toml::table& soil, const ShapeChecker& shapes,
                            const ErrorContext& errors);
/// The typed soil phase from a validated, default-filled [soil] table.
SoilPhase build_soil_phase(const toml::table& soil);
/// Relations inside [[soil.loads]] (scene_soil_loads.cpp): min < max, traction along one axis,
/// `material` one of `materials` (the names of [[soil.materials]]).
void check_soil_loads(const toml::table& soil, const std::vector<std::string>& materials,
                      const ShapeChecker& shapes, const ErrorContext& errors);
/// Fills p.loads from a validated [soil] table.
void build_soil_loads(const toml::table& soil, SoilPhase& p);

// ---- water flow zones and coupling settings (scene_flow.cpp) ----

/// Relations inside [[water.inflow]] / [[water.outflow]]: min < max, exactly one of velocity and
/// flow_rate (+ cross_section), direction along one axis.
void check_flow_zones(const toml::table& water, const ShapeChecker& shapes,
                      const ErrorContext& errors);
/// Relations of [[water.reservoir]] with the rest of the scene: min < max, gravity along one
/// axis, level inside the box along that axis.
void check_reservoirs(const toml::table& root, const ShapeChecker& shapes,
                      const ErrorContext& errors);
/// Fills w.inflows, w.outflows and w.reservoirs from a validated [water] table.
void build_flow_zones(const toml::table& water, WaterPhase& w);
/// The [coupling] settings (defaults when the table is absent).
CouplingSettings build_coupling(const toml::table& root);

// ---- pipeline steps ----

/// Applies each "a.b=value" to `root` (scene_overrides.cpp). Throws SceneError (file "--set").
void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     const SceneSchema& schema);

/// Checks every table and key against the schema and fills in defaults (scene_validate.cpp).
/// Returns run.dimension.
int validate_against_schema(toml::table& root, const SceneSchema& schema,
                            const ErrorContext& errors);

/// Checks relations between keys that the schema cannot express: min < max, shapes inside the
/// domain, polygons only in 2D, container faces, wall phases, observable phases, names, fields and
/// regions (scene_consistency.cpp), the soil phase (scene_soil.cpp).
void check_scene_consistency(const toml::table& root, int dimension, const ErrorContext& errors);

/// Reads the typed Scene from a validated, default-filled table (scene_build.cpp).
Scene build_scene(const toml::table& root);

/// Rewrites integers given for float keys as floats, so the resolved TOML shows the types the
/// schema declares (scene_validate.cpp).
void promote_integers(toml::table& root, const SceneSchema& schema);

}  // namespace porosph::scene
