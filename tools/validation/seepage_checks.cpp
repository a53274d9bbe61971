#include "tools/validation/seepage_checks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "porous/permeability.h"
#include "porous/seepage_law.h"
#include "porous/seepage_laws.h"
#include "sph/kernels.h"
#include "tools/validation/lattice_registry.h"
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
  out.final_value = std::abs(q.back());
  out.time = t.back();
  out.settling = std::abs(q.back() - q[q.size() - 2]) / std::max(1e-300, std::abs(q.back()));
  const auto& run_keys = parameters.at("run");
  const double dp = run_keys.at("dp").get<double>();
  out.period = dp / out.expected;
  // 15 relaxation times 1 / (g (a + 2 b q)) of the linearised i = a q + b q^2 (Darcy: K / g):
  // the transient left is e^-15 = 3e-7 of the velocity.
  const double relaxation = 15.0 / (g * (c.a + 2.0 * c.b * out.expected));
  out.period_covered = t.back() - out.period >= relaxation;
  out.simulated = out.final_value;
  if (out.period_covered) {
    const double from = t.back() - out.period;
    std::vector<double> speed(q.size());
    for (std::size_t k = 0; k < q.size(); ++k) speed[k] = std::abs(q[k]);
    double low = std::abs(interpolate(t, q, from)), high = low;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] <= from) continue;
      low = std::min(low, speed[k]);
      high = std::max(high, speed[k]);
    }
    out.period_mean = time_mean(t, speed, from, t.back());
    out.period_swing = 0.5 * (high - low) / out.expected;
    out.simulated = out.period_mean;
  }
  out.rel_error = std::abs(out.simulated - out.expected) / out.expected;
  const int dimension = run_keys.at("dimension").get<int>();
  const double h = run_keys.at("h_factor").get<double>() * dp;
  const std::string kernel = run_keys.value("kernel", "cubic_spline");
  int axis = 0;  // the lattice axis along gravity
  for (int k = 1; k < static_cast<int>(gravity.size()); ++k)
    if (std::abs(gravity[k]) > std::abs(gravity[axis])) axis = k;
  // The seepage law with the drag scaled by the lattice sum S: S (a q + b q^2) = 1.
  const auto velocity = [&c](double s) {
    return c.b > 0 ? (-c.a + std::sqrt(c.a * c.a + 4 * c.b / s)) / (2 * c.b) : 1.0 / (c.a * s);
  };
  const auto mean = [&](const auto& w) { return registry_mean_velocity(w, dp, axis, velocity); };
  if (kernel == "cubic_spline") {
    out.registry_prediction =
        dimension == 2 ? mean(sph::CubicSpline<2>(h)) : mean(sph::CubicSpline<3>(h));
  } else if (kernel == "wendland_c2") {
    out.registry_prediction =
        dimension == 2 ? mean(sph::WendlandC2<2>(h)) : mean(sph::WendlandC2<3>(h));
  }
  return out;
}

}  // namespace porosph::validation
