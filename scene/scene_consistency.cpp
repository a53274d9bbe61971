// Relations between scene keys the schema cannot express: shapes (min < max, inside the domain,
// polygons only in 2D, container faces), wall phases, observables (unique names, phase present,
// field available, region). The soil phase's own relations are in scene_soil.cpp.
#include <algorithm>
#include <map>

#include "scene/scene_internal.h"
#include "scene/timeseries_columns.h"

namespace porosph::scene {
namespace {

/// Shapes may touch the domain faces up to round-off in the scene numbers.
constexpr double kDomainTolerance = 1e-9;

bool has_phase(const toml::table& root, const std::string& phase) {
  return root.get_as<toml::table>(phase) != nullptr;
}

std::string phase_missing(const std::string& phase) {
  return "phase '" + phase + "' is not in the scene (it has no [" + phase + "] table)";
}

/// Each listed phase is present and listed once.
void check_wall_phases(const toml::table& root, const toml::table& wall, const std::string& key,
                       const ErrorContext& errors) {
  const toml::array& phases = *wall.get_as<toml::array>("phases");
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const std::string phase = phases.get(i)->value<std::string>().value_or("");
    if (!has_phase(root, phase)) errors.fail(phases.get(i), key + ".phases", phase_missing(phase));
    for (std::size_t j = 0; j < i; ++j)
      if (phases.get(j)->value<std::string>() == phase)
        errors.fail(phases.get(i), key + ".phases", "phase '" + phase + "' is listed twice");
  }
}

/// The `key` text of each table of `array` (none: empty), of those whose `only_with` text is not
/// empty when `only_with` is given.
std::vector<std::string> texts_of(const toml::array* array, const std::string& key,
                                  const std::string& only_with = "") {
  std::vector<std::string> texts;
  if (array)
    for (const auto& element : *array) {
      const toml::table& t = *element.as_table();
      if (only_with.empty() || !text_of(t, only_with).empty()) texts.push_back(text_of(t, key));
    }
  return texts;
}

/// The names of the scene's observables.
std::vector<std::string> observable_names(const toml::table& root) {
  return texts_of(root.get_as<toml::array>("observables"), "name");
}

/// A moving wall (moves_with): it names an observable, has a non-zero move_direction of the
/// scene's dimension and acts on water only.
void check_wall_motion(const toml::table& root, const toml::table& wall, const std::string& key,
                       int dimension, const ErrorContext& errors) {
  const std::string follows = text_of(wall, "moves_with");
  const toml::node* direction = wall.get("move_direction");
  if (follows.empty()) {
    if (direction) errors.fail(direction, key + ".move_direction", "given without moves_with");
    return;
  }
  const std::vector<std::string> names = observable_names(root);
  if (std::find(names.begin(), names.end(), follows) == names.end())
    errors.fail(wall.get("moves_with"), key + ".moves_with",
                "no observable named '" + follows + "'" + did_you_mean(follows, names));
  if (!direction) {
    errors.fail(wall.get("moves_with"), key + ".move_direction",
                "required with moves_with (the direction the wall moves along)");
  } else {
    const auto d = vector_of(direction);
    if (static_cast<int>(d.size()) != dimension)
      errors.fail(
          direction, key + ".move_direction",
          "expected " + std::to_string(dimension) + " components, got " + std::to_string(d.size()));
    else if (std::all_of(d.begin(), d.end(), [](double c) { return c == 0.0; }))
      errors.fail(direction, key + ".move_direction", "must not be the zero vector");
  }
  const toml::array& phases = *wall.get_as<toml::array>("phases");
  if (phases.size() != 1 || phases.get(0)->value<std::string>().value_or("") != "water")
    errors.fail(wall.get("moves_with"), key + ".moves_with",
                "a moving wall acts on water only: give phases = [\"water\"]");
}

/// The wall a wall_force observable names is a moving wall; the observable measures the water.
void check_wall_force(const toml::table& root, const toml::table& observable,
                      const std::string& key, const ErrorContext& errors) {
  const toml::node* node = observable.get("wall");
  if (!node) return;
  const std::string wall = node->value<std::string>().value_or("");
  const std::vector<std::string> moving =
      texts_of(root.get_as<toml::array>("walls"), "label", "moves_with");
  if (std::find(moving.begin(), moving.end(), wall) == moving.end())
    errors.fail(node, key + ".wall",
                "no moving wall (moves_with) labelled '" + wall + "'" + did_you_mean(wall, moving));
  if (text_of(observable, "phase") != "water")
    errors.fail(observable.get("phase"), key + ".phase",
                "a wall_force observable measures the water: phase must be 'water'");
}

/// Each [[soil.loads]] plus_force_from names an observable.
void check_load_forces(const toml::table& root, const ErrorContext& errors) {
  const toml::array* loads = root["soil"]["loads"].as_array();
  if (!loads) return;
  const std::vector<std::string> names = observable_names(root);
  for (std::size_t i = 0; i < loads->size(); ++i) {
    const toml::table& load = *loads->get(i)->as_table();
    const std::string from = text_of(load, "plus_force_from");
    if (!from.empty() && std::find(names.begin(), names.end(), from) == names.end())
      errors.fail(load.get("plus_force_from"),
                  "soil.loads[" + std::to_string(i) + "].plus_force_from",
                  "no observable named '" + from + "'" + did_you_mean(from, names));
  }
}

/// The load a load_velocity observable names is a [[soil.loads]] label.
void check_load(const toml::table& root, const toml::table& observable, const std::string& key,
                const ErrorContext& errors) {
  const toml::node* node = observable.get("load");
  if (!node) return;
  const std::string load = node->value<std::string>().value_or("");
  const std::vector<std::string> labels = texts_of(root["soil"]["loads"].as_array(), "label");
  if (std::find(labels.begin(), labels.end(), load) == labels.end())
    errors.fail(node, key + ".load",
                "no [[soil.loads]] entry with label '" + load + "'" + did_you_mean(load, labels));
  if (text_of(observable, "phase") != "soil")
    errors.fail(observable.get("phase"), key + ".phase",
                "a load_velocity observable measures the soil: phase must be 'soil'");
}

/// The field exists on the observable's phase and in its dimension.
void check_field(const toml::table& observable, const std::string& key, int dimension,
                 const ErrorContext& errors) {
  const toml::node* node = observable.get("field");
  if (!node) return;
  const std::string field = node->value<std::string>().value_or("");
  const std::string phase = text_of(observable, "phase");
  const bool soil_only = field == "porosity" || field.rfind("stress_", 0) == 0;
  const std::string needed = field == "pressure" ? "water" : (soil_only ? "soil" : phase);
  if (needed != phase)
    errors.fail(
        node, key + ".field",
        "field '" + field + "' exists only for phase '" + needed + "' (phase is '" + phase + "')");
  if (field == "velocity_z" && dimension < 3)
    errors.fail(
        node, key + ".field",
        "field '" + field + "' needs a z axis (run.dimension = " + std::to_string(dimension) + ")");
}

/// region_min and region_max together or not at all, max > min.
void check_region(const toml::table& observable, const std::string& key, const ShapeChecker& shapes,
                  const ErrorContext& errors) {
  const toml::node* min = observable.get("region_min");
  const toml::node* max = observable.get("region_max");
  if (min && !max)
    errors.fail(min, key + ".region_min", "given without region_max (give both or neither)");
  if (max && !min)
    errors.fail(max, key + ".region_max", "given without region_min (give both or neither)");
  if (min) shapes.ordered(min, max, key + ".region_max", key + ".region_min");
}

void check_observables(const toml::table& root, int dimension, const ShapeChecker& shapes,
                       const ErrorContext& errors) {
  const toml::array* observables = root.get_as<toml::array>("observables");
  if (!observables) return;
  std::map<std::string, std::size_t> first_index;
  const auto builtin = builtin_timeseries_columns({"water", "soil"}, dimension, true);
  for (std::size_t i = 0; i < observables->size(); ++i) {
    const toml::table& observable = *observables->get(i)->as_table();
    const std::string key = "observables[" + std::to_string(i) + "]";
    const std::string name = text_of(observable, "name");
    if (const auto [it, inserted] = first_index.emplace(name, i); !inserted)
      errors.fail(observable.get("name"), key + ".name",
                  "duplicate observable name '" + name + "' (also observables[" +
                      std::to_string(it->second) + "])");
    if (std::find(builtin.begin(), builtin.end(), name) != builtin.end())
      errors.fail(observable.get("name"), key + ".name",
                  "observable name '" + name +
                      "' is a built-in column of timeseries.csv; choose another name");
    const std::string phase = text_of(observable, "phase");
    if (!has_phase(root, phase))
      errors.fail(observable.get("phase"), key + ".phase", phase_missing(phase));
    if (const toml::node* direction = observable.get("direction")) {
      const auto d = vector_of(direction);
      if (std::all_of(d.begin(), d.end(), [](double c) { return c == 0.0; }))
        errors.fail(direction, key + ".direction", "must not be the zero vector");
    }
    check_field(observable, key, dimension, errors);
    check_region(observable, key, shapes, errors);
    check_load(root, observable, key, errors);
    check_wall_force(root, observable, key, errors);
  }
}

}  // namespace

