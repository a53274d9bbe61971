// The soil phase: relations between its keys the schema cannot express, and the typed SoilPhase.
//
// Elasticity: a material gives (E, nu) or (K, G); the other pair follows from the isotropic
// relations (e.g. Timoshenko & Goodier, Theory of Elasticity)
//   K = E / (3 (1 - 2 nu)),  G = E / (2 (1 + nu)),  E = 9 K G / (3 K + G),
//   nu = (3 K - 2 G) / (2 (3 K + G)).
#include <algorithm>
#include <cmath>
#include <map>

#include "porous/seepage_laws.h"
#include "scene/scene_internal.h"

namespace porosph::scene {
namespace {

const std::string kElasticPairs =
    "give young_modulus and poisson_ratio, or bulk_modulus and shear_modulus";

/// Exactly one of the pairs (young_modulus, poisson_ratio) and (bulk_modulus, shear_modulus).
void check_elastic_pair(const toml::table& material, const std::string& key,
                        const ErrorContext& errors) {
  const toml::node* young = material.get("young_modulus");
  const toml::node* poisson = material.get("poisson_ratio");
  const toml::node* bulk = material.get("bulk_modulus");
  const toml::node* shear = material.get("shear_modulus");
  if ((young || poisson) && (bulk || shear)) {
    const bool bulk_given = bulk != nullptr;
    errors.fail(bulk_given ? bulk : shear, key + (bulk_given ? ".bulk_modulus" : ".shear_modulus"),
                "elasticity given twice: " + kElasticPairs + ", not both");
  }
  const std::pair<const char*, const toml::node*> halves[] = {{"young_modulus", young},
                                                              {"poisson_ratio", poisson},
                                                              {"bulk_modulus", bulk},
                                                              {"shear_modulus", shear}};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& [name, node] = halves[i];
    const auto& [partner_name, partner] = halves[i ^ 1];  // the other key of the same pair
    if (node && !partner)
      errors.fail(node, key + "." + name,
                  std::string("given without ") + partner_name + "; " + kElasticPairs);
  }
  if (!young && !bulk) errors.fail(&material, key, "no elasticity given: " + kElasticPairs);
}

/// Unique names, one elastic pair each, dilatancy <= friction. Returns the names in file order.
std::vector<std::string> check_materials(const toml::array& materials, const ErrorContext& errors) {
  std::vector<std::string> names;
  std::map<std::string, std::size_t> first_index;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const toml::table& material = *materials.get(i)->as_table();
    const std::string key = "soil.materials[" + std::to_string(i) + "]";
    const std::string name = text_of(material, "name");
    if (const auto [it, inserted] = first_index.emplace(name, i); !inserted)
      errors.fail(material.get("name"), key + ".name",
                  "duplicate material name '" + name + "' (also soil.materials[" +
                      std::to_string(it->second) + "])");
    names.push_back(name);
    check_elastic_pair(material, key, errors);
    const double friction = *material["friction_angle"].value<double>();
    const double dilatancy = *material["dilatancy_angle"].value<double>();
    if (dilatancy > friction)
      errors.fail(material.get("dilatancy_angle"), key + ".dilatancy_angle",
                  "must not exceed friction_angle (" + format_number(friction) + "), got " +
                      format_number(dilatancy));
  }
  return names;
}

