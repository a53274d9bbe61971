// The schema of the tables every phase shares: [[walls]] and [[observables]].
#include "scene/scene_schema_builder.h"

namespace porosph::scene::schema_detail {
namespace {

void add_walls(SceneSchema& s) {
  s.tables.push_back({"walls[]", true, false,
                      "Fixed wall particles, shared by every phase present unless `phases` says "
                      "otherwise. Walls may extend outside the domain."});
  s.keys.push_back(
      Key("walls[].shape", T::String)
          .required()
          .one_of({"box", "polygon", "container"})
          .doc("box / polygon: a filled region; container: a wall of `layers` particle "
               "layers around the inner box [min, max]."));
  s.keys.push_back(Key("walls[].min", T::Vector)
                       .unit("m")
                       .required()
                       .only_when("shape", {"box", "container"})
                       .doc("Lower corner of the box (container: of the inner box)."));
  s.keys.push_back(Key("walls[].max", T::Vector)
                       .unit("m")
                       .required()
                       .only_when("shape", {"box", "container"})
                       .doc("Upper corner of the box (container: of the inner box); greater than "
                            "min in every component."));
  s.keys.push_back(Key("walls[].vertices", T::VectorList)
                       .unit("m")
                       .required()
                       .vector_length(2)
                       .min_count(3)
                       .only_when("shape", {"polygon"})
                       .doc("Polygon corners [[x, y], ...] (2D only), closed implicitly."));
  s.keys.push_back(Key("walls[].layers", T::Int)
                       .fallback("3")
                       .at_least(1)
                       .only_when("shape", {"container"})
                       .doc("Wall thickness in particle layers."));
  s.keys.push_back(Key("walls[].open_faces", T::StringList)
                       .fallback("[]")
                       .one_of({"x-", "x+", "y-", "y+", "z-", "z+"})
                       .only_when("shape", {"container"})
                       .doc("Faces of the container left open (z faces only in 3D)."));
  s.keys.push_back(Key("walls[].label", T::String)
                       .fallback("\"\"")
                       .doc("Optional name shown in errors and output."));
  s.keys.push_back(Key("walls[].remove_at", T::Float)
                       .unit("s")
                       .fallback("-1.0")
                       .doc("Time at which the wall is removed; negative: never."));
  s.keys.push_back(Key("walls[].phases", T::StringList)
                       .derived("every phase present")
                       .one_of({"water", "soil"})
                       .min_count(1)
                       .doc("Phases the wall acts on; each must be present in the scene, none "
                            "listed twice. A wall left out for a phase does not exist for it."));
  s.keys.push_back(Key("walls[].condition", T::String)
                       .fallback("\"default\"")
                       .one_of({"default", "no_slip", "free_slip"})
                       .doc("Velocity condition at this wall; default: the `wall_condition` of "
                            "each phase it acts on."));
  s.keys.push_back(Key("walls[].moves_with", T::String)
                       .fallback("\"\"")
                       .doc("Name of an observable whose value, at the latest state, is this "
                            "wall's speed along move_direction [m/s]: the wall moves as one body "
                            "(e.g. the lid that keeps the pore water under a rigid plate, an "
                            "observable of kind load_velocity). Water walls only (phases = "
                            "[\"water\"]). Empty: the wall is fixed."));
  s.keys.push_back(Key("walls[].move_direction", T::Vector)
                       .optional()
                       .doc("Direction the wall moves along (normalised by the loader); "
                            "required with moves_with, non-zero."));
}

void add_observables(SceneSchema& s) {
  s.tables.push_back({"observables[]", true, false,
                      "Quantities measured on one phase at every output time and at the end "
                      "(columns of timeseries.csv, values in run.json)."});
  s.keys.push_back(Key("observables[].name", T::String)
                       .required()
                       .format(StringFormat::Identifier)
                       .doc("Column name in timeseries.csv; unique among observables."));
  s.keys.push_back(
      Key("observables[].kind", T::String)
          .required()
          .one_of({"front_position", "max_speed", "pressure_at", "kinetic_energy", "max_height",
                   "particle_count", "mean_field", "max_displacement", "load_velocity",
                   "wall_force"})
          .doc("What is measured over the phase's particles (those inside the region, if one is "
               "given): front_position and max_height, the largest dot(x - origin, direction); "
               "max_speed, the largest speed; pressure_at, the pressure interpolated at point; "
               "kinetic_energy, the total kinetic energy; particle_count, the number of "
               "particles; mean_field, the arithmetic mean of `field`; max_displacement, the "
               "largest distance of a particle from its position at t = 0; load_velocity, the "
               "mean velocity of a soil load's particles along its traction (the speed of a "
               "rigid plate; NaN from a soil solver without loads); wall_force, the force the "
               "water's pressure puts on a moving wall, along `direction` [N/m in 2D]."));
  s.keys.push_back(Key("observables[].phase", T::String)
                       .derived("`\"water\"` if the scene has water, else `\"soil\"`")
                       .one_of({"water", "soil"})
                       .doc("Phase measured; must be present in the scene."));
  s.keys.push_back(Key("observables[].direction", T::Vector)
                       .required()
                       .only_when("kind", {"front_position", "max_height", "wall_force"})
                       .doc("Direction of measurement; non-zero, normalised by the loader."));
  s.keys.push_back(Key("observables[].origin", T::Vector)
                       .unit("m")
                       .fallback_per_dimension("[0.0, 0.0]", "[0.0, 0.0, 0.0]")
                       .only_when("kind", {"front_position", "max_height"})
                       .doc("Point the distance is measured from."));
  s.keys.push_back(Key("observables[].point", T::Vector)
                       .unit("m")
                       .required()
                       .only_when("kind", {"pressure_at"})
                       .doc("Probe point."));
  s.keys.push_back(Key("observables[].field", T::String)
                       .required()
                       .one_of({"density", "mass", "pressure", "porosity", "speed", "velocity_x",
                                "velocity_y", "velocity_z", "stress_xx", "stress_yy", "stress_zz",
                                "stress_xy", "stress_xz", "stress_yz"})
                       .only_when("kind", {"mean_field"})
                       .doc("Particle field averaged (mass: kg/m in 2D, kg in 3D). pressure: water "
                            "only; porosity and stress_* (Pa, "
                            "tension positive): soil only; velocity_z: 3D only."));
  s.keys.push_back(Key("observables[].load", T::String)
                       .required()
                       .only_when("kind", {"load_velocity"})
                       .doc("Label of the [[soil.loads]] entry measured."));
  s.keys.push_back(Key("observables[].wall", T::String)
                       .required()
                       .only_when("kind", {"wall_force"})
                       .doc("Label of the moving wall (walls[].moves_with) measured."));
  const std::vector<std::string> regional = {"front_position",  "max_speed",      "kinetic_energy",
                                             "max_height",      "particle_count", "mean_field",
                                             "max_displacement"};
  s.keys.push_back(Key("observables[].region_min", T::Vector)
                       .unit("m")
                       .optional()
                       .only_when("kind", regional)
                       .doc("Lower corner of the box the measurement is restricted to; give "
                            "region_min and region_max together or neither (all particles)."));
  s.keys.push_back(Key("observables[].region_max", T::Vector)
                       .unit("m")
                       .optional()
                       .only_when("kind", regional)
                       .doc("Upper corner of that box; greater than region_min in every "
                            "component."));
}

}  // namespace

void add_walls_and_observables(SceneSchema& s) {
  add_walls(s);
  add_observables(s);
}

void add_zone_box_keys(SceneSchema& s, const std::string& table) {
  s.keys.push_back(Key(table + ".min", T::Vector).unit("m").required().doc("Lower corner."));
  s.keys.push_back(Key(table + ".max", T::Vector)
                       .unit("m")
                       .required()
                       .doc("Upper corner; greater than min in every component."));
}

void add_filled_region_keys(SceneSchema& s, const std::string& table) {
  s.keys.push_back(Key(table + ".shape", T::String)
                       .required()
                       .one_of({"box", "polygon"})
                       .doc("Kind of region."));
  s.keys.push_back(Key(table + ".min", T::Vector)
                       .unit("m")
                       .required()
                       .only_when("shape", {"box"})
                       .doc("Lower corner of the box."));
  s.keys.push_back(Key(table + ".max", T::Vector)
                       .unit("m")
                       .required()
                       .only_when("shape", {"box"})
                       .doc("Upper corner of the box; greater than min in every component."));
  s.keys.push_back(Key(table + ".vertices", T::VectorList)
                       .unit("m")
                       .required()
                       .vector_length(2)
                       .min_count(3)
                       .only_when("shape", {"polygon"})
                       .doc("Polygon corners [[x, y], ...] (2D only), closed implicitly."));
}

}  // namespace porosph::scene::schema_detail
