// The schema of the soil phase: [soil] (solver settings), [[soil.materials]] (Drucker-Prager
// skeleton and seepage law per material) and [[soil.blocks]] (regions filled with soil).
// Relations between keys (elastic pairs, dilatancy <= friction, block materials) are checked in
// scene_soil.cpp.
#include <algorithm>

#include "porous/seepage_laws.h"
#include "scene/scene_schema_builder.h"

namespace porosph::scene::schema_detail {
namespace {

void add_soil_settings(SceneSchema& s) {
  s.tables.push_back({"soil", false, false,
                      "The soil phase (elastic-perfectly-plastic Drucker-Prager skeleton, eq. "
                      "5-12). Its presence means the scene has soil."});
  s.keys.push_back(Key("soil.solver", T::String)
                       .fallback("\"\"")
                       .doc("Executable of the soil solver; empty: the built-in soil_solver."));
  s.keys.push_back(
      Key("soil.sound_speed", T::Float)
          .unit("m/s")
          .fallback("0.0")
          .at_least(0)
          .doc(
              "Numerical sound speed (time-step limit, artificial viscosity); 0: "
              "from the stiffest material, max sqrt((K + 4 G / 3) / density) (the P-wave speed)."));
}

void add_soil_materials(SceneSchema& s) {
  s.tables.push_back({"soil.materials[]", true, true,
                      "Soil materials (needed when [soil] exists), referred to by name from "
                      "[[soil.blocks]]. Elasticity is given as young_modulus and poisson_ratio "
                      "or as bulk_modulus and shear_modulus: exactly one pair."});
  const std::string m = "soil.materials[].";
  s.keys.push_back(Key(m + "name", T::String)
                       .required()
                       .format(StringFormat::Identifier)
                       .doc("Material name, unique among the materials."));
  s.keys.push_back(Key(m + "density", T::Float)
                       .unit("kg/m^3")
                       .required()
                       .above(0)
                       .doc("Bulk density of the soil, used for its weight when dry."));
  s.keys.push_back(Key(m + "saturated_density", T::Float)
                       .unit("kg/m^3")
                       .optional()
                       .above(0)
                       .doc("Bulk density with the pores full of water (weight of submerged "
                            "soil, eq. 16); absent: not given (0 in the typed scene)."));
  s.keys.push_back(Key(m + "porosity", T::Float)
                       .fallback("0.4")
                       .at_least(0.01)
                       .at_most(0.99)
                       .doc("Initial porosity n0 (eq. 18-20); within the range the soil solver "
                            "clamps every porosity to (porous/porosity.h), so that no value "
                            "is changed silently."));
  s.keys.push_back(Key(m + "young_modulus", T::Float)
                       .unit("Pa")
                       .optional()
                       .above(0)
                       .doc("Young's modulus E; with poisson_ratio."));
  s.keys.push_back(Key(m + "poisson_ratio", T::Float)
                       .optional()
                       .above(-1)
                       .below(0.5)
                       .doc("Poisson's ratio nu; with young_modulus."));
  s.keys.push_back(Key(m + "bulk_modulus", T::Float)
                       .unit("Pa")
                       .optional()
                       .above(0)
                       .doc("Bulk modulus K; with shear_modulus."));
  s.keys.push_back(Key(m + "shear_modulus", T::Float)
                       .unit("Pa")
                       .optional()
                       .above(0)
                       .doc("Shear modulus G; with bulk_modulus."));
  s.keys.push_back(Key(m + "cohesion", T::Float)
                       .unit("Pa")
                       .fallback("0.0")
                       .at_least(0)
                       .doc("Cohesion c of the Drucker-Prager yield function (eq. 9-10)."));
  s.keys.push_back(Key(m + "friction_angle", T::Float)
                       .unit("deg")
                       .required()
                       .at_least(0)
                       .at_most(89)
                       .doc("Internal friction angle phi."));
  s.keys.push_back(Key(m + "dilatancy_angle", T::Float)
                       .unit("deg")
                       .fallback("0.0")
                       .at_least(0)
                       .at_most(89)
                       .doc("Dilatancy angle psi of the plastic potential; at most "
                            "friction_angle."));
  s.keys.push_back(
      Key(m + "yield_fit", T::String)
          .fallback("\"eq10\"")
          .one_of({"eq10", "flow_rule"})
          .doc("How the Drucker-Prager cone is matched to Mohr-Coulomb (phi, c) in plane "
               "strain: eq10, the seed paper's constants, exact at plastic flow only for "
               "associated flow (psi = phi); flow_rule, exact for the material's own psi (psi = "
               "0: alpha_phi = sin(phi) / 3, k_c = c cos(phi); a wider cone than eq10)."));
}

void add_seepage(SceneSchema& s) {
  const std::string m = "soil.materials[].";
  // The laws and their keys are registered in porous/seepage_laws.h; each key is allowed (and
  // required or defaulted) only with the laws that declare it.
  const std::vector<porous::SeepageLawSpec> laws = porous::seepage_laws();
  std::vector<std::string> names = {"none"};
  std::string doc =
      "Seepage law of the water-soil interaction (eq. 13; porous/seepage_laws.h). none: no "
      "seepage force.";
  for (const porous::SeepageLawSpec& law : laws) {
    names.push_back(law.name);
    doc += " " + law.name + ": " + law.summary;
  }
  s.keys.push_back(Key(m + "seepage", T::String).fallback("\"none\"").one_of(names).doc(doc));
  std::vector<KeySpec> law_keys;
  for (const porous::SeepageLawSpec& law : laws) {
    for (KeySpec key : law.keys) {
      auto same = std::find_if(law_keys.begin(), law_keys.end(),
                               [&key](const KeySpec& k) { return k.path == key.path; });
      if (same != law_keys.end()) {
        same->applies_when->values.push_back(law.name);
        continue;
      }
      key.applies_when = Condition{"seepage", {law.name}};
      law_keys.push_back(key);
    }
  }
  s.keys.insert(s.keys.end(), law_keys.begin(), law_keys.end());
}

void add_soil_blocks(SceneSchema& s) {
  s.tables.push_back({"soil.blocks[]", true, true,
                      "Regions filled with soil at t = 0 (needed when [soil] exists), each of "
                      "one material. Particles sit on a lattice of spacing dp, half a spacing "
                      "inside the region. Every block must lie inside the domain. Blocks may touch "
                      "but not overlap: `coupler check` and `run` refuse two blocks that share a "
                      "lattice point (exit 2, both lines)."});
  add_filled_region_keys(s, "soil.blocks[]");
  s.keys.push_back(Key("soil.blocks[].material", T::String)
                       .required()
                       .doc("Name of the block's material (a [[soil.materials]] entry)."));
  s.keys.push_back(Key("soil.blocks[].label", T::String)
                       .fallback("\"\"")
                       .doc("Optional name shown in errors and output."));
}

}  // namespace

void add_soil(SceneSchema& s) {
  add_soil_settings(s);
  add_soil_materials(s);
  add_seepage(s);
  add_soil_blocks(s);
  add_soil_loads(s);
}

}  // namespace porosph::scene::schema_detail
