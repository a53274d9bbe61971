// The pressure gradient of eq. 3 inside soil in the hydrostatic difference form
// (water.pressure_gradient_in_soil = "hydrostatic_difference"; docs/coupling.md):
//   grad p_a = sum_b V_b [(p_b - p_a) - rho0 g . (x_b - x_a)] grad_a W_ab + rho0 g,
//   (dv_a/dt)_p = -grad p_a / rho_a,
// that is, the difference form (pressure_force.h) of the departure p - rho0 g . x from the
// still-water pressure, plus that pressure's exact gradient. With L_a = sum_b V_b (x_b - x_a) (x)
// grad_a W_ab it equals L_a grad p + (I - L_a) rho0 g for a linear p: exact for still water at any
// particle arrangement, and elsewhere the operator's error multiplies only the departure.
//
// Why. In a Darcy flow the drag slaves each particle's velocity to the pressure gradient:
// v = -(k / gamma_w)(grad p - rho g), g the gravity vector, so the seepage gradient is what
// remains of grad p after rho g. Under the seepage weir (docs/verification.md) it is ~3 % of rho g.
// An operator error eps in the vertical (L_zz = 1 + eps) therefore becomes an error eps / 0.03 in
// the vertical seepage: with the symmetric form and the particle gradient, L_zz - L_xx reached
// 0.006 on the lattice that the flow had strained, and the vertical Darcy flow came out 8 % too
// slow (a fit of the head field in the pools' entry and exit regions). The symmetric form also
// pushes each particle with 2 p_a grad C_a (pressure_force.h): with the drag holding the particles
// that drift rearranged the sand's square water lattice into a hexagon-like packing within ~0.5 s
// at dp 5 mm (6th neighbour 1.41 -> 1.17 dp), which took 12-15 % of dh off the heads. With this
// form the lattice stays square (1.38 dp at 1.5 s), the heads are within 0.35 % of the reference
// pressure and the local Darcy law holds in x and z (0.995-1.005).
//
// Where. A particle uses w_a = s_a c_a of this form and 1 - w_a of the symmetric one:
// - s_a = min(1, lambda_a / (0.5 lambda_max,a)), lambda_a the particle's drag rate from the coupler
//   and lambda_max,a the largest over it and its water neighbours: 1 inside soil, a ramp over the
//   soil's surface layer, where the kernel sum of the soil thins out, and 0 without drag. The form
//   needs the drag to hold the particles, since it has no ordering force; it is blended in over the
//   surface layer, so that a particle's force does not jump where it first feels drag (a switch
//   there instead, tried on the seepage weir: exit gradient +11.2 / +3.6 % at dp 10 / 5 mm against
//   the ramp's +5.8 / +1.3 %, docs/verification.md). The ramp is a fraction of the soil's own drag,
//   so it spans the same kernel-scale layer at every resolution. Until 2026-12-06 s_a was the drag
//   share min(1, lambda_a / r_av) of artificial_viscosity.h, r_av = alpha c0 pi^2 / (2 (D + 2) h):
//   it fell with h inside the soil (0.48 under the weir at dp 2.5 mm), so the symmetric form's
//   errors came back as the resolution was refined (exit gradient -3.8 % at dp 5 mm, -16 % at
//   dp 2.5 mm; with c0 doubled at dp 5 mm -12.6 %);
// - c_a, the completeness of the support from t = tr(L_a) / D: 0 at t <= 0.90 (a free surface, a
//   seepage face: there the still-water continuation of the missing neighbours is wrong, and the
//   seepage embankment blew up within 0.02 s without this), 1 at t >= 0.97, linear between, 0 above
//   1.1 (a clump), as particle_gradient.h.
// Not antisymmetric in a, b: the water's momentum is not conserved pair by pair inside soil
// (the drag exchange with the soil still is; docs/coupling.md, the external-impulse ledger).
#pragma once

#include <algorithm>

#include "fluid_solver/drag_weight.h"
#include "fluid_solver/particle_gradient.h"
#include "sph/vector.h"

namespace porosph::water {

/// The sums of one water particle's pressure term over its neighbours, in both forms, water and
/// wall neighbours apart (the walls' share is booked as an external impulse).
template <int D>
struct SoilPressureSums {
  using Vec = sph::Vec<D>;
  Vec symmetric[2] = {Vec::Zero(), Vec::Zero()};  ///< [water, walls]: pressure_force.h's pairs
  Vec departure[2] = {Vec::Zero(), Vec::Zero()};  ///< -sum m_b [(p_b - p_a) - rho0 g.x_ba] ...
  double trace = 0.0;                             ///< tr(L_a) over both

  /// Adds neighbour b (`wall`: a wall particle): `symmetric_term` its term of pressure_force.h,
  /// `rho0_g_dot_x_ab` = rho0 g . (x_a - x_b), grad_w = grad_factor x_ab (grad_factor: dW/dr / r
  /// with the kernel gradient's scale).
  void add(bool wall, const Vec& symmetric_term, double m_b, double p_a, double p_b,
           double inv_rho_a, double inv_rho_b, double rho0_g_dot_x_ab, double volume_b,
           double grad_factor, double r, const Vec& grad_w) {
    symmetric[wall] += symmetric_term;
    departure[wall] -= (m_b * (p_b - p_a + rho0_g_dot_x_ab) * inv_rho_a * inv_rho_b) * grad_w;
    trace -= volume_b * grad_factor * r * r;
  }

  /// c_a of t = tr(L_a) / D (above), with the thresholds of the per-particle gradient.
  static double completeness(double t) {
    using G = ParticleGradient;
    if (!(t > G::kFrom) || t > G::kMax) return 0.0;
    return std::min(1.0, (t - G::kFrom) / (G::kFull - G::kFrom));
  }

  struct Split {
    Vec total;     ///< the pressure acceleration of the particle
    Vec walls;     ///< its wall neighbours' share
    Vec residual;  ///< total - walls - the symmetric water pairs: not antisymmetric
  };
  /// s_a (above; drag_weight.h) of the particle's drag rate lambda_a >= 0 and the largest drag
  /// rate over it and its water neighbours, lambda_max >= lambda_a [1/s]: 0 without drag.
  static double drag_weight(double drag_rate, double neighbour_max) {
    return DragWeight::of(drag_rate, neighbour_max);
  }

  /// The blend with weight w = s_a c_a: drag weight s_a (drag_weight()), 1 / rho_a, rho0 g.
  Split split(double drag_weight, double inv_rho_a, const Vec& rho0_g) const {
    const double w = drag_weight * completeness(trace / D);
    Split out;
    out.walls = (1.0 - w) * symmetric[1] + w * departure[1];
    out.residual = w * (departure[0] - inv_rho_a * rho0_g - symmetric[0]);
    out.total = symmetric[0] + out.walls + out.residual;
    return out;
  }
};

}  // namespace porosph::water
