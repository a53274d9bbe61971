// Surface loads on the soil ([[soil.loads]]): a traction carried by the soil particles of a region
// (a surcharge, a footing, the piston of an oedometer): its schema, the relations between its keys
// and its typed form.
#include <algorithm>

#include "scene/scene_internal.h"
#include "scene/scene_schema_builder.h"

namespace porosph::scene {
namespace schema_detail {

void add_soil_loads(SceneSchema& s) {
  s.tables.push_back(
      {"soil.loads[]", true, false,
       "Surface loads: a traction on a face of the soil. Of the free soil particles whose "
       "centres lie in the box [min, max] at t = 0, the outermost layer facing the traction "
       "(those within dp / 2 of the farthest one against it: the top row for a downward load) "
       "carries it for good, as it moves. The total force is the traction times the box's extent "
       "across the traction's axis (2D: per unit thickness), shared equally by those "
       "particles."});
  add_zone_box_keys(s, "soil.loads[]");
  s.keys.push_back(Key("soil.loads[].traction", T::Vector)
                       .unit("Pa")
                       .required()
                       .doc("Force per unit area of the loaded face once ramped up, along one "
                            "axis, e.g. [0.0, -1000.0] pushes down with 1 kPa."));
  s.keys.push_back(Key("soil.loads[].start_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("Time at which the load starts (before it: 0)."));
  s.keys.push_back(Key("soil.loads[].ramp_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("The load grows linearly from 0 to the traction over this time; 0: "
                            "a step."));
  s.keys.push_back(Key("soil.loads[].rigid", T::Bool)
                       .fallback("false")
                       .doc("The loaded particles move as one along the traction's axis, free "
                            "across it: a rigid, frictionless plate (Mandel's problem). After "
                            "every kick their velocities along the axis are set to their "
                            "mass-weighted mean (internal forces: momentum is unchanged)."));
  s.keys.push_back(Key("soil.loads[].material", T::String)
                       .fallback("\"\"")
                       .doc("Material the loaded particles take from t = 0, which must have the "
                            "density and porosity of their own (checked at start-up); e.g. an "
                            "impermeable one, so that the pore water cannot leave through the "
                            "plate. Empty: they keep their own."));
  s.keys.push_back(Key("soil.loads[].plus_force_from", T::String)
                       .fallback("\"\"")
                       .doc("Name of an observable whose latest value [N/m in 2D] is added to "
                            "the load's force along the positive direction of its traction's "
                            "axis: the wall_force of the lid that moves with a rigid plate, so "
                            "that lid and plate carry the load as one body. Empty: none."));
  s.keys.push_back(Key("soil.loads[].label", T::String)
                       .fallback("\"\"")
                       .doc("Optional name shown in errors and output."));
}

}  // namespace schema_detail

void check_soil_loads(const toml::table& soil, const std::vector<std::string>& materials,
                      const ShapeChecker& shapes, const ErrorContext& errors) {
  const toml::array* loads = soil.get_as<toml::array>("loads");
  if (!loads) return;
  for (std::size_t i = 0; i < loads->size(); ++i) {
    const toml::table& load = *loads->get(i)->as_table();
    const std::string key = "soil.loads[" + std::to_string(i) + "]";
    shapes.ordered(load.get("min"), load.get("max"), key + ".max", key + ".min");
    int nonzero = 0;
    for (double c : vector_of(load.get("traction"))) nonzero += c != 0.0;
    if (nonzero != 1)
      errors.fail(load.get("traction"), key + ".traction",
                  "must act along one axis and not vanish, e.g. [0.0, -1000.0]");
    const std::string material = text_of(load, "material");
    if (!material.empty() &&
        std::find(materials.begin(), materials.end(), material) == materials.end())
      errors.fail(load.get("material"), key + ".material",
                  "unknown material '" + material + "'" + did_you_mean(material, materials));
  }
}

void build_soil_loads(const toml::table& soil, SoilPhase& p) {
  const toml::array* loads = soil.get_as<toml::array>("loads");
  if (!loads) return;
  for (const auto& element : *loads) {
    const toml::table& t = *element.as_table();
    SoilLoad load;
    load.min = vector_of(t.get("min"));
    load.max = vector_of(t.get("max"));
    load.traction = vector_of(t.get("traction"));
    load.start_time = *t["start_time"].value<double>();
    load.ramp_time = *t["ramp_time"].value<double>();
    load.label = text_of(t, "label");
    load.rigid = *t["rigid"].value<bool>();
    load.material = text_of(t, "material");
    load.plus_force_from = text_of(t, "plus_force_from");
    p.loads.push_back(std::move(load));
  }
}

double SoilLoad::factor_at(double time) const {
  if (time < start_time) return 0.0;
  if (ramp_time <= 0.0 || time >= start_time + ramp_time) return 1.0;
  return (time - start_time) / ramp_time;
}

double SoilLoad::face_extent() const {
  double extent = 1.0;
  for (std::size_t k = 0; k < traction.size(); ++k)
    if (traction[k] == 0.0) extent *= max[k] - min[k];
  return extent;
}

}  // namespace porosph::scene