void ShapeChecker::check(const toml::table& shape, const std::string& key,
                         bool inside_domain) const {
  const std::string kind = text_of(shape, "shape");
  if (kind == "polygon") {
    if (dimension_ != 2)
      errors_.fail(
          shape.get("shape"), key + ".shape",
          "polygon shapes exist only in 2D (run.dimension = " + std::to_string(dimension_) + ")");
    polygon(shape, key, inside_domain);
    return;
  }
  const toml::node* min = shape.get("min");
  const toml::node* max = shape.get("max");
  ordered(min, max, key + ".max", key + ".min");
  if (inside_domain) {
    within_domain(min, key + ".min");
    within_domain(max, key + ".max");
  }
  if (kind == "container") faces(shape, key);
}

void ShapeChecker::ordered(const toml::node* min, const toml::node* max, const std::string& max_key,
                           const std::string& min_key) const {
  const auto lo = vector_of(min);
  const auto hi = vector_of(max);
  for (std::size_t i = 0; i < lo.size(); ++i)
    if (!(hi[i] > lo[i]))
      errors_.fail(max, max_key,
                   "must be greater than " + min_key + " in every component; " + axis_name(i) +
                       ": " + format_number(hi[i]) + " <= " + format_number(lo[i]));
}

void ShapeChecker::within_domain(const toml::node* node, const std::string& key,
                                 const std::string& where) const {
  const auto point = vector_of(node);
  const auto lo = vector_of(domain_.get("min"));
  const auto hi = vector_of(domain_.get("max"));
  for (std::size_t i = 0; i < point.size(); ++i)
    if (point[i] < lo[i] - kDomainTolerance || point[i] > hi[i] + kDomainTolerance)
      errors_.fail(node, key,
                   where + "lies outside the domain: " + axis_name(i) + " = " +
                       format_number(point[i]) + " not in [" + format_number(lo[i]) + ", " +
                       format_number(hi[i]) + "]");
}

