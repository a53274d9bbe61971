// --set overrides (applied before validation, errors naming "--set") and the resolved TOML, which
// must load back into the same Scene.
#include <gtest/gtest.h>

#include "tests/scene/scene_examples.h"
#include "tests/scene/scene_examples_soil.h"

namespace porosph::scene::test {
namespace {

using Doubles = std::vector<double>;

TEST(SceneOverrides, ScalarVectorAndStringValues) {
  const Scene s = load_scene_text(
      kWaterColumn2D, "x.toml",
      {"run.dp=0.005", "run.end_time=2", "run.gravity=[0, -1]", "run.kernel=wendland_c2",
       "run.h_factor = 1.5", "scene.description=\"two words\"", "water.solver=my_solver",
       "run.dt_smoothing=false"});
  EXPECT_EQ(s.run.dp, 0.005);
  EXPECT_EQ(s.run.end_time, 2.0);  // an integer is accepted for a float
  EXPECT_EQ(s.run.gravity, (Doubles{0.0, -1.0}));
  EXPECT_EQ(s.run.kernel, "wendland_c2");  // a bare word is a string
  EXPECT_EQ(s.run.h_factor, 1.5);          // a key the file does not set
  EXPECT_EQ(s.description, "two words");
  EXPECT_EQ(s.water->solver, "my_solver");
  EXPECT_FALSE(s.run.dt_smoothing);
}

TEST(SceneOverrides, StringKeyTakesAnyValueAsText) {
  const Scene s = load_scene_text(kWaterColumn2D, "x.toml", {"scene.description=42"});
  EXPECT_EQ(s.description, "42");
}

TEST(SceneOverrides, ArrayOfTablesElementsInBothNotations) {
  const Scene s = load_scene_text(kWaterColumn2D, "x.toml",
                                  {"walls[0].max=[1.0, 2.0]", "walls.0.layers=5",
                                   "water.blocks.0.label=left", "observables[0].direction=[3, 4]"});
  EXPECT_EQ(s.walls[0].max, (Doubles{1.0, 2.0}));
  EXPECT_EQ(s.walls[0].layers, 5);
  EXPECT_EQ(s.water->blocks[0].label, "left");
  // [3, 4] / 5: 0.6 and 0.8 to within one rounding of the division.
  ASSERT_EQ(s.observables[0].direction.size(), 2u);
  EXPECT_DOUBLE_EQ(s.observables[0].direction[0], 0.6);
  EXPECT_DOUBLE_EQ(s.observables[0].direction[1], 0.8);
}

TEST(SceneOverrides, LaterOverrideWins) {
  const Scene s = load_scene_text(kWaterColumn2D, "x.toml", {"run.dp=0.02", "run.dp=0.03"});
  EXPECT_EQ(s.run.dp, 0.03);
}

struct OverrideErrorCase {
  std::string assignment;
  std::string what;  ///< the full message expected
};

TEST(SceneOverrides, ErrorsNameTheCommandLine) {
  const std::vector<OverrideErrorCase> cases = {
      {"run.dpp=1", "--set: key 'run.dpp': unknown key (did you mean 'run.dp'?)"},
      {"walls[0].layer=2",
       "--set: key 'walls[0].layer': unknown key (did you mean 'walls[0].layers'?)"},
      {"sediment.d50=0.001", "--set: key 'sediment': unknown key"},
      {"soil.rho0=2000", "--set: key 'soil.rho0': unknown key"},
      {"soil.materials[0].density=2000",
       "--set: key 'soil.materials[0]': no such entry: the scene has 0 [[soil.materials]] entries "
       "(indices start at 0)"},
      {"walls[3].max=[1, 1]",
       "--set: key 'walls[3]': no such entry: the scene has 1 [[walls]] entries (indices start at "
       "0)"},
      {"walls.max=[1, 1]",
       "--set: key 'walls': an array of tables: address an entry as walls[0].max"},
      {"run.dp", "--set: key 'run.dp': expected key=value"},
      {"run..dp=1", "--set: key 'run..dp': malformed key (write a.b or walls[1].max)"},
      {"run.dp=-1", "--set: key 'run.dp': must be > 0, got -1"},
      {"run.dp=fine", "--set: key 'run.dp': expected a float, got a string"},
      {"run.gravity=[0, 0, -9.81]",
       "--set: key 'run.gravity': expected 2 components (run.dimension = 2), got 3"},
      {"scene.name=bad name",
       "--set: key 'scene.name': must be an identifier (letters, digits, '_', '-'; not starting "
       "with a digit), got 'bad name'"},
      {"water.blocks[0].max=[0.5, 2]",
       "--set: key 'water.blocks[0].max': lies outside the domain: y = 2 not in [-0.1, 1.5]"},
      {"walls[0].vertices=[[0, 0], [1, 0], [0, 1]]",
       "--set: key 'walls[0].vertices': only allowed when shape is 'polygon'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.assignment);
    const SceneError e = error_of(kWaterColumn2D, {c.assignment});
    EXPECT_EQ(std::string(e.what()), c.what);
    EXPECT_EQ(e.file(), "--set");
    EXPECT_EQ(e.line(), 0);
  }
}

void expect_same_shape(const Shape& a, const Shape& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.layers, b.layers);
  EXPECT_EQ(a.open_faces, b.open_faces);
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.remove_at, b.remove_at);
  EXPECT_EQ(a.phases, b.phases);
  EXPECT_EQ(a.condition, b.condition);
  EXPECT_EQ(a.material, b.material);
}

void expect_same_material(const SoilMaterial& m, const SoilMaterial& n) {
  EXPECT_EQ(m.name, n.name);
  EXPECT_EQ(m.density, n.density);
  EXPECT_EQ(m.saturated_density, n.saturated_density);
  EXPECT_EQ(m.porosity, n.porosity);
  EXPECT_EQ(m.young_modulus, n.young_modulus);
  EXPECT_EQ(m.poisson_ratio, n.poisson_ratio);
  EXPECT_EQ(m.bulk_modulus, n.bulk_modulus);
  EXPECT_EQ(m.shear_modulus, n.shear_modulus);
  EXPECT_EQ(m.cohesion, n.cohesion);
  EXPECT_EQ(m.friction_angle_deg, n.friction_angle_deg);
  EXPECT_EQ(m.dilatancy_angle_deg, n.dilatancy_angle_deg);
  EXPECT_EQ(m.artificial_stress, n.artificial_stress);
  EXPECT_EQ(m.fixed, n.fixed);
  EXPECT_EQ(m.seepage, n.seepage);
  EXPECT_EQ(m.seepage_parameters, n.seepage_parameters);
  EXPECT_EQ(m.variable_permeability, n.variable_permeability);
  EXPECT_EQ(m.wet_cohesion_loss, n.wet_cohesion_loss);
}

void expect_same_soil(const SoilPhase& p, const SoilPhase& q) {
  EXPECT_EQ(p.solver, q.solver);
  EXPECT_EQ(p.wall_condition, q.wall_condition);
  EXPECT_EQ(p.alpha, q.alpha);
  EXPECT_EQ(p.beta, q.beta);
  EXPECT_EQ(p.artificial_stress_epsilon, q.artificial_stress_epsilon);
  EXPECT_EQ(p.artificial_stress_exponent, q.artificial_stress_exponent);
  EXPECT_EQ(p.sound_speed, q.sound_speed);
  EXPECT_EQ(p.initial_stress, q.initial_stress);
  EXPECT_EQ(p.k0, q.k0);
  EXPECT_EQ(p.damping_duration, q.damping_duration);
  EXPECT_EQ(p.damping_coefficient, q.damping_coefficient);
  ASSERT_EQ(p.materials.size(), q.materials.size());
  for (std::size_t i = 0; i < p.materials.size(); ++i)
    expect_same_material(p.materials[i], q.materials[i]);
  ASSERT_EQ(p.blocks.size(), q.blocks.size());
  for (std::size_t i = 0; i < p.blocks.size(); ++i) expect_same_shape(p.blocks[i], q.blocks[i]);
}

/// Every field of the typed scene but source_path is equal (doubles bit for bit).
void expect_same_scene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.resolved_toml, b.resolved_toml);
  const RunSettings &r = a.run, &q = b.run;
  EXPECT_EQ(r.dimension, q.dimension);
  EXPECT_EQ(r.end_time, q.end_time);
  EXPECT_EQ(r.max_steps, q.max_steps);
  EXPECT_EQ(r.output_interval, q.output_interval);
  EXPECT_EQ(r.dp, q.dp);
  EXPECT_EQ(r.h_factor, q.h_factor);
  EXPECT_EQ(r.dt0, q.dt0);
  EXPECT_EQ(r.cfl, q.cfl);
  EXPECT_EQ(r.c_a, q.c_a);
  EXPECT_EQ(r.viscous_coefficient, q.viscous_coefficient);
  EXPECT_EQ(r.dt_smoothing, q.dt_smoothing);
  EXPECT_EQ(r.euler_every, q.euler_every);
  EXPECT_EQ(r.solver_timeout, q.solver_timeout);
  EXPECT_EQ(r.gravity, q.gravity);
  EXPECT_EQ(r.periodic, q.periodic);
  EXPECT_EQ(r.kernel, q.kernel);
  EXPECT_EQ(a.domain.min, b.domain.min);
  EXPECT_EQ(a.domain.max, b.domain.max);
  ASSERT_EQ(a.has_water(), b.has_water());
  if (a.has_water()) {
    const WaterPhase &w = *a.water, &v = *b.water;
    EXPECT_EQ(w.rho0, v.rho0);
    EXPECT_EQ(w.sound_speed, v.sound_speed);
    EXPECT_EQ(w.viscosity, v.viscosity);
    EXPECT_EQ(w.alpha, v.alpha);
    EXPECT_EQ(w.beta, v.beta);
    EXPECT_EQ(w.gamma, v.gamma);
    EXPECT_EQ(w.density_filter_every, v.density_filter_every);
    EXPECT_EQ(w.hydrostatic_initial, v.hydrostatic_initial);
    EXPECT_EQ(w.wall_condition, v.wall_condition);
    EXPECT_EQ(w.solver, v.solver);
    ASSERT_EQ(w.blocks.size(), v.blocks.size());
    for (std::size_t i = 0; i < w.blocks.size(); ++i) expect_same_shape(w.blocks[i], v.blocks[i]);
  }
  ASSERT_EQ(a.has_soil(), b.has_soil());
  if (a.has_soil()) expect_same_soil(*a.soil, *b.soil);
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) expect_same_shape(a.walls[i], b.walls[i]);
  ASSERT_EQ(a.observables.size(), b.observables.size());
  for (std::size_t i = 0; i < a.observables.size(); ++i) {
    const Observable &o = a.observables[i], &p = b.observables[i];
    EXPECT_EQ(o.name, p.name);
    EXPECT_EQ(o.kind, p.kind);
    EXPECT_EQ(o.phase, p.phase);
    EXPECT_EQ(o.direction, p.direction);
    EXPECT_EQ(o.origin, p.origin);
    EXPECT_EQ(o.point, p.point);
    EXPECT_EQ(o.field, p.field);
    EXPECT_EQ(o.region_min, p.region_min);
    EXPECT_EQ(o.region_max, p.region_max);
  }
}

