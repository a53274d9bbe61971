// Errors of the soil phase and of the wall, observable and run keys added with it: each names the
// file, the line and the key. Each case edits a valid example so exactly one thing is wrong.
#include <gtest/gtest.h>

#include "porous/seepage_laws.h"
#include "tests/scene/scene_examples.h"
#include "tests/scene/scene_examples_soil.h"

namespace porosph::scene::test {
namespace {

/// "'none', 'darcy_kozeny_carman', ... or 'forchheimer_ergun'": the registered laws
/// (porous/seepage_laws.h), so that adding a law does not touch this test.
std::string allowed_seepage_laws() {
  std::vector<std::string> names = {"none"};
  for (const auto& law : porous::seepage_laws()) names.push_back(law.name);
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("'" + names[i] + "'");
  return out;
}

std::vector<ErrorCase> soil_error_cases() {
  const std::string& g = kGranularColumn2D;
  const std::string& b = kSubmergedBed2D;
  const std::string elastic = "young_modulus = 0.84e6\npoisson_ratio = 0.3\n";
  const std::string pairs =
      "give young_modulus and poisson_ratio, or bulk_modulus and "
      "shear_modulus";
  const std::string region = "region_min = [0.0, 0.0]\nregion_max = [0.05, 0.01]\n";
  return {
      {"unknown material in a block", with(b, "material = \"sand\"", "material = \"sandd\""),
       "soil.blocks[1].material", "material = \"sandd\"",
       "unknown material 'sandd' (did you mean 'sand'?); known materials: 'gravel', 'sand'"},
      {"unknown material in a load",
       with(b, "[[soil.materials]]\nname = \"sand\"",
            "[[soil.loads]]\nmin = [0.0, 0.1]\nmax = [0.4, 0.12]\ntraction = [0.0, -1e3]\n"
            "material = \"sandd\"\n\n[[soil.materials]]\nname = \"sand\""),
       "soil.loads[0].material", "material = \"sandd\"",
       "unknown material 'sandd' (did you mean 'sand'?)"},
      {"moving wall acting on soil",
       with(b, "open_faces = [\"y+\"]\n\n[[walls]]",
            "open_faces = [\"y+\"]\nmoves_with = \"p_bed\"\nmove_direction = [0.0, 1.0]\n\n"
            "[[walls]]"),
       "walls[0].moves_with", "moves_with = \"p_bed\"",
       "a moving wall acts on water only: give phases = [\"water\"]"},
      {"moving wall without a direction",
       with(b, "label = \"baffle\"", "label = \"baffle\"\nmoves_with = \"p_bed\""),
       "walls[1].move_direction", "moves_with = \"p_bed\"",
       "required with moves_with (the direction the wall moves along)"},
      {"moving wall following no observable",
       with(b, "label = \"baffle\"",
            "label = \"baffle\"\nmoves_with = \"p_bedd\"\nmove_direction = [0.0, 1.0]"),
       "walls[1].moves_with", "moves_with = \"p_bedd\"",
       "no observable named 'p_bedd' (did you mean 'p_bed'?)"},
      {"wall_force of a fixed wall",
       with(b, "name = \"water_count\"",
            "name = \"baffle_force\"\nkind = \"wall_force\"\nwall = \"baffle\"\n"
            "direction = [0.0, 1.0]\n\n[[observables]]\nname = \"water_count\""),
       "observables[2].wall", "wall = \"baffle\"", "no moving wall (moves_with) labelled 'baffle'"},
      {"load_velocity of no load",
       with(b, "name = \"water_count\"",
            "name = \"v\"\nkind = \"load_velocity\"\nphase = \"soil\"\nload = \"plate\"\n\n"
            "[[observables]]\nname = \"water_count\""),
       "observables[2].load", "load = \"plate\"", "no [[soil.loads]] entry with label 'plate'"},
      {"unknown material, nothing close",
       with(g, "material = \"aluminium_bars\"", "material = \"clay\""), "soil.blocks[0].material",
       "material = \"clay\"", "unknown material 'clay'; known materials: 'aluminium_bars'"},
      {"both elastic pairs",
       with(g, elastic, elastic + "bulk_modulus = 1e6\nshear_modulus = 1e6\n"),
       "soil.materials[0].bulk_modulus", "bulk_modulus",
       "elasticity given twice: " + pairs + ", not both"},
      {"keys of both pairs", with(g, elastic, "young_modulus = 0.84e6\nshear_modulus = 1e6\n"),
       "soil.materials[0].shear_modulus", "shear_modulus",
       "elasticity given twice: " + pairs + ", not both"},
      {"neither elastic pair", with(g, elastic, ""), "soil.materials[0]", "[[soil.materials]]",
       "no elasticity given: " + pairs},
      {"half an elastic pair", with(g, "poisson_ratio = 0.3\n", ""),
       "soil.materials[0].young_modulus", "young_modulus", "given without poisson_ratio; " + pairs},
      {"other half of the other pair", with(b, "bulk_modulus = 5e6\n", ""),
       "soil.materials[0].shear_modulus", "shear_modulus", "given without bulk_modulus; " + pairs},
      {"dilatancy above friction", with(b, "dilatancy_angle = 2", "dilatancy_angle = 33"),
       "soil.materials[1].dilatancy_angle", "dilatancy_angle",
       "must not exceed friction_angle (32), got 33"},
      {"seepage model missing its diameter", with(b, "effective_diameter = 0.0004\n", ""),
       "soil.materials[1].effective_diameter", "", "required key is missing"},
      {"Forchheimer missing d15", with(b, "d15 = 0.01\n", ""), "soil.materials[0].d15", "",
       "required key is missing"},
      {"seepage parameter of another model",
       with(b, "d15 = 0.01", "d15 = 0.01\nhydraulic_conductivity = 1e-3"),
       "soil.materials[0].hydraulic_conductivity", "hydraulic_conductivity",
       "only allowed when seepage is 'darcy_conductivity'"},
      {"seepage parameter without seepage", with(g, elastic, elastic + "d15 = 0.01\n"),
       "soil.materials[0].d15", "d15", "only allowed when seepage is 'forchheimer_den_adel'"},
      {"bad seepage model", with(b, "\"darcy_kozeny_carman\"", "\"darcy\""),
       "soil.materials[1].seepage", "seepage = \"darcy\"",
       "must be " + allowed_seepage_laws() + ", got 'darcy'"},
      {"duplicate material name", with(b, "name = \"gravel\"", "name = \"sand\""),
       "soil.materials[1].name", "name = \"sand\"\ndensity = 1500",
       "duplicate material name 'sand' (also soil.materials[0])"},
      {"material name not an identifier", with(b, "name = \"gravel\"", "name = \"coarse gravel\""),
       "soil.materials[0].name", "coarse gravel",
       "must be an identifier (letters, digits, '_'; not starting with a digit), got 'coarse "
       "gravel'"},
      {"porosity out of range", with(b, "porosity = 0.35", "porosity = 1"),
       "soil.materials[0].porosity", "porosity = 1", "must be in [0.01, 0.99], got 1"},
      {"poisson ratio 0.5", with(g, "poisson_ratio = 0.3", "poisson_ratio = 0.5"),
       "soil.materials[0].poisson_ratio", "poisson_ratio", "must be in (-1, 0.5), got 0.5"},
      {"friction angle 90", with(g, "friction_angle = 19.8", "friction_angle = 90"),
       "soil.materials[0].friction_angle", "friction_angle", "must be in [0, 89], got 90"},
      {"friction angle missing", with(g, "friction_angle = 19.8\n", ""),
       "soil.materials[0].friction_angle", "", "required key is missing"},
      {"density missing", with(g, "density = 2650\n", ""), "soil.materials[0].density", "",
       "required key is missing"},
      {"saturated density zero", with(b, "saturated_density = 2050", "saturated_density = 0"),
       "soil.materials[0].saturated_density", "saturated_density", "must be > 0, got 0"},
      {"artificial stress exponent zero",
       with(b, "artificial_stress_exponent = 4", "artificial_stress_exponent = 0"),
       "soil.artificial_stress_exponent", "artificial_stress_exponent", "must be > 0, got 0"},
      {"bad initial stress", with(g, "\"geostatic\"", "\"lithostatic\""), "soil.initial_stress",
       "initial_stress", "must be 'geostatic' or 'none', got 'lithostatic'"},
      {"unknown soil key", with(g, "initial_stress", "initial_stres"), "soil.initial_stres",
       "initial_stres", "unknown key (did you mean 'soil.initial_stress'?)"},
      {"soil without materials", erase(g, "[[soil.materials]]", "[[soil.blocks]]"),
       "soil.materials", "", "at least one [[soil.materials]] entry is required"},
      {"soil without blocks", erase(g, "[[soil.blocks]]", "[[walls]]"), "soil.blocks", "",
       "at least one [[soil.blocks]] entry is required"},
      {"block without material", with(g, "material = \"aluminium_bars\"\n", ""),
       "soil.blocks[0].material", "", "required key is missing"},
      {"soil block outside the domain", with(g, "max = [0.2, 0.1]", "max = [0.6, 0.1]"),
       "soil.blocks[0].max", "max = [0.6, 0.1]",
       "lies outside the domain: x = 0.6 not in [-0.01, 0.51]"},
      {"walls.phases naming an absent phase",
       with(g, "open_faces = [\"y+\"]", "open_faces = [\"y+\"]\nphases = [\"water\"]"),
       "walls[0].phases", "phases", "phase 'water' is not in the scene (it has no [water] table)"},
      {"walls.phases listing a phase twice", with(b, "[\"water\"]", "[\"water\", \"water\"]"),
       "walls[1].phases", "phases = [", "phase 'water' is listed twice"},
      {"walls.phases naming no phase", with(b, "[\"water\"]", "[\"air\"]"), "walls[1].phases",
       "phases = [", "entry 0: must be 'water' or 'soil', got 'air'"},
      {"walls.phases empty", with(b, "[\"water\"]", "[]"), "walls[1].phases", "phases = [",
       "expected at least 1 entry, got 0"},
      {"bad wall condition", with(b, "\"free_slip\"\nlabel", "\"free-slip\"\nlabel"),
       "walls[1].condition", "condition = \"free-slip\"",
       "must be 'default', 'no_slip' or 'free_slip', got 'free-slip' (did you mean 'free_slip'?)"},
      {"region_min without region_max", with(g, region, "region_min = [0.0, 0.0]\n"),
       "observables[2].region_min", "region_min",
       "given without region_max (give both or neither)"},
      {"region_max without region_min", with(g, region, "region_max = [0.05, 0.01]\n"),
       "observables[2].region_max", "region_max",
       "given without region_min (give both or neither)"},
      {"region not ordered", with(g, "[0.05, 0.01]", "[0.05, 0.0]"), "observables[2].region_max",
       "region_max",
       "must be greater than observables[2].region_min in every component; y: 0 <= 0"},
      {"region for pressure_at", with(b, "point = [0.2, 0.06]", "point = [0.2, 0.06]\n" + region),
       "observables[1].region_min", "region_min = [0.0, 0.0]",
       "only allowed when kind is 'front_position', 'max_speed', 'kinetic_energy', 'max_height', "
       "'particle_count', 'mean_field' or 'max_displacement'"},
      {"mean_field without field", with(g, "field = \"stress_yy\"\n", ""), "observables[2].field",
       "", "required key is missing"},
      {"field for another kind",
       with(g, "kind = \"max_displacement\"", "kind = \"max_displacement\"\nfield = \"porosity\""),
       "observables[1].field", "field = \"porosity\"", "only allowed when kind is 'mean_field'"},
      {"unknown field", with(g, "\"stress_yy\"", "\"stress_yyy\""), "observables[2].field",
       "field =",
       "must be 'density', 'mass', 'pressure', 'porosity', 'speed', 'velocity_x', 'velocity_y', "
       "'velocity_z', 'stress_xx', 'stress_yy', 'stress_zz', 'stress_xy', 'stress_xz' or "
       "'stress_yz', got 'stress_yyy' (did you mean 'stress_yy'?)"},
      {"water field on soil", with(g, "\"stress_yy\"", "\"pressure\""), "observables[2].field",
       "field =", "field 'pressure' exists only for phase 'water' (phase is 'soil')"},
      {"soil field on water", with(b, "phase = \"soil\"\n", ""), "observables[0].field",
       "field =", "field 'porosity' exists only for phase 'soil' (phase is 'water')"},
      {"z velocity in 2D", with(g, "\"stress_yy\"", "\"velocity_z\""), "observables[2].field",
       "field =", "field 'velocity_z' needs a z axis (run.dimension = 2)"},
      {"observable of an absent phase",
       with(g, "kind = \"max_displacement\"", "kind = \"max_displacement\"\nphase = \"water\""),
       "observables[1].phase", "phase = \"water\"",
       "phase 'water' is not in the scene (it has no [water] table)"},
      {"negative max_steps", with(g, "dt0 = 1e-5", "dt0 = 1e-5\nmax_steps = -1"), "run.max_steps",
       "max_steps", "must be >= 0, got -1"},
      {"float max_steps", with(g, "dt0 = 1e-5", "dt0 = 1e-5\nmax_steps = 1e3"), "run.max_steps",
       "max_steps", "expected an integer, got a float"},
  };
}

TEST(SceneSoilErrors, NameFileLineKeyAndProblem) {
  for (const ErrorCase& c : soil_error_cases()) expect_error(c);
}

TEST(SceneSoilErrors, OverridesOfSoilKeysNameTheCommandLine) {
  // A relation broken by an override (dilatancy 40 deg is in range but above the sand's 32 deg).
  const SceneError e = error_of(kSubmergedBed2D, {"soil.materials[1].dilatancy_angle=40"});
  EXPECT_EQ(std::string(e.what()),
            "--set: key 'soil.materials[1].dilatancy_angle': must not exceed friction_angle (32), "
            "got 40");
  EXPECT_EQ(e.file(), "--set");
  EXPECT_EQ(e.line(), 0);
}

}  // namespace
}  // namespace porosph::scene::test
