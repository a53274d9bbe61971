// Mandel's problem (Mandel 1953; Cheng & Detournay 1988; Abousleiman et al. 1996): a saturated
// poroelastic sample -a <= x <= a in plane strain between two rigid, frictionless, impermeable
// plates that push with a force 2 F = 2 sigma0 a (per unit thickness), drained at x = +-a. With
// the drained and undrained Poisson ratios nu, nu_u, Skempton's B, the consolidation coefficient
// c and the roots alpha_n of tan(alpha) = (1 - nu) / (nu_u - nu) alpha, the pore pressure and the
// plates' displacement after a step load are
//   p(x, t) = 2 sigma0 B (1 + nu_u) / 3 sum_n sin(a_n) / (a_n - sin(a_n) cos(a_n))
//                                        (cos(a_n x / a) - cos(a_n)) exp(-a_n^2 c t / a^2),
//   u_y(b, t) = b sigma0 / G [-(1 - nu) / 2 + (1 - nu_u) sum_n sin(a_n) cos(a_n) /
//                                        (a_n - sin(a_n) cos(a_n)) exp(-a_n^2 c t / a^2)],
// so p = p0 = sigma0 B (1 + nu_u) / 3 at once, uniformly, and at the centre it first rises above
// p0 (the Mandel-Cryer effect) before it falls to 0. A load ramped over t_r is the Duhamel
// superposition: each exp(-a_n^2 T) becomes its ramp average (as in terzaghi.h) and the constant
// term takes the load's fraction L(t) / sigma0.
// For this model (docs/verification.md "Mandel's problem"): Biot coefficient 1 and Biot modulus
// K_w = rho_w c0^2 (the water fills the whole volume), so K_u = K + K_w, B = K_w / K_u, and
//   c = (k / gamma_w) K_w (K + 4 G / 3) / (K_u + 4 G / 3).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace porosph::validation {

class MandelClosedForm {
 public:
  /// Drained bulk and shear moduli K, G [Pa], water modulus K_w [Pa], hydraulic conductivity k
  /// [m/s], gamma_w [N/m^3], half-width a [m], plate stress sigma0 [Pa] (> 0: compression), ramp
  /// time t_r [s].
  MandelClosedForm(double bulk, double shear, double bulk_water, double conductivity,
                   double gamma_w, double half_width, double sigma0, double ramp_time)
      : shear_(shear), a_(half_width), sigma0_(sigma0) {
    const double undrained = bulk + bulk_water;
    nu_ = (3 * bulk - 2 * shear) / (2 * (3 * bulk + shear));
    nu_u_ = (3 * undrained - 2 * shear) / (2 * (3 * undrained + shear));
    b_ = bulk_water / undrained;
    c_ = conductivity / gamma_w * bulk_water * (bulk + 4 * shear / 3) / (undrained + 4 * shear / 3);
    ramp_ = c_ * ramp_time / (a_ * a_);
    const double slope = (1 - nu_) / (nu_u_ - nu_);  // tan(x) = slope x, one root per branch
    for (int n = 0; n < kTerms; ++n) {
      double lo = n * kPi + (n == 0 ? 1e-9 : 1e-12), hi = n * kPi + kPi / 2 - 1e-12;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (std::tan(mid) - slope * mid < 0 ? lo : hi) = mid;
      }
      roots_.push_back(0.5 * (lo + hi));
    }
  }

  double poisson() const { return nu_; }
  double undrained_poisson() const { return nu_u_; }
  double skempton() const { return b_; }
  double consolidation_coefficient() const { return c_; }
  /// The pore pressure a step load puts in at once, p0 = sigma0 B (1 + nu_u) / 3 [Pa].
  double initial_pressure() const { return sigma0_ * b_ * (1 + nu_u_) / 3; }
  /// T = c t / a^2 of a time t [s] since the load started.
  double time_factor(double t) const { return c_ * t / (a_ * a_); }
  double load_fraction(double tf) const {
    if (tf <= 0.0) return 0.0;
    return ramp_ > 0.0 ? std::min(tf / ramp_, 1.0) : 1.0;
  }
  /// Pore pressure [Pa] at x (0: the centre, a: the drained side), time factor tf.
  double pressure(double x, double tf) const {
    double sum = 0.0;
    for (const double r : roots_) {
      const double s = std::sin(r), co = std::cos(r);
      sum += s / (r - s * co) * (std::cos(r * x / a_) - co) * history(r, tf);
    }
    return 2 * initial_pressure() * sum;
  }
  /// Displacement [m] of the plate at height b (negative: down).
  double plate_displacement(double b, double tf) const {
    double sum = 0.0;
    for (const double r : roots_) {
      const double s = std::sin(r), co = std::cos(r);
      sum += s * co / (r - s * co) * history(r, tf);
    }
    return b * sigma0_ / shear_ * (-(1 - nu_) / 2 * load_fraction(tf) + (1 - nu_u_) * sum);
  }

 private:
  static constexpr double kPi = 3.14159265358979323846;
  static constexpr int kTerms = 400;  ///< alpha_400 ~ 1257: exp(-alpha^2 T) < 1e-6 from T = 1e-5

  /// exp(-alpha^2 T) for a step, its average over the ramp otherwise; 0 before the load.
  double history(double alpha, double tf) const {
    if (tf <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    if (ramp_ <= 0.0) return std::exp(-a2 * tf);
    return (std::exp(-a2 * (tf - std::min(tf, ramp_))) - std::exp(-a2 * tf)) / (a2 * ramp_);
  }

  double shear_, a_, sigma0_;
  double nu_ = 0, nu_u_ = 0, b_ = 0, c_ = 0, ramp_ = 0;
  std::vector<double> roots_;
};

}  // namespace porosph::validation
