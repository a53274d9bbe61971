// Density diffusion term ("delta-SPH") of Molteni & Colagrossi (2009), "A simple procedure to
// improve the pressure evaluation in hydrodynamic context using the SPH", Comput. Phys. Commun.
// 180, 861-872, with a hydrostatic correction written in the enthalpy of the Tait EOS (below; to
// first order the correction of Fourtakas et al. 2019). It is added to the right-hand side of the
// continuity equation (eq. 2):
//   drho_a/dt = rho_a sum_b V_b v_ab . grad_a W_ab + D_a,
//   D_a = delta h c0 sum_b 2 (rho_b - rho_a - rho^H_ab) V_b (x_ba . grad_a W_ab) / (r^2 + eta^2)
// with x_ba = x_b - x_a, V_b = m_b / rho_b, eta^2 = 0.01 h^2, delta ~ 0.1 (dimensionless).
//
// Sign: grad_a W_ab = F(r) x_ab with F = (1/r) dW/dr <= 0, so x_ba . grad_a W_ab = -F r^2 >= 0 and
// D_a has the sign of rho_b - rho_a: a particle denser than its neighbours loses density, one
// lighter gains it. The term diffuses. (Written with x_ab = x_a - x_b, as in the neighbour list,
// the pair weight is -(x_ab . grad_a W_ab); the equivalent form with (rho_a - rho_b) x_ab is the
// one of TrixiParticles' DensityDiffusionMolteniColagrossi.)
//
// Hydrostatic correction: still weakly compressible water is in equilibrium when its enthalpy
// Phi(rho) = int dp / rho follows the gravity potential, Phi_b - Phi_a = g . x_ba (g the gravity
// vector; deeper b has the larger Phi). For the Tait EOS (eq. 4)
//   Phi(rho) = c0^2 / (gamma - 1) ((rho / rho0)^(gamma - 1) - 1),   dPhi/drho = c^2 / rho.
// The term diffuses the departure from that equilibrium, converted back to a density difference
// with kappa = d rho / dp = rho / c^2 taken as the pair mean:
//   rho_b - rho_a - rho^H_ab  ->  kappa_ab (Phi_b - Phi_a - g . x_ba),
//   kappa_ab = (kappa_a + kappa_b) / 2,  kappa = rho0 / (c0^2 s^(gamma - 2)),  s = rho / rho0.
// To first order in p / B it is the correction of Fourtakas, Dominguez, Vacondio & Rogers (2019),
// "Local Uniform Stencil (LUST) boundary condition ...", Comput. Fluids 190, 346-361 (DualSPHysics
// "DDT Fourtakas", rho^H_ab = rho0 ((1 + rho0 g . x_ba / B)^(1/gamma) - 1)), which is exact only
// where p_a = 0: below the surface its residual, a fraction (1 - 1/gamma) p_a / B of the summand
// (6 % at the bottom of a 0.6 m tank at c0 = 24 m/s), is a steady flux out of every truncated
// stencil (floor, free surface) that still water answers with a steady upward creep (measured
// 2.4e-5 m/s in the still-bed case; inside a porous bed the drag turns it into a head gradient of
// 1 %). This form vanishes exactly, at every depth, in the weakly compressible hydrostatic state
// p(d) = B ((1 + (gamma - 1)/gamma rho0 g d / B)^(gamma/(gamma - 1)) - 1), and its summand is
// exactly antisymmetric (see Conservation). Gravity enters as a vector: no "up" axis.
//
// Conservation: the uncorrected summand K_ab (rho_b - rho_a) with the symmetric pair weight
// K_ab = 2 (x_ba . grad_a W_ab) / (r^2 + eta^2) >= 0 is antisymmetric, so sum_a V_a D_a = 0: the
// term only moves density between particles, and what it gives one it takes from another. With the
// hydrostatic correction the bracket Phi_b - Phi_a - g . x_ba is antisymmetric and kappa_ab
// symmetric, so the corrected summand is antisymmetric too and the sum stays zero to round-off.
//
// Applied between water particles only: wall particles carry Adami-extrapolated densities that
// already follow the water (wall_boundary.h), and a flux to them would be lost rather than
// conserved. With the hydrostatic correction the truncated sum next to a wall is harmless (the
// DualSPHysics "DDT2" choice; "DDT2Full" would include the walls).
#pragma once

#include <cmath>