SoilMaterial material_of(const toml::table& table) {
  SoilMaterial m;
  const auto number = [&table](const char* name, double fallback) {
    return table[name].value<double>().value_or(fallback);
  };
  const auto flag = [&table](const char* name, bool fallback) {
    return table[name].value<bool>().value_or(fallback);
  };
  m.name = text_of(table, "name");
  m.density = number("density", m.density);
  m.saturated_density = number("saturated_density", m.saturated_density);
  m.porosity = number("porosity", m.porosity);
  if (table.contains("young_modulus")) {
    const double e = number("young_modulus", 0.0), nu = number("poisson_ratio", 0.0);
    m.young_modulus = e;
    m.poisson_ratio = nu;
    m.bulk_modulus = e / (3.0 * (1.0 - 2.0 * nu));
    m.shear_modulus = e / (2.0 * (1.0 + nu));
  } else {
    const double k = number("bulk_modulus", 0.0), g = number("shear_modulus", 0.0);
    m.bulk_modulus = k;
    m.shear_modulus = g;
    m.young_modulus = 9.0 * k * g / (3.0 * k + g);
    m.poisson_ratio = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
  }
  m.cohesion = number("cohesion", m.cohesion);
  m.friction_angle_deg = number("friction_angle", m.friction_angle_deg);
  m.dilatancy_angle_deg = number("dilatancy_angle", m.dilatancy_angle_deg);
  m.yield_fit = table["yield_fit"].value<std::string>().value_or(m.yield_fit);
  m.artificial_stress = flag("artificial_stress", m.artificial_stress);
  m.fixed = flag("fixed", m.fixed);
  m.seepage = table["seepage"].value<std::string>().value_or(m.seepage);
  const std::vector<porous::SeepageLawSpec> laws = porous::seepage_laws();
  if (const porous::SeepageLawSpec* law = porous::find_seepage_law(laws, m.seepage)) {
    for (const KeySpec& key : law->keys)
      m.seepage_parameters[key.name()] = number(key.name().c_str(), 0.0);
  }
  m.variable_permeability = flag("variable_permeability", m.variable_permeability);
  m.wet_cohesion_loss = flag("wet_cohesion_loss", m.wet_cohesion_loss);
  return m;
}

/// "'a', 'b', 'c'".
std::string comma_list(const std::vector<std::string>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) out += (i == 0 ? "'" : ", '") + values[i] + "'";
  return out;
}

}  // namespace

void check_soil_consistency(const toml::table& soil, const ShapeChecker& shapes,
                            const ErrorContext& errors) {
  const std::vector<std::string> names =
      check_materials(*soil.get_as<toml::array>("materials"), errors);
  const toml::array& blocks = *soil.get_as<toml::array>("blocks");
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const toml::table& block = *blocks.get(i)->as_table();
    const std::string key = "soil.blocks[" + std::to_string(i) + "]";
    shapes.check(block, key, true);
    const std::string material = text_of(block, "material");
    if (std::find(names.begin(), names.end(), material) == names.end())
      errors.fail(block.get("material"), key + ".material",
                  "unknown material '" + material + "'" + did_you_mean(material, names) +
                      "; known materials: " + comma_list(names));
  }
  check_soil_loads(soil, names, shapes, errors);
}

SoilPhase build_soil_phase(const toml::table& soil) {
  SoilPhase p;
  p.solver = text_of(soil, "solver");
  p.wall_condition = text_of(soil, "wall_condition");
  p.thin_walls = text_of(soil, "thin_walls");
  p.wall_stress = text_of(soil, "wall_stress");
  p.wall_stress_continuation = text_of(soil, "wall_stress_continuation");
  p.stress_integration = text_of(soil, "stress_integration");
  p.alpha = *soil["alpha"].value<double>();
  p.beta = *soil["beta"].value<double>();
  p.artificial_stress_epsilon = *soil["artificial_stress_epsilon"].value<double>();
  p.artificial_stress_exponent = *soil["artificial_stress_exponent"].value<double>();
  p.sound_speed = *soil["sound_speed"].value<double>();
  p.initial_stress = text_of(soil, "initial_stress");
  p.k0 = text_of(soil, "k0");
  p.damping_duration = *soil["damping_duration"].value<double>();
  p.damping_coefficient = *soil["damping_coefficient"].value<double>();
  p.stress_filter_every = static_cast<int>(*soil["stress_filter_every"].value<int64_t>());
  p.stress_filter = text_of(soil, "stress_filter");
  for (const auto& element : *soil.get_as<toml::array>("materials"))
    p.materials.push_back(material_of(*element.as_table()));
  p.blocks = shapes_of(soil.get_as<toml::array>("blocks"));
  build_soil_loads(soil, p);
  return p;
}

int SoilPhase::material_index(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

double SoilPhase::stiffest_sound_speed() const {
  double fastest = 0.0;
  for (const SoilMaterial& m : materials)
    if (m.density > 0.0) {  // P-wave modulus K + 4G/3: the fastest elastic wave of the skeleton
      fastest =
          std::max(fastest, std::sqrt((m.bulk_modulus + 4.0 * m.shear_modulus / 3.0) / m.density));
    }
  return fastest;
}

double SoilPhase::effective_sound_speed() const {
  return sound_speed > 0.0 ? sound_speed : stiffest_sound_speed();
}

}  // namespace porosph::scene
