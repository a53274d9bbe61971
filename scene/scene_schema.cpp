// The single declaration of every scene table and key: type, unit, default, range, description.
// The loader validates against it and docs/scene.md is rendered from it. This file: [scene], [run],
// [domain], [water] and the schema's look-ups; [soil] is in scene_schema_soil.cpp, [[walls]] and
// [[observables]] in scene_schema_shared.cpp.
#include "scene/scene_schema.h"

#include "scene/scene_schema_builder.h"
#include "scene/term_registry.h"

namespace porosph::scene {
namespace schema_detail {

void add_scene_and_run(SceneSchema& s) {
  s.tables.push_back({"scene", false, true, "Identification of the scene."});
  s.keys.push_back(Key("scene.name", T::String)
                       .required()
                       .format(StringFormat::Name)
                       .doc("Scene name, written to run.json."));
  s.keys.push_back(
      Key("scene.description", T::String).fallback("\"\"").doc("Free text describing the scene."));

  s.tables.push_back(
      {"run", false, true, "Global run settings: dimension, resolution, time stepping, gravity."});
  s.keys.push_back(Key("run.dimension", T::Int)
                       .fallback("2")
                       .at_least(2)
                       .at_most(3)
                       .doc("Spatial dimension (2: plane strain, 3). Every vector has this many "
                            "components."));
  s.keys.push_back(Key("run.end_time", T::Float)
                       .unit("s")
                       .required()
                       .above(0)
                       .doc("Simulated time at which the run ends."));
  s.keys.push_back(Key("run.max_steps", T::Int)
                       .fallback("0")
                       .at_least(0)
                       .doc("The run stops after this many time steps even before end_time "
                            "(benchmarks); 0: no limit."));
  s.keys.push_back(Key("run.output_interval", T::Float)
                       .unit("s")
                       .required()
                       .above(0)
                       .doc("Simulated time between two snapshots (and time-series rows unless "
                            "run.timeseries_interval says otherwise)."));
  s.keys.push_back(
      Key("run.timeseries_interval", T::Float)
          .unit("s")
          .fallback("0.0")
          .at_least(0)
          .doc("Simulated time between two rows of timeseries.csv (every built-in column and "
               "observable at that instant), independent of the snapshots; 0: "
               "run.output_interval, one row per snapshot. A row costs no snapshot, so a "
               "finely sampled history of a long run stays small. The last state always gets "
               "a row."));
  s.keys.push_back(Key("run.dp", T::Float)
                       .unit("m")
                       .required()
                       .above(0)
                       .doc("Particle spacing of the initial lattice."));
  s.keys.push_back(Key("run.h_factor", T::Float)
                       .fallback("1.2")
                       .at_least(1.0)
                       .at_most(3.0)
                       .doc("Smoothing length over particle spacing, h = h_factor dp."));
  s.keys.push_back(Key("run.dt0", T::Float)
                       .unit("s")
                       .required()
                       .above(0)
                       .doc("Initial and largest time step (time-step smoothing, Fig. 1)."));
  s.keys.push_back(Key("run.cfl", T::Float)
                       .fallback("0.2")
                       .above(0)
                       .at_most(1)
                       .doc("C_cfl in dt_cfl = C_cfl h / (c + |v|max)."));
  s.keys.push_back(Key("run.c_a", T::Float)
                       .derived("0.005 when the scene has water and soil (the seed paper's value "
                                "for coupled runs), else 0.25")
                       .above(0)
                       .at_most(1)
                       .doc("C_a in dt_force = C_a min sqrt(h / |a|) (eq. 21), |a| the total "
                            "acceleration, interaction included."));
  s.keys.push_back(Key("run.viscous_coefficient", T::Float)
                       .fallback("0.125")
                       .above(0)
                       .at_most(1)
                       .doc("Coefficient of the viscous limit dt_visc = coefficient h^2 / nu."));
  s.keys.push_back(Key("run.dt_smoothing", T::Bool)
                       .fallback("true")
                       .doc("Smooth time-step changes (Fig. 1); false: dt = min(limits, dt0)."));
  s.keys.push_back(Key("run.euler_every", T::Int)
                       .fallback("40")
                       .at_least(1)
                       .doc("Modified Verlet: one Euler step every this many steps."));
  s.keys.push_back(Key("run.solver_timeout", T::Float)
                       .unit("s")
                       .fallback("60.0")
                       .above(0)
                       .doc("A solver process silent for this long (wall time) fails the run."));
  s.keys.push_back(Key("run.checkpoint_interval", T::Float)
                       .unit("s")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("Simulated time between two checkpoints in OUT/checkpoint (resume with "
                            "`coupler run --resume OUT`, docs/checkpoints.md); 0: none."));
  s.keys.push_back(Key("run.checkpoint_wall_minutes", T::Float)
                       .unit("min")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("Wall time between two checkpoints (docs/checkpoints.md); 0: none."));
  s.keys.push_back(Key("run.gravity", T::Vector)
                       .unit("m/s^2")
                       .fallback_per_dimension("[0.0, -9.81]", "[0.0, 0.0, -9.81]")
                       .doc("Gravitational acceleration."));
  s.keys.push_back(Key("run.periodic", T::BoolVector)
                       .fallback_per_dimension("[false, false]", "[false, false, false]")
                       .doc("Per axis: particles leaving the domain through a face re-enter "
                            "through the opposite face."));
  s.keys.push_back(Key("run.kernel", T::String)
                       .fallback("\"cubic_spline\"")
                       .one_of({"cubic_spline", "wendland_c2"})
                       .doc("SPH smoothing kernel (support 2h)."));
  s.keys.push_back(
      Key("run.kernel_gradient", T::String)
          .fallback("\"lattice\"")
          .one_of({"lattice", "plain", "particle", "particle_matrix"})
          .doc("\"lattice\": dW/dr divided by the kernel's gradient sum on the initial lattice "
               "(0.9908 for the cubic spline at h = 1.2 dp), so that gradients of linear fields "
               "are exact there (Bonet & Lok 1999, eq. 27; sph/lattice_gradient.h); \"plain\": "
               "the kernel as published, whose gradients are that factor too small; "
               "\"particle\": \"lattice\" and, for the water, each particle's gradient "
               "renormalised by D / tr(L) where its kernel support is full "
               "(fluid_solver/particle_gradient.h), so that a lattice that rearranges in a flow "
               "keeps its pressure gradients (seepage under the weir: heads within 1.7 % of dh "
               "instead of 15 % once the sand's water lattice turned hexagonal); "
               "\"particle_matrix\": "
               "\"lattice\" and, for the water, each particle's gradient corrected by the "
               "inverse of L itself where its support is full, pair-averaged (Bonet & Lok 1999), "
               "so that a lattice that a shear flow strains does not leak the hydrostatic "
               "gradient sideways (the weir's pools: a head tilt of 1 % of dh along the flow "
               "with \"particle\")."));

  s.tables.push_back({"domain", false, true,
                      "The simulation box. Periodic axes wrap at its faces; particles leaving it "
                      "are removed and counted."});
  s.keys.push_back(
      Key("domain.min", T::Vector).unit("m").required().doc("Lower corner of the domain."));
  s.keys.push_back(Key("domain.max", T::Vector)
                       .unit("m")
                       .required()
                       .doc("Upper corner of the domain; greater than min in every component."));
}

void add_water(SceneSchema& s) {
  s.tables.push_back({"water", false, false,
                      "The water phase (weakly compressible SPH). Its presence means the scene has "
                      "water."});
  s.keys.push_back(
      Key("water.rho0", T::Float).unit("kg/m^3").fallback("1000.0").above(0).doc("Rest density."));
  s.keys.push_back(Key("water.sound_speed", T::Float)
                       .unit("m/s")
                       .required()
                       .above(0)
                       .doc("Numerical sound speed c of the Tait equation (eq. 4); at least 10 "
                            "times the largest expected speed."));
  s.keys.push_back(Key("water.gamma", T::Float)
                       .fallback("7.0")
                       .at_least(1)
                       .doc("Exponent of the Tait equation of state (eq. 4)."));
  s.keys.push_back(
      Key("water.hydrostatic_initial", T::Bool)
          .fallback("true")
          .doc("Initial density from the pressure of still weakly compressible "
               "water d = level - height below the surface, p(d) = B ((1 + (gamma - "
               "1)/gamma rho0 g d / B)^(gamma/(gamma - 1)) - 1) = rho0 g d (1 + g d / "
               "(2 c0^2) + ...) (inverse of eq. 4), per connected water body (particles "
               "linked through neighbours at most 1.5 dp apart: a wall separates "
               "bodies, water in a gap under it joins them), each from its own free "
               "surface: in each column of a body the level is the top of its water "
               "+ dp/2, except under a wall (a wall particle less than 2 dp above "
               "the water's top in its column: under a wall's tip, a plate, a lid), "
               "where it is the top of the whole body + dp/2 "
               "(fluid_solver/hydrostatic_initial.h)."));
  s.keys.push_back(Key("water.initial_velocity", T::String)
                       .fallback("\"none\"")
                       .one_of({"none", "taylor_green"})
                       .doc("Velocity of the water at t = 0: none, at rest; taylor_green, the "
                            "Taylor-Green vortex u = U sin(kx) cos(ky), v = -U cos(kx) sin(ky), "
                            "k = 2 pi / L (x, y in the scene frame; in 3D uniform along z), with "
                            "its pressure p = rho0 U^2 / 4 (cos 2kx + cos 2ky) added to the "
                            "hydrostatic one (density: inverse of eq. 4)."));
  s.keys.push_back(Key("water.taylor_green_speed", T::Float)
                       .unit("m/s")
                       .required()
                       .above(0)
                       .only_when("initial_velocity", {"taylor_green"})
                       .doc("Velocity amplitude U of the Taylor-Green vortex."));
  s.keys.push_back(Key("water.taylor_green_wavelength", T::Float)
                       .unit("m")
                       .required()
                       .above(0)
                       .only_when("initial_velocity", {"taylor_green"})
                       .doc("Wavelength L = 2 pi / k of the Taylor-Green vortex: a periodic L x L "
                            "box holds one period (four vortices)."));
  s.keys.push_back(Key("water.solver", T::String)
                       .fallback("\"\"")
                       .doc("Executable of the water solver; empty: the built-in fluid_solver."));

  s.tables.push_back({"water.blocks[]", true, true,
                      "Regions filled with water at t = 0 (needed when [water] exists). "
                      "Particles sit on a lattice of spacing dp, half a spacing inside the region. "
                      "Every block must lie inside the domain. Blocks may touch but not overlap: "
                      "`coupler check` and `run` refuse two blocks that share a lattice point "
                      "(exit 2, both lines)."});
  add_filled_region_keys(s, "water.blocks[]");
  s.keys.push_back(Key("water.blocks[].label", T::String)
                       .fallback("\"\"")
                       .doc("Optional name shown in errors and output."));
}

}  // namespace schema_detail

namespace {

/// Part of `path` before its last '.', or "" when there is none.
std::string parent_of(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string last_segment(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

}  // namespace

std::string KeySpec::name() const { return last_segment(path); }
std::string KeySpec::table() const { return parent_of(path); }

std::string TableSpec::header_name() const {
  std::string out;
  for (char c : path)
    if (c != '[' && c != ']') out += c;
  return out;
}

const TableSpec* SceneSchema::find_table(const std::string& path) const {
  for (const auto& t : tables)
    if (t.path == path) return &t;
  return nullptr;
}

const KeySpec* SceneSchema::find_key(const std::string& path) const {
  for (const auto& k : keys)
    if (k.path == path) return &k;
  return nullptr;
}

std::vector<std::string> SceneSchema::child_names(const std::string& path) const {
  std::vector<std::string> names;
  for (const auto& k : keys)
    if (k.table() == path) names.push_back(k.name());
  for (const auto& t : tables) {
    if (parent_of(t.path) != path) continue;
    std::string name = last_segment(t.path);
    if (t.array) name = name.substr(0, name.size() - 2);  // drop "[]"
    names.push_back(name);
  }
  return names;
}

SceneSchema make_scene_schema() {
  using namespace schema_detail;
  SceneSchema schema;
  add_scene_and_run(schema);
  add_water(schema);
  add_flow_zones(schema);
  add_soil(schema);
  add_coupling(schema);
  add_walls_and_observables(schema);
  add_term_keys(schema);  // the keys each physics term owns (scene/term_registry.h)
  return schema;
}

std::string type_name(ValueType type) {
  switch (type) {
    case ValueType::Int:
      return "int";
    case ValueType::Float:
      return "float";
    case ValueType::Bool:
      return "bool";
    case ValueType::String:
      return "string";
    case ValueType::Vector:
      return "vector";
    case ValueType::VectorList:
      return "list of vectors";
    case ValueType::StringList:
      return "list of strings";
    case ValueType::BoolVector:
      return "bool vector";
  }
  return "?";
}

}  // namespace porosph::scene
