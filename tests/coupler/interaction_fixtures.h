// Hand-made scenes and overlap sets for the soil-water interaction tests (no processes), and the
// formulas of seed eq. 13-15 and the cubic spline written out independently of the code under test.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "proto/coupling_client.h"
#include "scene/scene.h"

namespace porosph::testing {

constexpr double kPi = 3.14159265358979323846;

/// A 2D scene with water (rho0 1000, mu 1e-3: nu = 1e-6) and soil, dp 0.01, h 0.012, g = 9.81
/// downwards, domain [0, 1]^2, no periodic axis, and one material `m`.
inline scene::Scene two_phase_scene(const scene::SoilMaterial& m, int dimension = 2) {
  scene::Scene s;
  s.name = "interaction_test";
  s.run.dimension = dimension;
  s.run.dp = 0.01;
  s.run.h_factor = 1.2;
  s.run.c_a = 0.25;
  s.run.gravity.assign(dimension, 0.0);
  s.run.gravity[dimension - 1] = -9.81;
  s.run.periodic.assign(dimension, false);
  s.domain.min.assign(dimension, 0.0);
  s.domain.max.assign(dimension, 1.0);
  s.water.emplace();
  s.water->rho0 = 1000.0;
  s.water->viscosity = 1.0e-3;
  s.soil.emplace();
  s.soil->materials.push_back(m);
  return s;
}

inline scene::SoilMaterial kozeny_carman_material(double n0 = 0.4, double d_e = 1e-3) {
  scene::SoilMaterial m;
  m.name = "sand";
  m.density = 1600.0;
  m.porosity = n0;
  m.seepage = "darcy_kozeny_carman";
  m.seepage_parameters = {{"effective_diameter", d_e}};
  m.variable_permeability = false;
  return m;
}

inline scene::SoilMaterial conductivity_material(double k = 1e-3) {
  scene::SoilMaterial m = kozeny_carman_material();
  m.name = "silt";
  m.seepage = "darcy_conductivity";
  m.seepage_parameters = {{"hydraulic_conductivity", k}};
  return m;
}

inline scene::SoilMaterial den_adel_material(double d15 = 5e-3) {
  scene::SoilMaterial m = kozeny_carman_material();
  m.name = "gravel";
  m.seepage = "forchheimer_den_adel";
  m.seepage_parameters = {{"d15", d15}, {"den_adel_alpha", 150.0}, {"den_adel_beta", 0.4}};
  return m;
}

/// Appends one particle to an overlap set (porosity/material only for soil: material >= 0).
inline void add_particle(coupling::StepState& s, const std::vector<double>& x,
                         const std::vector<double>& v, double density, double mass,
                         double porosity = 0.0, int material = -1) {
  s.overlap_id.push_back(static_cast<std::int64_t>(s.overlap_id.size()));
  s.overlap_position.insert(s.overlap_position.end(), x.begin(), x.end());
  s.overlap_velocity.insert(s.overlap_velocity.end(), v.begin(), v.end());
  s.overlap_density.push_back(density);
  s.overlap_mass.push_back(mass);
  if (material >= 0) {
    s.overlap_porosity.push_back(porosity);
    s.overlap_material.push_back(material);
  }
}

/// 2D cubic spline (Monaghan 1992), written out: sigma = 10 / (7 pi h^2).
inline double cubic_spline_2d(double r, double h) {
  const double q = r / h, sigma = 10.0 / (7.0 * kPi * h * h);
  if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  if (q < 2.0) return 0.25 * sigma * (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}

/// Eq. 14: Kozeny-Carman conductivity.
inline double kozeny_carman_k(double n, double d, double g, double nu) {
  return n * n * n / (180.0 * (1.0 - n) * (1.0 - n)) * g / nu * d * d;
}

/// Relative difference |a - b| / max(|b|, tiny).
inline double relative(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

}  // namespace porosph::testing