TEST(SceneResolvedToml, RoundTripGivesTheSameScene) {
  struct Input {
    std::string text;
    std::vector<std::string> overrides;
  };
  const std::vector<Input> inputs = {
      {kWaterColumn2D, {}},
      // Values whose shortest decimal form differs from a 6-digit print: must survive exactly.
      {kWaterColumn2D,
       {"run.dp=0.1234567890123", "walls[0].max=[1.0000000000000002, 1]", "water.alpha=0",
        "observables[0].direction=[1, 3]", "water.blocks[0].label=\"a \\\"quoted\\\" label\""}},
      {kWaterBox3D, {"run.gravity=[0.1, 0, -9.80665]"}},
      // The soil tables: defaults filled in (and the derived wall phases and observable phase),
      // optional keys left out, the elastic pair not given recomputed identically.
      {kGranularColumn2D, {"soil.materials[0].poisson_ratio=0.2999999999999999"}},
      {kSubmergedBed2D,
       {"soil.materials[0].d15=0.0123456789012345", "run.max_steps=7",
        "observables[0].region_max=[0.30000000000000004, 0.15]"}},
  };
  for (const Input& input : inputs) {
    const Scene first = load_scene_text(input.text, "x.toml", input.overrides);
    SCOPED_TRACE(first.resolved_toml);
    const Scene second = load_scene_text(first.resolved_toml, "resolved.toml");
    EXPECT_EQ(second.source_path, "resolved.toml");
    expect_same_scene(first, second);
  }
}

TEST(SceneResolvedToml, ShowsOverridesAndDefaults) {
  const Scene s = load_scene_text(kWaterColumn2D, "x.toml", {"run.dp=0.005"});
  for (const std::string expected :
       {"dp = 0.005", "h_factor = 1.2", "kernel = 'cubic_spline'", "layers = 3",
        "gravity = [ 0.0, -9.81 ]", "cfl = 0.2\n", "rho0 = 1000.0\n", "dt0 = 0.0001\n",
        "[[water.blocks]]", "min = [ 0.0, 0.0 ]"})
    EXPECT_NE(s.resolved_toml.find(expected), std::string::npos)
        << "missing '" << expected << "' in\n"
        << s.resolved_toml;
}

}  // namespace
}  // namespace porosph::scene::test