#include "fluid_solver/diffusion_state.h"
#include "fluid_solver/equation_of_state.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
class DensityDiffusion {
 public:
  /// What the pair term needs of one particle (diffusion_state.h).
  using State = DiffusionState;

  DensityDiffusion() = default;
  /// delta (0: off), smoothing length h, the EOS (rho0, c0, gamma, B) and the gravity vector.
  DensityDiffusion(double delta, double h, const TaitEos& eos, const sph::Vec<D>& gravity)
      : coefficient_(delta * h * eos.c0()),
        rho0_(eos.rho0()),
        gamma_(eos.gamma()),
        inv_gamma_1_(1.0 / (eos.gamma() - 1.0)),
        g_over_c0_2_(gravity / (eos.c0() * eos.c0())),
        seven_(eos.gamma() == 7.0) {}

  /// delta h c0 [m^2/s]: the caller multiplies the sum of pair_term() by it once.
  double coefficient() const { return coefficient_; }

  State state(double rho) const {
    const double s = rho / rho0_;
    if (seven_) {  // the common case, without pow()
      const double s2 = s * s;
      const double s5 = s2 * s2 * s;
      return {1.0 / s5, s5 * s};
    }
    return {std::pow(s, 2.0 - gamma_), std::pow(s, gamma_ - 1.0)};
  }

  /// (psi_b - psi_a) / c0^2 with psi = Phi - g . x, the departure potential: (Phi_b - Phi_a -
  /// g . x_ba) / c0^2 = (s_b^(g-1) - s_a^(g-1)) / (g - 1) + g . x_ab / c0^2 [-].
  double potential_difference(const State& a, const State& b, const sph::Vec<D>& x_ab) const {
    return (b.s_gamma_1 - a.s_gamma_1) * inv_gamma_1_ + g_over_c0_2_.dot(x_ab);
  }

  /// kappa_ab (Phi_b - Phi_a - g . x_ba) [kg/m^3]: the density difference of b over a that is not
  /// hydrostatic (zero in still water at every depth; rho_b - rho_a without gravity, to first
  /// order in p / B).
  double hydrostatic_departure(const State& a, const State& b, const sph::Vec<D>& x_ab) const {
    return kappa_c0_2(a, b) * potential_difference(a, b, x_ab);
  }

  /// Summand of D_a for neighbour b, without the factor delta h c0:
  ///   2 kappa_ab (psi_b - psi_a - (G_a + G_b)/2 . x_ba) (x_ba . grad_a W_ab) / (r^2 + eta^2) V_b,
  /// from `factor` = x_ab . grad_a W_ab / (r^2 + eta^2) (viscosity_morris.h
  /// regularised_gradient_factor, shared with the Morris term), the volume V_b = m_b / rho_b and
  /// the renormalised gradients G of psi / c0^2 (density_diffusion_gradient.h; zero: the plain
  /// bracket). The linear correction makes the summand vanish for any linear psi: a steady
  /// seepage flow as well as still water (Antuono et al. 2010). Still antisymmetric.
  double pair_term(const State& a, const State& b, double volume_b, const sph::Vec<D>& x_ab,
                   double factor, const sph::Vec<D>& gradient_a = sph::Vec<D>::Zero(),
                   const sph::Vec<D>& gradient_b = sph::Vec<D>::Zero()) const {
    const double weight = -2.0 * factor;                              // x_ba . grad W >= 0
    const double linear = 0.5 * (gradient_a + gradient_b).dot(x_ab);  // -(G_a + G_b)/2 . x_ba
    return volume_b * (weight * kappa_c0_2(a, b) * (potential_difference(a, b, x_ab) + linear));
  }

  /// The summand without the hydrostatic correction (Molteni & Colagrossi 2009 as such).
  double uncorrected_pair_term(double rho_a, double rho_b, double volume_b, double factor) const {
    return volume_b * (-2.0 * factor * (rho_b - rho_a));
  }

 private:
  /// kappa_ab c0^2 = rho0 (s_a^(2-g) + s_b^(2-g)) / 2 [kg/m^3].
  double kappa_c0_2(const State& a, const State& b) const {
    return 0.5 * rho0_ * (a.inv_s_gamma_2 + b.inv_s_gamma_2);
  }

  double coefficient_ = 0.0, rho0_ = 1000.0, gamma_ = 7.0, inv_gamma_1_ = 1.0 / 6.0;
  sph::Vec<D> g_over_c0_2_ = sph::Vec<D>::Zero();
  bool seven_ = true;
};

}  // namespace porosph::water
