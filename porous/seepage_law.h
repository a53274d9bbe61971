// The seepage force of the soil-water interaction, seed paper eq. 13-15 and 20 (section 2.3-2.4):
//   f_ia = gamma_w (a v_r + b |v_r| v_r),   v_r = v_water - v_soil,   gamma_w = rho0_w |g|  (eq.
//   13)
// a force per unit volume of soil [N/m^3] acting on the soil (the water feels the reaction). The
// coefficients a [s/m], b [s^2/m^2] come from the soil material's seepage law
// (porous/permeability.h), evaluated at the porosity n of the soil particle: its current
// porosity (eq. 20) when the material has variable_permeability, else its initial porosity n0.
//   "darcy_kozeny_carman"   a = 1/k, k from Kozeny-Carman (eq. 14, effective_diameter), b = 0
//   "darcy_conductivity"    a = 1/k, b = 0, k = hydraulic_conductivity at n0; with variable
//                           permeability k follows the Kozeny-Carman porosity function:
//                           k(n) = k0 [n^3 / (1 - n)^2] / [n0^3 / (1 - n0)^2]
//   "forchheimer_den_adel"  a, b of Den Adel (eq. 15, d15, den_adel_alpha, den_adel_beta)
//   "none"                  no seepage force (the coupler skips the force of such pairs)
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "porous/permeability.h"
#include "porous/porosity.h"
#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::porous {

/// Eq. 13 with the unit weight folded into the coefficients: f = A v_r + B |v_r| v_r, where
/// A = gamma_w a [kg/(m^3 s)] and B = gamma_w b [kg/m^4].
template <int D>
sph::Vec<D> seepage_force(double weighted_a, double weighted_b,
                          const sph::Vec<D>& relative_velocity) {
  if (weighted_b == 0.0) return weighted_a * relative_velocity;  // Darcy: no |v_r| needed
  return (weighted_a + weighted_b * relative_velocity.norm()) * relative_velocity;
}

/// The derivative of eq. 13 along v_r, d|f| / d|v_r| = A + 2 B |v_r| [kg/(m^3 s)]: the rate of
/// the implicit drag (sph/integrator.h) per unit volume (Darcy: A).
template <int D>
double seepage_rate_coefficient(double weighted_a, double weighted_b,
                                const sph::Vec<D>& relative_velocity) {
  if (weighted_b == 0.0) return weighted_a;
  return weighted_a + 2.0 * weighted_b * relative_velocity.norm();
}

/// The seepage law of one soil material: a and b of eq. 13 as functions of a particle's porosity.
class SeepageLaw {
 public:
  enum class Kind { None, DarcyKozenyCarman, DarcyConductivity, ForchheimerDenAdel };

  /// `gravity` = |g| [m/s^2] and `kinematic_viscosity` = nu of the water [m^2/s], both > 0 for
  /// an active law. Throws std::invalid_argument naming the material on an unknown law or a
  /// parameter the law needs that is not positive.
  static SeepageLaw from_material(const scene::SoilMaterial& m, double gravity,
                                  double kinematic_viscosity) {
    SeepageLaw law;
    law.initial_porosity_ = m.porosity;
    law.variable_ = m.variable_permeability;
    law.gravity_ = gravity;
    law.nu_ = kinematic_viscosity;
    auto need = [&](double value, const char* what) {
      if (!(value > 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument("soil material '" + m.name + "': seepage '" + m.seepage +
                                    "' needs " + what + " > 0");
      }
    };
    if (m.seepage == "none") return law;
    if (!(m.porosity > 0.0 && m.porosity < 1.0)) {
      throw std::invalid_argument("soil material '" + m.name + "': seepage '" + m.seepage +
                                  "' needs 0 < porosity < 1");
    }
    need(gravity, "gravity |g|");
    if (m.seepage == "darcy_kozeny_carman") {
      law.kind_ = Kind::DarcyKozenyCarman;
      need(kinematic_viscosity, "a water viscosity (water.viscosity)");
      need(m.effective_diameter, "effective_diameter");
      law.diameter_ = m.effective_diameter;
    } else if (m.seepage == "darcy_conductivity") {
      law.kind_ = Kind::DarcyConductivity;
      need(m.hydraulic_conductivity, "hydraulic_conductivity");
      law.conductivity_ = m.hydraulic_conductivity;
    } else if (m.seepage == "forchheimer_den_adel") {
      law.kind_ = Kind::ForchheimerDenAdel;
      need(kinematic_viscosity, "a water viscosity (water.viscosity)");
      need(m.d15, "d15");
      law.diameter_ = m.d15;
      law.alpha_ = m.den_adel_alpha;
      law.beta_ = m.den_adel_beta;
    } else {
      throw std::invalid_argument("soil material '" + m.name + "': unknown seepage law '" +
                                  m.seepage + "'");
    }
    return law;
  }

  Kind kind() const { return kind_; }
  bool active() const { return kind_ != Kind::None; }

  /// The porosity the coefficients use for a particle whose current porosity is
  /// `particle_porosity`: that porosity with variable permeability (clamped to the admissible
  /// range of porous/porosity.h, where the coefficients stay finite), else n0.
  double porosity_used(double particle_porosity) const {
    if (!variable_) return initial_porosity_;
    const PorosityRange range;
    if (!(particle_porosity >= range.min)) return range.min;  // also NaN
    return std::min(particle_porosity, range.max);
  }

  /// a and b of eq. 13 for a particle of current porosity `particle_porosity` ({0, 0} if none).
  SeepageCoefficients coefficients(double particle_porosity) const {
    const double n = porosity_used(particle_porosity);
    switch (kind_) {
      case Kind::None:
        return {};
      case Kind::DarcyKozenyCarman:
        return darcy_kozeny_carman(n, diameter_, gravity_, nu_);
      case Kind::DarcyConductivity:
        return darcy_constant(conductivity_ * kozeny_carman_shape(n) /
                              kozeny_carman_shape(initial_porosity_));
      case Kind::ForchheimerDenAdel:
        return forchheimer_den_adel(n, diameter_, gravity_, nu_, alpha_, beta_);
    }
    return {};
  }

  /// n^3 / (1 - n)^2, the porosity dependence of the Kozeny-Carman conductivity (eq. 14).
  static double kozeny_carman_shape(double n) { return n * n * n / ((1.0 - n) * (1.0 - n)); }

 private:
  Kind kind_ = Kind::None;
  double initial_porosity_ = 0.4;
  bool variable_ = false;
  double gravity_ = 0.0, nu_ = 0.0;
  double diameter_ = 0.0;      ///< d_e (Kozeny-Carman) or d15 (Den Adel) [m]
  double conductivity_ = 0.0;  ///< k at n0 [m/s]
  double alpha_ = kDenAdelAlpha, beta_ = kDenAdelBeta;
};

}  // namespace porosph::porous
