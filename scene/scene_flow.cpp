// Water inflow / outflow zones and reservoirs ([[water.inflow]], [[water.outflow]],
// [[water.reservoir]]) and the soil-water coupling settings ([coupling]): their schema, the
// relations between their keys, and their typed form.
#include <cmath>

#include "scene/scene_internal.h"
#include "scene/scene_schema_builder.h"

namespace porosph::scene {
namespace schema_detail {

void add_flow_zones(SceneSchema& s) {
  s.tables.push_back({"water.inflow[]", true, false,
                      "Inflow zones: a box whose water particles move with a prescribed velocity "
                      "along `direction`; a particle leaving the box downstream becomes free and a "
                      "new one enters at its upstream end. The box must be at least the kernel "
                      "support 2h long along `direction` (the water leaving it needs a full "
                      "kernel of zone particles behind it). Give `velocity`, or `flow_rate` with "
                      "`cross_section`."});
  add_zone_box_keys(s, "water.inflow[]");
  s.keys.push_back(Key("water.inflow[].direction", T::Vector)
                       .required()
                       .doc("Flow direction (normalised by the loader); the zone's upstream end is "
                            "its face against this direction. Must be along an axis."));
  s.keys.push_back(Key("water.inflow[].velocity", T::Float)
                       .unit("m/s")
                       .optional()
                       .above(0)
                       .doc("Prescribed speed once ramped up."));
  s.keys.push_back(Key("water.inflow[].flow_rate", T::Float)
                       .unit("m^3/s")
                       .optional()
                       .above(0)
                       .doc("Prescribed flow rate once ramped up; speed = flow_rate / "
                            "cross_section (the superficial velocity of a 2D model of a 3D rig). "
                            "The box must be a whole number of run.dp rows across the flow, or "
                            "its particles would carry another discharge (refused)."));
  s.keys.push_back(Key("water.inflow[].cross_section", T::Float)
                       .unit("m^2")
                       .optional()
                       .above(0)
                       .doc("Area that turns flow_rate into a speed; with flow_rate."));
  s.keys.push_back(Key("water.inflow[].start_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("Time at which the ramp starts (before it: speed 0)."));
  s.keys.push_back(Key("water.inflow[].ramp_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("The speed grows linearly from 0 to its full value over this time; "
                            "0: a step."));

  s.tables.push_back({"water.outflow[]", true, false,
                      "Outflow zones: water particles entering the box are removed (counted in "
                      "run.json and timeseries.csv as removed)."});
  add_zone_box_keys(s, "water.outflow[]");
  s.keys.push_back(Key("water.outflow[].start_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("The zone removes water from this time on (e.g. the sudden removal "
                            "of a water surcharge)."));
  s.keys.push_back(
      Key("water.outflow[].stagger", T::Float)
          .fallback("0.0")
          .at_least(0)
          .doc("Spreads the removal of water rising into the box through its lower face (along "
               "gravity) over this many particle spacings: a particle is removed once its centre "
               "lies in the box and at least s stagger dp above that face, s in [0, 1) a fixed "
               "fraction of its id (the golden-ratio sequence). A water surface rising through "
               "the face as one lattice row then leaves one particle at a time instead of all at "
               "once; a whole row at once drops the head of the water below by rho g dp in one "
               "step, and that pressure step crosses the domain as a pulse "
               "(docs/validation-studies.md, fluidized_bed). 0: at the face. Needs gravity along "
               "one axis when > 0."));

  s.tables.push_back(
      {"water.reservoir[]", true, false,
       "Constant-head reservoirs (a dam's reservoir, a river, a pit kept dry by pumping): a box in "
       "which the water surface is held at `level`. After every step, free water particles in "
       "the box whose centres lie above the level are removed (booked as outflow), and in each "
       "lattice column of the box (spacing dp across gravity, from its min) whose highest water "
       "particle lies more than dp below the level a particle is added at the column's centre dp "
       "above it (booked as inflow; with that particle's velocity, the hydrostatic density for "
       "p(level - height) of still water through the inverse of eq. 4, mass rho dp^D; in an empty "
       "column "
       "at the box's bottom + dp/2, at rest), unless another particle lies within 0.5 dp or the "
       "particles around fill more than 0.45 of its kernel volume (it would lie inside the "
       "water). So the particle tops stay between level - dp and level: the surface (tops + "
       "dp/2) within half a spacing of the level. The box should reach down into the water and "
       "up above the level (fluid_solver/reservoirs.h)."});
  add_zone_box_keys(s, "water.reservoir[]");
  s.keys.push_back(Key("water.reservoir[].level", T::Float)
                       .unit("m")
                       .required()
                       .doc("Coordinate, along the axis gravity acts along, of the water surface "
                            "to hold (gravity must be along one axis); inside the box along that "
                            "axis."));
  s.keys.push_back(Key("water.reservoir[].start_time", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("The zone holds the level from this time on."));
  s.keys.push_back(
      Key("water.reservoir[].boundary", T::String)
          .fallback("\"surface\"")
          .one_of({"surface", "open"})
          .doc("\"surface\": the level is held by adding and removing particles at the surface "
               "(above). \"open\": the box is a buffer beyond the domain's open side (no wall "
               "there), filled with water at the hydrostatic pressure of the level, through "
               "which water enters and leaves the pool (Tafuni et al. 2018): its particles carry "
               "p = rho0 g (level - height) (the weakly compressible still-water pressure, "
               "inverse eq. 4 for the density) and move along `direction` with the mean normal "
               "velocity of the water within 2h of the face, per dp-high row; a buffer particle "
               "crossing the face becomes water and is replaced one buffer length behind "
               "(booked as inflow); water crossing into the buffer below the level becomes "
               "buffer, above it is removed, and buffer leaving at the far face is removed "
               "(booked as outflow). Nothing is added or removed at the pool's surface, so the "
               "pool is not stirred. Needs `direction`; the box must be at least 2h thick along "
               "it; start_time must be 0 (fluid_solver/open_reservoirs.h)."));
  s.keys.push_back(
      Key("water.reservoir[].absorbing", T::Bool)
          .fallback("false")
          .doc("For boundary = \"open\": a radiation condition of Flather (1976) type for long "
               "waves. The buffer's pressure is that of the level less (H / sqrt(g H)) u, H the "
               "level's depth above the box's bottom and u the depth-mean velocity into the "
               "domain of the water within 2h of the face, so that a wave arriving at the face "
               "leaves instead of reflecting (a pool between a wall and a fixed level rings as a "
               "quarter-wave seiche that nothing damps). A steady flow u through the face then "
               "holds the pool H u / sqrt(g H) below the level where water enters (above it where "
               "it leaves), as a long channel to the reservoir would (fluid_solver/"
               "open_reservoirs.h)."));
  s.keys.push_back(Key("water.reservoir[].direction", T::Vector)
                       .optional()
                       .doc("For boundary = \"open\": unit vector along one axis across gravity, "
                            "from the buffer into the domain (the box's face along it is the "
                            "open side)."));
}

void add_coupling(SceneSchema& s) {
  s.tables.push_back({"coupling", false, false,
                      "Soil-water interaction settings (used when the scene has both phases)."});
  s.keys.push_back(Key("coupling.submerged_saturation", T::Float)
                       .fallback("0.8")
                       .above(0)
                       .at_most(1)
                       .doc("A soil particle whose kernel-weighted water volume fraction "
                            "sum_a V_a W_ia reaches this value is submerged: its weight and the "
                            "seepage term use the submerged density (saturated - water); below it "
                            "the particle keeps its total unit weight."));
  s.keys.push_back(
      Key("coupling.implicit_drag", T::Bool)
          .fallback("true")
          .doc("Take the seepage drag implicitly, pair by pair: each soil-water pair's force at "
               "the end of the step, linearised (docs/coupling.md); stable and exactly "
               "momentum-conserving whatever the drag's relaxation time; false: the paper's "
               "explicit drag at the start of the step."));
  s.keys.push_back(
      Key("coupling.drag_step", T::String)
          .fallback("\"backward_euler\"")
          .one_of({"backward_euler", "exponential"})
          .doc("How the implicit drag weighs a pair over the step "
               "(coupler/interaction/drag_step_weights.h, docs/coupling.md). backward_euler: the "
               "drag at the predicted relative velocity over 1 + lambda dt, first order in dt; "
               "exponential: the exact mean of the linearised pair over the step, f(v^n) phi + "
               "(f(v*) - f(v^n)) psi, second order; both keep a steady state exactly and are "
               "stable whatever lambda dt."));
  s.keys.push_back(
      Key("coupling.drag_at_walls", T::String)
          .fallback("\"renormalised\"")
          .one_of({"truncated", "renormalised"})
          .doc("The soil sums of a water particle in soil beside a wall (drag, its rate, "
               "porosity). \"renormalised\" (default since 2026-12-06): divided by 1 - S, S "
               "the share of the particle's kernel support inside walls that hold neither "
               "water nor soil (the walls acting on water, less a wall the soil passes through "
               "where it overlaps a soil block; moving walls left out; "
               "coupler/interaction/wall_kernel_share.h, docs/coupling.md); \"truncated\": "
               "as they are, so the first water row along a wall sees too little soil "
               "(porosity 0.51 for 0.40) and seeps 25-45 % too fast (the model before)."));
  s.keys.push_back(Key("coupling.wet_saturation", T::Float)
                       .fallback("0.1")
                       .above(0)
                       .at_most(1)
                       .doc("A soil particle whose water volume fraction reaches this value is wet "
                            "(materials with wet_cohesion_loss lose their cohesion for good)."));
}

}  // namespace schema_detail

void check_flow_zones(const toml::table& water, const ShapeChecker& shapes,
                      const ErrorContext& errors) {
  if (const toml::array* inflows = water.get_as<toml::array>("inflow")) {
    for (std::size_t i = 0; i < inflows->size(); ++i) {
      const toml::table& zone = *inflows->get(i)->as_table();
      const std::string key = "water.inflow[" + std::to_string(i) + "]";
      shapes.ordered(zone.get("min"), zone.get("max"), key + ".max", key + ".min");
      const bool velocity = zone.contains("velocity");
      const bool flow_rate = zone.contains("flow_rate");
      const bool section = zone.contains("cross_section");
      if (velocity == flow_rate)
        errors.fail(&zone, key, "give either velocity or flow_rate (with cross_section)");
      if (flow_rate != section)
        errors.fail(zone.get(flow_rate ? "flow_rate" : "cross_section"),
                    key + (flow_rate ? ".flow_rate" : ".cross_section"),
                    "flow_rate and cross_section go together");
      const std::vector<double> d = vector_of(zone.get("direction"));
      int nonzero = 0;
      for (double c : d) nonzero += c != 0.0;
      if (nonzero != 1)
        errors.fail(zone.get("direction"), key + ".direction",
                    "must point along one axis, e.g. [0.0, 1.0]");
    }
  }
  if (const toml::array* outflows = water.get_as<toml::array>("outflow")) {
    for (std::size_t i = 0; i < outflows->size(); ++i) {
      const toml::table& zone = *outflows->get(i)->as_table();
      const std::string key = "water.outflow[" + std::to_string(i) + "]";
      shapes.ordered(zone.get("min"), zone.get("max"), key + ".max", key + ".min");
    }
  }
}

void check_reservoirs(const toml::table& root, const ShapeChecker& shapes,
                      const ErrorContext& errors) {
  const toml::array* reservoirs = root["water"]["reservoir"].as_array();
  if (!reservoirs) return;
  const std::vector<double> g = vector_of(root["run"]["gravity"].node());
  int nonzero = 0;
  std::size_t axis = 0;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g[k] != 0.0) {
      ++nonzero;
      axis = k;
    }
  for (std::size_t i = 0; i < reservoirs->size(); ++i) {
    const toml::table& zone = *reservoirs->get(i)->as_table();
    const std::string key = "water.reservoir[" + std::to_string(i) + "]";
    shapes.ordered(zone.get("min"), zone.get("max"), key + ".max", key + ".min");
    if (nonzero != 1)
      errors.fail(zone.get("level"), key + ".level",
                  "a reservoir needs run.gravity along one axis, e.g. [0.0, -9.81]");
    const bool open = zone["boundary"].value_or<std::string>("surface") == "open";
    if (open != zone.contains("direction"))
      errors.fail(zone.get(open ? "boundary" : "direction"), key + ".direction",
                  open ? "an open reservoir needs `direction` (into the domain, e.g. [1.0, 0.0])"
                       : "`direction` is for boundary = \"open\" only");
    if (!open && zone["absorbing"].value_or(false))
      errors.fail(zone.get("absorbing"), key + ".absorbing", "is for boundary = \"open\" only");
    if (open && zone["start_time"].value_or(0.0) != 0.0)
      errors.fail(zone.get("start_time"), key + ".start_time",
                  "an open reservoir holds its level from t = 0; leave start_time out");
    if (open && zone.contains("direction")) {
      const std::vector<double> d = vector_of(zone.get("direction"));
      int along = 0;
      std::size_t along_axis = 0;
      for (std::size_t k = 0; k < d.size(); ++k)
        if (d[k] != 0.0) {
          ++along;
          along_axis = k;
        }
      if (along != 1 || (nonzero == 1 && along_axis == axis))
        errors.fail(zone.get("direction"), key + ".direction",
                    "must point along one axis across gravity, e.g. [1.0, 0.0]");
    }
    const double level = *zone["level"].value<double>();
    const double lo = vector_of(zone.get("min"))[axis], hi = vector_of(zone.get("max"))[axis];
    if (!(level > lo && level < hi))
      errors.fail(zone.get("level"), key + ".level",
                  "must lie inside the box along " + std::string(axis_name(axis)) + " (between " +
                      format_number(lo) + " and " + format_number(hi) + "), got " +
                      format_number(level));
  }
}

void build_flow_zones(const toml::table& water, WaterPhase& w) {
  if (const toml::array* reservoirs = water.get_as<toml::array>("reservoir")) {
    for (const auto& element : *reservoirs) {
      const toml::table& t = *element.as_table();
      ReservoirZone z;
      z.min = vector_of(t.get("min"));
      z.max = vector_of(t.get("max"));
      z.level = *t["level"].value<double>();
      z.start_time = *t["start_time"].value<double>();
      z.boundary = *t["boundary"].value<std::string>();
      if (t.contains("direction")) z.direction = vector_of(t.get("direction"));
      z.absorbing = *t["absorbing"].value<bool>();
      w.reservoirs.push_back(std::move(z));
    }
  }
  if (const toml::array* inflows = water.get_as<toml::array>("inflow")) {
    for (const auto& element : *inflows) {
      const toml::table& t = *element.as_table();
      InflowZone z;
      z.min = vector_of(t.get("min"));
      z.max = vector_of(t.get("max"));
      z.direction = vector_of(t.get("direction"));
      double norm = 0.0;
      for (double c : z.direction) norm += c * c;
      for (double& c : z.direction) c /= std::sqrt(norm);
      if (const auto v = t["velocity"].value<double>()) {
        z.speed = *v;
      } else {
        z.speed = *t["flow_rate"].value<double>() / *t["cross_section"].value<double>();
      }
      z.start_time = *t["start_time"].value<double>();
      z.ramp_time = *t["ramp_time"].value<double>();
      w.inflows.push_back(std::move(z));
    }
  }
  if (const toml::array* outflows = water.get_as<toml::array>("outflow")) {
    for (const auto& element : *outflows) {
      const toml::table& t = *element.as_table();
      OutflowZone z;
      z.min = vector_of(t.get("min"));
      z.max = vector_of(t.get("max"));
      z.start_time = *t["start_time"].value<double>();
      z.stagger = *t["stagger"].value<double>();
      w.outflows.push_back(std::move(z));
    }
  }
}

CouplingSettings build_coupling(const toml::table& root) {
  CouplingSettings c;
  if (const toml::table* t = root.get_as<toml::table>("coupling")) {
    c.submerged_saturation = *(*t)["submerged_saturation"].value<double>();
    c.wet_saturation = *(*t)["wet_saturation"].value<double>();
    c.implicit_drag = *(*t)["implicit_drag"].value<bool>();
    c.drag_step = *(*t)["drag_step"].value<std::string>();
    c.drag_at_walls = *(*t)["drag_at_walls"].value<std::string>();
  }
  return c;
}

double InflowZone::speed_at(double time) const {
  if (time < start_time) return 0.0;
  if (ramp_time <= 0.0 || time >= start_time + ramp_time) return speed;
  return speed * (time - start_time) / ramp_time;
}

}  // namespace porosph::scene
