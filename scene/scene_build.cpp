// Relations between scene keys the schema cannot express, and the typed Scene read from a
// validated, default-filled table.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "scene/scene_internal.h"

namespace porosph::scene {
namespace {

/// Shapes may touch the domain faces up to round-off in the scene numbers.
constexpr double kDomainTolerance = 1e-9;

/// Phases, in the fixed order Scene::phases() reports them; each is a top-level table.
constexpr std::array<const char*, 1> kPhases = {"water"};

std::vector<double> vector_of(const toml::node* node) {
  std::vector<double> out;
  if (const toml::array* array = node ? node->as_array() : nullptr)
    for (const auto& component : *array) out.push_back(component.value<double>().value_or(0.0));
  return out;
}

std::string text_of(const toml::table& table, const std::string& name) {
  return table[name].value<std::string>().value_or("");
}

const char* axis_name(std::size_t axis) { return axis == 0 ? "x" : (axis == 1 ? "y" : "z"); }

/// Relations inside one shape table (`key` is its concrete path, e.g. "walls[2]").
class ShapeChecker {
 public:
  ShapeChecker(const ErrorContext& errors, int dimension, const toml::table& domain)
      : errors_(errors), dimension_(dimension), domain_(domain) {}

  void check(const toml::table& shape, const std::string& key, bool inside_domain) const {
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

  /// max > min in every component, else an error at max.
  void ordered(const toml::node* min, const toml::node* max, const std::string& max_key,
               const std::string& min_key) const {
    const auto lo = vector_of(min);
    const auto hi = vector_of(max);
    for (std::size_t i = 0; i < lo.size(); ++i)
      if (!(hi[i] > lo[i]))
        errors_.fail(max, max_key,
                     "must be greater than " + min_key + " in every component; " + axis_name(i) +
                         ": " + format_number(hi[i]) + " <= " + format_number(lo[i]));
  }

 private:
  void within_domain(const toml::node* node, const std::string& key,
                     const std::string& where = "") const {
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

  void polygon(const toml::table& shape, const std::string& key, bool inside_domain) const {
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

  void faces(const toml::table& shape, const std::string& key) const {
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

  const ErrorContext& errors_;
  int dimension_;
  const toml::table& domain_;
};

void check_observables(const toml::table& root, const ErrorContext& errors) {
  const toml::array* observables = root.get_as<toml::array>("observables");
  if (!observables) return;
  std::map<std::string, std::size_t> first_index;
  for (std::size_t i = 0; i < observables->size(); ++i) {
    const toml::table& observable = *observables->get(i)->as_table();
    const std::string key = "observables[" + std::to_string(i) + "]";
    const std::string name = text_of(observable, "name");
    if (const auto [it, inserted] = first_index.emplace(name, i); !inserted)
      errors.fail(observable.get("name"), key + ".name",
                  "duplicate observable name '" + name + "' (also observables[" +
                      std::to_string(it->second) + "])");
    const std::string phase = text_of(observable, "phase");
    if (!root.contains(phase))
      errors.fail(observable.get("phase"), key + ".phase",
                  "phase '" + phase + "' is not in the scene (it has no [" + phase + "] table)");
    if (const toml::node* direction = observable.get("direction")) {
      const auto d = vector_of(direction);
      if (std::all_of(d.begin(), d.end(), [](double c) { return c == 0.0; }))
        errors.fail(direction, key + ".direction", "must not be the zero vector");
    }
  }
}

Shape shape_of(const toml::table& table) {
  Shape shape;
  const std::string kind = text_of(table, "shape");
  shape.kind = kind == "polygon"     ? Shape::Kind::Polygon
               : kind == "container" ? Shape::Kind::Container
                                     : Shape::Kind::Box;
  shape.min = vector_of(table.get("min"));
  shape.max = vector_of(table.get("max"));
  if (const toml::array* vertices = table.get_as<toml::array>("vertices"))
    for (const auto& vertex : *vertices) shape.vertices.push_back(vector_of(&vertex));
  shape.layers = static_cast<int>(table["layers"].value<int64_t>().value_or(shape.layers));
  if (const toml::array* faces = table.get_as<toml::array>("open_faces"))
    for (const auto& face : *faces)
      shape.open_faces.push_back(face.value<std::string>().value_or(""));
  shape.label = text_of(table, "label");
  shape.remove_at = table["remove_at"].value<double>().value_or(shape.remove_at);
  return shape;
}

std::vector<Shape> shapes_of(const toml::array* array) {
  std::vector<Shape> shapes;
  if (array)
    for (const auto& element : *array) shapes.push_back(shape_of(*element.as_table()));
  return shapes;
}

}  // namespace

void check_scene_consistency(const toml::table& root, int dimension, const ErrorContext& errors) {
  if (std::none_of(kPhases.begin(), kPhases.end(),
                   [&](const char* phase) { return root.contains(phase); }))
    errors.fail(nullptr, "water", "the scene has no phase; add a [water] table");
  const toml::table& domain = *root.get_as<toml::table>("domain");
  const ShapeChecker shapes(errors, dimension, domain);
  shapes.ordered(domain.get("min"), domain.get("max"), "domain.max", "domain.min");
  if (const toml::array* blocks = root["water"]["blocks"].as_array())
    for (std::size_t i = 0; i < blocks->size(); ++i)
      shapes.check(*blocks->get(i)->as_table(), "water.blocks[" + std::to_string(i) + "]", true);
  if (const toml::array* walls = root.get_as<toml::array>("walls"))
    for (std::size_t i = 0; i < walls->size(); ++i)
      shapes.check(*walls->get(i)->as_table(), "walls[" + std::to_string(i) + "]", false);
  check_observables(root, errors);
}

Scene build_scene(const toml::table& root) {
  Scene scene;
  scene.name = text_of(*root["scene"].as_table(), "name");
  scene.description = text_of(*root["scene"].as_table(), "description");

  const toml::table& run = *root["run"].as_table();
  RunSettings& r = scene.run;
  r.dimension = static_cast<int>(*run["dimension"].value<int64_t>());
  r.end_time = *run["end_time"].value<double>();
  r.output_interval = *run["output_interval"].value<double>();
  r.dp = *run["dp"].value<double>();
  r.h_factor = *run["h_factor"].value<double>();
  r.dt0 = *run["dt0"].value<double>();
  r.cfl = *run["cfl"].value<double>();
  r.c_a = *run["c_a"].value<double>();
  r.viscous_coefficient = *run["viscous_coefficient"].value<double>();
  r.dt_smoothing = *run["dt_smoothing"].value<bool>();
  r.euler_every = static_cast<int>(*run["euler_every"].value<int64_t>());
  r.solver_timeout = *run["solver_timeout"].value<double>();
  r.gravity = vector_of(run.get("gravity"));
  for (const auto& axis : *run["periodic"].as_array()) r.periodic.push_back(*axis.value<bool>());
  r.kernel = text_of(run, "kernel");

  scene.domain.min = vector_of(root["domain"]["min"].node());
  scene.domain.max = vector_of(root["domain"]["max"].node());

  if (const toml::table* water = root.get_as<toml::table>("water")) {
    WaterPhase w;
    w.rho0 = *(*water)["rho0"].value<double>();
    w.sound_speed = *(*water)["sound_speed"].value<double>();
    w.viscosity = *(*water)["viscosity"].value<double>();
    w.alpha = *(*water)["alpha"].value<double>();
    w.beta = *(*water)["beta"].value<double>();
    w.gamma = *(*water)["gamma"].value<double>();
    w.density_filter_every = static_cast<int>(*(*water)["density_filter_every"].value<int64_t>());
    w.hydrostatic_initial = *(*water)["hydrostatic_initial"].value<bool>();
    w.wall_condition = text_of(*water, "wall_condition");
    w.solver = text_of(*water, "solver");
    w.blocks = shapes_of(water->get_as<toml::array>("blocks"));
    scene.water = std::move(w);
  }
  scene.walls = shapes_of(root.get_as<toml::array>("walls"));

  if (const toml::array* observables = root.get_as<toml::array>("observables")) {
    for (const auto& element : *observables) {
      const toml::table& table = *element.as_table();
      Observable o;
      o.name = text_of(table, "name");
      o.kind = text_of(table, "kind");
      o.phase = text_of(table, "phase");
      o.direction = vector_of(table.get("direction"));
      double norm = 0.0;
      for (double c : o.direction) norm += c * c;
      for (double& c : o.direction) c /= std::sqrt(norm);
      o.origin = vector_of(table.get("origin"));
      o.point = vector_of(table.get("point"));
      scene.observables.push_back(std::move(o));
    }
  }
  return scene;
}

std::vector<std::string> Scene::phases() const {
  std::vector<std::string> present;
  for (const std::string phase : kPhases)
    if (phase == "water" && has_water()) present.push_back(phase);
  return present;
}

}  // namespace porosph::scene
