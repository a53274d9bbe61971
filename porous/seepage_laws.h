// The seepage laws a soil material can name (soil.materials[].seepage), each registered once
// here: its name, its equation and source, the material keys it reads (declared here, nowhere
// else) and its coefficients a, b of eq. 13 as functions of the porosity. From this list the
// scene schema takes the allowed names and the law keys (each shown only with its laws), the
// term registry the interaction term seepage_<name>, and SeepageLaw (seepage_law.h) the
// coefficients. Adding a law is one entry here and its test (docs/contributing.md, worked
// example).
#pragma once

#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "porous/permeability.h"
#include "scene/scene_schema.h"
#include "scene/scene_schema_builder.h"

namespace porosph::porous {

/// What a law's coefficients depend on besides the porosity.
struct SeepageLawInputs {
  const std::map<std::string, double>* parameters = nullptr;  ///< the law's keys, by name
  double initial_porosity = 0.4;                              ///< n0
  double gravity = 9.81;                                      ///< |g| [m/s^2]
  double kinematic_viscosity = 1e-6;                          ///< nu of the water [m^2/s]

  /// The value of one of the law's keys (std::out_of_range if the law did not declare it).
  double operator[](const std::string& key) const { return parameters->at(key); }
};

struct SeepageLawSpec {
  std::string name;     ///< the value of soil.materials[].seepage
  std::string summary;  ///< equation and source
  /// The material keys the law reads, paths "soil.materials[].<key>"; the schema shows each
  /// only with the laws that declare it. Every one must be > 0 (SeepageLaw checks).
  std::vector<scene::KeySpec> keys;
  bool needs_viscosity = false;  ///< a water viscosity > 0 (water.viscosity)
  /// Binds the law to one material's inputs (read once, here): the function it returns gives a
  /// [s/m] and b [s^2/m^2] of eq. 13 at porosity n (0 < n < 1), and is what runs per particle.
  std::function<std::function<SeepageCoefficients(double n)>(const SeepageLawInputs&)> bind;
};

/// `value` as a TOML float ("150.0", "0.4"), for a default taken from a constant of the code.
inline std::string toml_float(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  std::string out = text;
  if (out.find_first_of(".eEn") == std::string::npos) out += ".0";
  return out;
}

/// Every seepage law, in documentation order ("none", no seepage force, is not a law).
inline std::vector<SeepageLawSpec> seepage_laws() {
  using scene::schema_detail::Key;
  using T = scene::ValueType;
  const std::string m = "soil.materials[].";
  std::vector<SeepageLawSpec> laws;
  laws.push_back(
      {"darcy_kozeny_carman",
       "Darcy with the Kozeny-Carman permeability (seed paper eq. 14): k = (1/180) n^3 / (1 - n)^2 "
       "(g / nu) d_e^2, a = 1 / k, b = 0.",
       {Key(m + "effective_diameter", T::Float)
            .unit("m")
            .required()
            .above(0)
            .doc("Effective grain diameter d_e of Kozeny-Carman (eq. 14).")},
       true,
       [](const SeepageLawInputs& in) {
         const double d = in["effective_diameter"], g = in.gravity, nu = in.kinematic_viscosity;
         return [=](double n) { return darcy_kozeny_carman(n, d, g, nu); };
       }});
  laws.push_back(
      {"darcy_conductivity",
       "Darcy with a given hydraulic conductivity k0 at n0; with variable permeability k follows "
       "the Kozeny-Carman porosity function, k(n) = k0 [n^3 / (1 - n)^2] / [n0^3 / (1 - n0)^2].",
       {Key(m + "hydraulic_conductivity", T::Float)
            .unit("m/s")
            .required()
            .above(0)
            .doc("Darcy hydraulic conductivity at porosity n0.")},
       false,
       [](const SeepageLawInputs& in) {
         const auto shape = [](double x) { return x * x * x / ((1.0 - x) * (1.0 - x)); };
         const double k0 = in["hydraulic_conductivity"], shape0 = shape(in.initial_porosity);
         return [=](double n) { return darcy_constant(k0 * shape(n) / shape0); };
       }});
  laws.push_back(
      {"forchheimer_den_adel",
       "Forchheimer with Den Adel's coefficients (seed paper eq. 15): a = alpha (1 - n)^2 / n^3 "
       "nu / (g d15^2), b = beta / n^2 / (g d15).",
       {Key(m + "d15", T::Float)
            .unit("m")
            .required()
            .above(0)
            .doc("Grain diameter d15 (15 % finer by weight) of Den Adel (eq. 15)."),
        Key(m + "den_adel_alpha", T::Float)
            .fallback(toml_float(kDenAdelAlpha))
            .above(0)
            .doc("Den Adel coefficient alpha of the linear term (eq. 15)."),
        Key(m + "den_adel_beta", T::Float)
            .fallback(toml_float(kDenAdelBeta))
            .above(0)
            .doc("Den Adel coefficient beta of the quadratic term (eq. 15).")},
       true,
       [](const SeepageLawInputs& in) {
         const double d15 = in["d15"], g = in.gravity, nu = in.kinematic_viscosity;
         const double alpha = in["den_adel_alpha"], beta = in["den_adel_beta"];
         return [=](double n) { return forchheimer_den_adel(n, d15, g, nu, alpha, beta); };
       }});
  laws.push_back(
      {"forchheimer_ergun",
       "Forchheimer with Ergun's (1952) packed-bed coefficients: a = 150 (1 - n)^2 / n^3 nu / "
       "(g d^2), b = 1.75 (1 - n) / n^3 / (g d) (Ergun, Chem. Eng. Prog. 48, 89-94).",
       {Key(m + "grain_diameter", T::Float)
            .unit("m")
            .required()
            .above(0)
            .doc("Mean grain diameter d of Ergun's equation.")},
       true,
       [](const SeepageLawInputs& in) {
         const double d = in["grain_diameter"], g = in.gravity, nu = in.kinematic_viscosity;
         return [=](double n) {
           SeepageCoefficients c;
           c.a = 150.0 * (1.0 - n) * (1.0 - n) / (n * n * n) * nu / (g * d * d);
           c.b = 1.75 * (1.0 - n) / (n * n * n) / (g * d);
           return c;
         };
       }});
  return laws;
}

/// The law named `name` among `laws`, or nullptr.
inline const SeepageLawSpec* find_seepage_law(const std::vector<SeepageLawSpec>& laws,
                                              const std::string& name) {
  for (const SeepageLawSpec& law : laws)
    if (law.name == name) return &law;
  return nullptr;
}

}  // namespace porosph::porous