void ShapeChecker::polygon(const toml::table& shape, const std::string& key,
                           bool inside_domain) const {
  const toml::array& vertices = *shape.get_as<toml::array>("vertices");
  double twice_area = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto a = vector_of(vertices.get(i));
    const auto b = vector_of(vertices.get((i + 1) % vertices.size()));
    twice_area += a[0] * b[1] - b[0] * a[1];
    if (inside_domain)
      within_domain(vertices.get(i), key + ".vertices", "entry " + std::to_string(i) + ": ");
  }
  if (twice_area == 0.0) errors_.fail(&vertices, key + ".vertices", "polygon has zero area");
}

void ShapeChecker::faces(const toml::table& shape, const std::string& key) const {
  const toml::array& faces = *shape.get_as<toml::array>("open_faces");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const std::string face = faces.get(i)->value<std::string>().value_or("");
    if (face[0] == 'z' && dimension_ < 3)
      errors_.fail(faces.get(i), key + ".open_faces",
                   "face '" + face +
                       "' needs a z axis (run.dimension = " + std::to_string(dimension_) + ")");
    for (std::size_t j = 0; j < i; ++j)
      if (faces.get(j)->value<std::string>() == face)
        errors_.fail(faces.get(i), key + ".open_faces", "face '" + face + "' is listed twice");
  }
}

void check_scene_consistency(const toml::table& root, int dimension, const ErrorContext& errors) {
  if (std::none_of(kPhaseNames.begin(), kPhaseNames.end(),
                   [&](const char* phase) { return has_phase(root, phase); }))
    errors.fail(nullptr, "water", "the scene has no phase; add a [water] or a [soil] table");
  const toml::table& domain = *root.get_as<toml::table>("domain");
  const ShapeChecker shapes(errors, dimension, domain);
  shapes.ordered(domain.get("min"), domain.get("max"), "domain.max", "domain.min");
  if (const toml::array* blocks = root["water"]["blocks"].as_array())
    for (std::size_t i = 0; i < blocks->size(); ++i)
      shapes.check(*blocks->get(i)->as_table(), "water.blocks[" + std::to_string(i) + "]", true);
  if (const toml::table* water = root.get_as<toml::table>("water"))
    check_flow_zones(*water, shapes, errors);
  check_reservoirs(root, shapes, errors);
  if (const toml::table* soil = root.get_as<toml::table>("soil"))
    check_soil_consistency(*soil, shapes, errors);
  if (const toml::array* walls = root.get_as<toml::array>("walls"))
    for (std::size_t i = 0; i < walls->size(); ++i) {
      const std::string key = "walls[" + std::to_string(i) + "]";
      shapes.check(*walls->get(i)->as_table(), key, false);
      check_wall_phases(root, *walls->get(i)->as_table(), key, errors);
      check_wall_motion(root, *walls->get(i)->as_table(), key, dimension, errors);
    }
  check_observables(root, dimension, shapes, errors);
  check_load_forces(root, errors);
}

}  // namespace porosph::scene
