// Artificial viscosity of Monaghan (1992), Annu. Rev. Astron. Astrophys. 30, 543-574, eq. 4.1
// there:
//   (dv_a/dt)_av = - sum_b m_b Pi_ab grad_a W_ab,
//   Pi_ab = (-alpha c_ab mu_ab + beta mu_ab^2) / rho_ab   if v_ab . x_ab < 0 (approaching), else 0,
//   mu_ab = h v_ab . x_ab / (r_ab^2 + eta^2),  c_ab = (c_a + c_b)/2,  rho_ab = (rho_a + rho_b)/2,
// eta^2 = 0.01 h^2. Pi_ab >= 0, so the force pushes approaching particles apart and is zero for
// receding ones: purely dissipative.
//
// Inside soil the seepage drag takes over (water.artificial_viscosity_in_soil = "drag_limited",
// the default; docs/coupling.md). The term is a numerical dissipation of kernel-scale noise; it
// acts like a kinematic viscosity nu = alpha h c0 / (2 (D + 2)) (Monaghan 2005, Rep. Prog. Phys.
// 68, 1703, section 4.3), which damps a mode of wavenumber pi / h at the rate
//   r_av = nu (pi / h)^2 = alpha c0 pi^2 / (2 (D + 2) h).
// The drag damps every relative velocity at the rate lambda_a the coupler reports for the particle
// (the derivative of eq. 13-17 along v_r). With the share s_a = min(1, lambda_a / r_av) of the
// term removed, each pair keeping 1 - (s_a + s_b) / 2 of Pi_ab (walls: 1 - s_a), the damping of
// kernel-scale noise is r_av (1 - s_a) + lambda_a >= r_av at every particle: never less than the
// artificial viscosity's own. Where the drag is stronger than r_av the term is off, so it adds no
// Brinkman-like viscosity (nu ~ 1000 times water's) to the Darcy flow: under the seepage weir of
// docs/verification.md it took 2.0 % off the discharge at dp 10 mm (-9.61 % against -7.58 %).
// But r_av grows as h falls, so the share left on grows with the resolution: under the weir
// (lambda = 196 1/s, alpha 0.05, c0 20 m/s) r_av = 103 / 205 / 411 1/s at dp 10 / 5 / 2.5 mm
// leaves 0 / 5 / 52 % of the term on, and the discharge fell by 2.8 points from dp 5 to 2.5 mm.
// With "drag_replaced" the term keeps 1 - s_a of the drag weight of drag_weight.h instead, which
// is 1 inside soil at every h: the noise there is damped by the drag alone (lambda_a), which in
// sand is well above r_av; in weakly dragged coarse rockfill "drag_limited" is the safer choice.
#pragma once

#include <algorithm>
#include <cmath>

#include "sph/vector.h"

namespace porosph::water {

struct ArtificialViscosity {
  double alpha = 0.05, beta = 0.0, h = 0.0;
  /// r_av [1/s]: the damping rate of a kernel-scale mode (above); 0 switches off the drag limit.
  double damping_rate = 0.0;

  /// r_av of alpha, c0 and h in D dimensions.
  static double kernel_damping_rate(double alpha, double c0, double h, int dimension) {
    constexpr double kPi = 3.14159265358979323846;
    return alpha * c0 * kPi * kPi / (2.0 * (dimension + 2) * h);
  }

  /// The drag share s_a = min(1, lambda_a / r) of a drag rate lambda_a >= 0 [1/s] against the rate
  /// r >= 0: 0 without drag; 1 wherever there is drag when r = 0 (alpha = 0: no kernel-scale
  /// damping to compare with). Also used by the hydrostatic difference form (water_params.h).
  static double drag_share(double drag_rate, double rate) {
    if (!(drag_rate > 0.0)) return 0.0;
    return rate > 0.0 ? std::min(1.0, drag_rate / rate) : 1.0;
  }

  /// s_a = min(1, lambda_a / r_av): the share of the term the drag replaces; 0 when the drag limit
  /// is off.
  double cut(double drag_rate) const {
    return damping_rate > 0.0 ? drag_share(drag_rate, damping_rate) : 0.0;
  }

  /// Pi_ab from v_ab . x_ab, 1 / (r_ab^2 + eta^2) (shared with the other regularised terms of
  /// the pair), the mean sound speed and the mean density of the pair.
  double pi(double v_dot_x, double inv_r2_eta2, double c_mean, double rho_mean) const {
    if (v_dot_x >= 0.0) return 0.0;
    const double mu = h * v_dot_x * inv_r2_eta2;
    return (-alpha * c_mean * mu + beta * mu * mu) / rho_mean;
  }

  /// Acceleration of a due to b; `keep` = 1 - (s_a + s_b) / 2 of the pair (1 without soil).
  template <int D>
  sph::Vec<D> acceleration(double m_b, const sph::Vec<D>& v_ab, const sph::Vec<D>& x_ab,
                           double inv_r2_eta2, double c_a, double c_b, double rho_a, double rho_b,
                           const sph::Vec<D>& grad_w, double keep = 1.0) const {
    const double p = pi(v_ab.dot(x_ab), inv_r2_eta2, 0.5 * (c_a + c_b), 0.5 * (rho_a + rho_b));
    return (-m_b * p * keep) * grad_w;
  }
};

}  // namespace porosph::water
