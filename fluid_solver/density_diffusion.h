// Density diffusion term ("delta-SPH") of Molteni & Colagrossi (2009), "A simple procedure to
// improve the pressure evaluation in hydrodynamic context using the SPH", Comput. Phys. Commun.
// 180, 861-872, with the hydrostatic correction of Fourtakas, Dominguez, Vacondio & Rogers (2019),
// "Local Uniform Stencil (LUST) boundary condition ...", Comput. Fluids 190, 346-361, as
// DualSPHysics implements it (DensityDT = 2, "DDT Fourtakas"; there with |g_z| and z: here with the
// gravity vector). It is added to the right-hand side of the continuity equation (eq. 2):
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
// Hydrostatic correction: still water has grad p = rho g, so between two particles
//   p_b - p_a = rho0 g . (x_b - x_a)        (g the gravity vector: deeper b has the larger p),
// and inverting the Tait EOS (eq. 4) for that difference alone, as if p_a were 0 (Fourtakas et
// al.), gives the density difference that still water has between b and a:
//   rho^H_ab = rho0 ((1 + rho0 g . x_ba / B)^(1/gamma) - 1),   B = rho0 c0^2 / gamma.
// Subtracting it makes the pair summand vanish in still water, so the term no longer drives a
// flux out of a column whose kernel support is truncated (free surface, walls left out below).
// It is exact when p_a = 0 and first-order in p/B otherwise: with p_a > 0 the residual per pair is
// rho0 (1/gamma) (1 - 1/gamma) p_a (p_b - p_a) / B^2 + O(p^3/B^3), a fraction (1 - 1/gamma) p_a / B
// of the uncorrected summand (up to 6 % at the bottom of the tank case, 2 % in the dam break).
// Gravity enters as a vector: no "up" axis.
//
// Conservation: the uncorrected summand K_ab (rho_b - rho_a) with the symmetric pair weight
// K_ab = 2 (x_ba . grad_a W_ab) / (r^2 + eta^2) >= 0 is antisymmetric, so sum_a V_a D_a = 0: the
// term only moves density between particles, and what it gives one it takes from another. The
// correction is not exactly antisymmetric: rho^H_ab + rho^H_ba = rho0 (1/gamma)(1/gamma - 1)
// (rho0 g . x_ba / B)^2 + ..., a second-order leak that vanishes without gravity.
//
// Applied between water particles only: wall particles carry Adami-extrapolated densities that
// already follow the water (wall_boundary.h), and a flux to them would be lost rather than
// conserved. With the hydrostatic correction the truncated sum next to a wall is harmless (the
// DualSPHysics "DDT2" choice; "DDT2Full" would include the walls).
#pragma once

#include <cmath>

#include "fluid_solver/equation_of_state.h"
#include "sph/vector.h"

namespace porosph::fluid {

template <int D>
class DensityDiffusion {
 public:
  DensityDiffusion() = default;
  /// delta (0: off), smoothing length h, the EOS (rho0, c0, gamma, B) and the gravity vector.
  DensityDiffusion(double delta, double h, const TaitEos& eos, const sph::Vec<D>& gravity)
      : coefficient_(delta * h * eos.c0()),
        rho0_(eos.rho0()),
        inv_gamma_(1.0 / eos.gamma()),
        rho0_g_over_b_(eos.rho0() / eos.b() * gravity) {
    double c = 1.0;
    for (int n = 1; n <= 5; ++n) c_[n - 1] = c *= (inv_gamma_ - n) / (n + 1);
  }

  /// delta h c0 [m^2/s]: the caller multiplies the sum of pair_term() by it once.
  double coefficient() const { return coefficient_; }

  /// rho^H_ab = rho0 ((1 + rho0 g . x_ba / B)^(1/gamma) - 1), the still-water density of b minus
  /// that of a, by its binomial series to x^6 (a few multiplications, no transcendental call per
  /// pair). Within the kernel support |x| = |rho0 g . x_ba / B| <= gamma g 2h / c0^2: 2.8e-3 in
  /// the tank case, 6e-4 in the dam break, below 0.004 whenever c0 >= 10 sqrt(g H) and 2h <= H
  /// / 20. The first omitted term is 0.1 x^6 of the result: round-off (1e-13) up to |x| = 0.01 and
  /// 1e-7 at |x| = 0.1, far below the correction's own first-order error in p/B. Needs |x| < 1.
  double hydrostatic_difference(const sph::Vec<D>& x_ab) const {
    const double x = -rho0_g_over_b_.dot(x_ab);  // rho0 g . x_ba / B
    // (1 + x)^s - 1 = s x (1 + c1 x + ... + c5 x^5), c_n = prod_{i=1..n} (s - i) / (i + 1);
    // Estrin's scheme keeps the dependency chain short.
    const double x2 = x * x;
    const double low = 1.0 + c_[0] * x, mid = c_[1] + c_[2] * x, high = c_[3] + c_[4] * x;
    return rho0_ * inv_gamma_ * x * (low + x2 * (mid + x2 * high));
  }

  /// Summand of D_a for neighbour b, without the factor delta h c0:
  ///   2 (rho_b - rho_a - rho^H_ab) (x_ba . grad_a W_ab) / (r^2 + eta^2) m_b / rho_b,
  /// from `factor` = x_ab . grad_a W_ab / (r^2 + eta^2) (viscosity_morris.h
  /// regularised_gradient_factor, shared with the Morris term) and the volume V_b = m_b / rho_b.
  double pair_term(double rho_a, double rho_b, double volume_b, const sph::Vec<D>& x_ab,
                   double factor) const {
    const double weight = -2.0 * factor;  // x_ba . grad W >= 0
    return volume_b * (weight * (rho_b - rho_a - hydrostatic_difference(x_ab)));
  }

  /// The same summand without the hydrostatic correction (Molteni & Colagrossi 2009 as such).
  double uncorrected_pair_term(double rho_a, double rho_b, double volume_b, double factor) const {
    return volume_b * (-2.0 * factor * (rho_b - rho_a));
  }

 private:
  double coefficient_ = 0.0, rho0_ = 1000.0, inv_gamma_ = 1.0 / 7.0;
  double c_[5] = {};  ///< binomial series coefficients of hydrostatic_difference()
  sph::Vec<D> rho0_g_over_b_ = sph::Vec<D>::Zero();
};

}  // namespace porosph::fluid
