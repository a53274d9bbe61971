#include "tools/validation/seepage_checks.h"

#include <cmath>
#include <stdexcept>

#include "porous/permeability.h"
#include "porous/seepage_law.h"
#include "porous/seepage_laws.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {

DarcyColumnCheck check_darcy_column(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const auto gravity = parameters.at("run").at("gravity").get<std::vector<double>>();
  double g = 0;
  for (double c : gravity) g += c * c;
  g = std::sqrt(g);
  const auto& water = parameters.at("water");
  const double nu = water.at("viscosity").get<double>() / water.at("rho0").get<double>();
  const auto& m = parameters.at("soil").at("materials").at(0);
  const double n = m.at("porosity").get<double>();
  DarcyColumnCheck out;
  out.seepage = m.at("seepage").get<std::string>();
  // Any registered law (porous/seepage_laws.h), at the initial porosity.
  const std::vector<porous::SeepageLawSpec> laws = porous::seepage_laws();
  const porous::SeepageLawSpec* law = porous::find_seepage_law(laws, out.seepage);
  if (law == nullptr)
    throw std::runtime_error(run_dir + ": the first soil material has no seepage law");
  scene::SoilMaterial material;
  material.name = m.value("name", "");
  material.porosity = n;
  material.seepage = out.seepage;
  material.variable_permeability = false;
  for (const scene::KeySpec& key : law->keys)
    material.seepage_parameters[key.name()] = m.at(key.name()).get<double>();
  const porous::SeepageCoefficients c =
      porous::SeepageLaw::from_material(material, g, nu).coefficients(n);
  out.a = c.a;
  out.b = c.b;
  // i = a q + b q^2 = 1.
  out.expected = c.b > 0 ? (-c.a + std::sqrt(c.a * c.a + 4 * c.b)) / (2 * c.b) : 1.0 / c.a;
  out.quadratic_share = c.b * out.expected * out.expected;  // of i = 1
  const auto series = read_timeseries(run_dir);
  const auto& q = series.column("darcy_velocity");
  const auto& t = series.column("t");
  if (q.size() < 2) throw std::runtime_error(run_dir + ": fewer than two outputs");
  out.simulated = std::abs(q.back());
  out.time = t.back();
  out.rel_error = std::abs(out.simulated - out.expected) / out.expected;
  out.settling = std::abs(q.back() - q[q.size() - 2]) / std::max(1e-300, std::abs(q.back()));
  return out;
}

}  // namespace porosph::validation
