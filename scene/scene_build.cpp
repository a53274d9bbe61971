// The typed Scene read from a validated, default-filled table (the soil phase: scene_soil.cpp).
#include <algorithm>
#include <cmath>

#include "scene/scene_internal.h"

namespace porosph::scene {

std::vector<double> vector_of(const toml::node* node) {
  std::vector<double> out;
  if (const toml::array* array = node ? node->as_array() : nullptr)
    for (const auto& component : *array) out.push_back(component.value<double>().value_or(0.0));
  return out;
}

std::vector<std::string> strings_of(const toml::node* node) {
  std::vector<std::string> out;
  if (const toml::array* array = node ? node->as_array() : nullptr)
    for (const auto& entry : *array) out.push_back(entry.value<std::string>().value_or(""));
  return out;
}

std::string text_of(const toml::table& table, const std::string& name) {
  return table[name].value<std::string>().value_or("");
}

Shape shape_of(const toml::table& table) {
  Shape shape;
  shape.source_line = static_cast<int>(table.source().begin.line);
  const std::string kind = text_of(table, "shape");
  shape.kind = kind == "polygon"     ? Shape::Kind::Polygon
               : kind == "container" ? Shape::Kind::Container
                                     : Shape::Kind::Box;
  shape.min = vector_of(table.get("min"));
  shape.max = vector_of(table.get("max"));
  if (const toml::array* vertices = table.get_as<toml::array>("vertices"))
    for (const auto& vertex : *vertices) shape.vertices.push_back(vector_of(&vertex));
  shape.layers = static_cast<int>(table["layers"].value<int64_t>().value_or(shape.layers));
  shape.open_faces = strings_of(table.get("open_faces"));
  shape.label = text_of(table, "label");
  shape.remove_at = table["remove_at"].value<double>().value_or(shape.remove_at);
  shape.phases = strings_of(table.get("phases"));
  shape.condition = table["condition"].value<std::string>().value_or(shape.condition);
  shape.material = text_of(table, "material");
  shape.moves_with = text_of(table, "moves_with");
  shape.move_direction = vector_of(table.get("move_direction"));
  double norm = 0.0;
  for (double c : shape.move_direction) norm += c * c;
  if (norm > 0.0)
    for (double& c : shape.move_direction) c /= std::sqrt(norm);
  return shape;
}

std::vector<Shape> shapes_of(const toml::array* array) {
  std::vector<Shape> shapes;
  if (array)
    for (const auto& element : *array) shapes.push_back(shape_of(*element.as_table()));
  return shapes;
}

Scene build_scene(const toml::table& root) {
  Scene scene;
  scene.name = text_of(*root["scene"].as_table(), "name");
  scene.description = text_of(*root["scene"].as_table(), "description");

  const toml::table& run = *root["run"].as_table();
  RunSettings& r = scene.run;
  r.dimension = static_cast<int>(*run["dimension"].value<int64_t>());
  r.end_time = *run["end_time"].value<double>();
  r.max_steps = static_cast<long>(*run["max_steps"].value<int64_t>());
  r.output_interval = *run["output_interval"].value<double>();
  r.timeseries_interval = run["timeseries_interval"].value<double>().value_or(0.0);
  r.dp = *run["dp"].value<double>();
  r.h_factor = *run["h_factor"].value<double>();
  r.dt0 = *run["dt0"].value<double>();
  r.cfl = *run["cfl"].value<double>();
  r.c_a = *run["c_a"].value<double>();
  r.viscous_coefficient = *run["viscous_coefficient"].value<double>();
  r.dt_smoothing = *run["dt_smoothing"].value<bool>();
  r.euler_every = static_cast<int>(*run["euler_every"].value<int64_t>());
  r.solver_timeout = *run["solver_timeout"].value<double>();
  r.checkpoint_interval = *run["checkpoint_interval"].value<double>();
  r.checkpoint_wall_minutes = *run["checkpoint_wall_minutes"].value<double>();
  r.gravity = vector_of(run.get("gravity"));
  for (const auto& axis : *run["periodic"].as_array()) r.periodic.push_back(*axis.value<bool>());
  r.kernel = text_of(run, "kernel");
  r.kernel_gradient = text_of(run, "kernel_gradient");

  scene.domain.min = vector_of(root["domain"]["min"].node());
  scene.domain.max = vector_of(root["domain"]["max"].node());

  if (const toml::table* water = root.get_as<toml::table>("water")) {
    WaterPhase w;
    w.rho0 = *(*water)["rho0"].value<double>();
    w.sound_speed = *(*water)["sound_speed"].value<double>();
    w.viscosity = *(*water)["viscosity"].value<double>();
    w.laminar_viscosity = text_of(*water, "laminar_viscosity");
    w.alpha = *(*water)["alpha"].value<double>();
    w.beta = *(*water)["beta"].value<double>();
    w.gamma = *(*water)["gamma"].value<double>();
    w.density_filter_every = static_cast<int>(*(*water)["density_filter_every"].value<int64_t>());
    w.density_diffusion = *(*water)["density_diffusion"].value<double>();
    w.density_diffusion_correction = text_of(*water, "density_diffusion_correction");
    w.artificial_viscosity_in_soil = text_of(*water, "artificial_viscosity_in_soil");
    w.pressure_gradient_in_soil = text_of(*water, "pressure_gradient_in_soil");
    w.particle_shifting = *(*water)["particle_shifting"].value<double>();
    w.hydrostatic_initial = *(*water)["hydrostatic_initial"].value<bool>();
    w.thin_walls = text_of(*water, "thin_walls");
    w.artificial_viscosity_at_walls = text_of(*water, "artificial_viscosity_at_walls");
    w.initial_velocity = text_of(*water, "initial_velocity");
    w.taylor_green_speed = (*water)["taylor_green_speed"].value<double>().value_or(0.0);
    w.taylor_green_wavelength = (*water)["taylor_green_wavelength"].value<double>().value_or(0.0);
    w.wall_condition = text_of(*water, "wall_condition");
    w.solver = text_of(*water, "solver");
    w.blocks = shapes_of(water->get_as<toml::array>("blocks"));
    build_flow_zones(*water, w);
    scene.water = std::move(w);
  }
  if (const toml::table* soil = root.get_as<toml::table>("soil"))
    scene.soil = build_soil_phase(*soil);
  scene.walls = shapes_of(root.get_as<toml::array>("walls"));
  scene.coupling = build_coupling(root);

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
      o.field = text_of(table, "field");
      o.load = text_of(table, "load");
      o.wall = text_of(table, "wall");
      o.region_min = vector_of(table.get("region_min"));
      o.region_max = vector_of(table.get("region_max"));
      scene.observables.push_back(std::move(o));
    }
  }
  return scene;
}

std::vector<std::string> Scene::phases() const {
  std::vector<std::string> present;
  for (const std::string phase : kPhaseNames)
    if ((phase == "water" && has_water()) || (phase == "soil" && has_soil()))
      present.push_back(phase);
  return present;
}

std::vector<Shape> Scene::walls_acting_on(const std::string& phase) const {
  std::vector<Shape> acting;
  for (const Shape& w : walls) {
    if (w.phases.empty() || std::find(w.phases.begin(), w.phases.end(), phase) != w.phases.end())
      acting.push_back(w);
  }
  return acting;
}

}  // namespace porosph::scene
