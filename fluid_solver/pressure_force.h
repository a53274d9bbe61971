// Pressure gradient of eq. 3, first term, in one of two forms:
//
// Symmetric form of the seed paper (Monaghan 1992), the default:
//   (dv_a/dt)_p = - sum_b m_b (p_a + p_b) / (rho_a rho_b) grad_a W_ab.
// Antisymmetric in a, b (grad_a W_ab = -grad_b W_ba), so it conserves linear momentum exactly.
//
// Difference form, used with particle shifting (water.particle_shifting > 0; confined or periodic
// water):
//   (dv_a/dt)_p = - sum_b m_b (p_b - p_a) / (rho_a rho_b) grad_a W_ab.
// The two differ by 2 p_a / rho_a sum_b V_b grad_a W_ab = 2 p_a / rho_a grad C_a (C the particle
// concentration of particle_shifting.h): the symmetric form is not zeroth-order consistent, it
// pushes a particle with a force proportional to its absolute pressure wherever the particles are
// not uniform (the zero-order consistency residue of Wang & Hu 2025, arXiv:2507.18210: a
// non-physical energy loss). In a strained flow it turns kinetic energy into particle noise that
// the viscosity dissipates: the Taylor-Green vortex (Re 100) decayed 6.5 % too fast at L/50 and
// 3.9 % at L/100 with it, against -2.3 % and +0.6 % with the difference form (docs/verification.md;
// a background pressure makes the residue larger, +12.6 % with 1 kPa at L/50). Without shifting the
// residue's force is what keeps the particles ordered (it is repulsive where p_a > 0); with
// shifting the particles are kept uniform kinematically, and the consistent difference form is the
// one of the second-order WCSPH schemes of Negi & Ramachandran (2022), Phys. Fluids 34, 087125
// (arXiv:2107.11859). Not antisymmetric: momentum is conserved only to the discretisation error
// (the Taylor-Green box's momentum stays below 1e-4 of M U). In the pair loop the form is chosen
// by the sign that p_a enters with.
#pragma once

#include "sph/vector.h"

namespace porosph::water {

/// Acceleration of a due to b from the pressure term of eq. 3: `p_a` as it enters the pair,
/// +p_a for the symmetric form, -p_a for the difference form; the densities enter as their
/// inverses 1/rho (computed once per particle and step: no division per pair).
template <int D>
inline sph::Vec<D> pressure_acceleration(double m_b, double p_a, double p_b, double inv_rho_a,
                                         double inv_rho_b, const sph::Vec<D>& grad_w) {
  return (-m_b * (p_a + p_b) * (inv_rho_a * inv_rho_b)) * grad_w;
}

}  // namespace porosph::water
