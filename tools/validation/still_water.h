// Still weakly compressible water: the closed form that the hydrostatic checks compare with.
//
// Water at rest under gravity satisfies dp/dd = rho(p) g (d the depth below the free surface). With
// the Tait EOS of the solver (eq. 4), rho = rho0 (1 + p/B)^(1/gamma), B = rho0 c0^2 / gamma, the
// enthalpy Phi(p) = int_0^p dp'/rho(p') = (B / rho0) gamma/(gamma - 1) ((1 + p/B)^((gamma-1)/gamma)
// - 1) grows as g d, so
//   p(d) = B ((1 + (gamma - 1)/gamma rho0 g d / B)^(gamma/(gamma - 1)) - 1)
//        = rho0 g d (1 + g d / (2 c0^2) + O((g d / c0^2)^2)).
// Against the incompressible rho0 g d the weakly compressible water carries the extra weight of its
// own compression, a relative g d / (2 c0^2): 0.5 % at the bottom of a tank whose c0 = 10 sqrt(g
// H), 0.43 % at the floor of the still-bed case. It is the model (c0 finite), falls as 1 / c0^2,
// and the head that stays flat in still water is z + Phi(p) / g, not z + p / (rho0 g).
#pragma once

#include <cmath>

#include "fluid_solver/equation_of_state.h"

namespace porosph::validation {

/// The Tait EOS parameters of the water of a run.
struct StillWater {
  double rho0 = 1000.0, c0 = 20.0, gamma = 7.0, g = 9.81;

  double b() const { return rho0 * c0 * c0 / gamma; }

  /// p(d) of still water d below its free surface: the solver's own TaitEos::still_water_pressure.
  double pressure(double depth) const {
    return water::TaitEos(rho0, c0, gamma).still_water_pressure(depth, g);
  }

  /// Phi(p) / g: the depth of still water at pressure p, the pressure part of the head.
  double pressure_head(double p) const {
    const double r = (gamma - 1.0) / gamma;
    return b() / (rho0 * g * r) * (std::pow(1.0 + p / b(), r) - 1.0);
  }
};

}  // namespace porosph::validation
