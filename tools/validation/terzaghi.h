// Terzaghi's 1D consolidation (Terzaghi 1943; Verruijt, "Soil Mechanics", 2012, ch. 15) of a
// column of height H on an impermeable base, drained at its top, under a surface load that grows
// linearly from 0 to p0 over t_r (t_r = 0: a step). With the time factor T = c_v t / H^2 and the
// depth z' below the drained top, the step solution (excess pore pressure per unit of the pore
// pressure the load puts in at once, B p0) is
//   u_step(z', T) = sum_m (2 / M_m) sin(M_m z' / H) exp(-M_m^2 T),   M_m = pi (2 m + 1) / 2,
// and a ramp is its Duhamel superposition, each term's exp(-M^2 T) replaced by
//   g_m(T) = [exp(-M^2 (T - min(T, T_r))) - exp(-M^2 T)] / (M^2 T_r).
// The settlement follows from the effective stress sigma' = L(t) - u and sigma' = eps / m_v:
//   s(T) = m_v H [L(T) - B p0 sum_m (2 / M_m^2) g_m(T)],
// and the degree of consolidation U = (s - s_undrained) / (s_drained - s_undrained), with
// s_drained = m_v L H and s_undrained = (1 - B) m_v L H, is
//   U(T) = 1 - sum_m (2 / M_m^2) g_m(T) / (L(T) / p0).
// For this model (docs/verification.md): B = 1 / (1 + 1 / (m_v K_w)), c_v = k / (gamma_w (m_v +
// 1 / K_w)), K_w = rho_w c^2, m_v = 1 / (K + 4 G / 3).
#pragma once

#include <algorithm>
#include <cmath>

namespace porosph::validation {

class TerzaghiColumn {
 public:
  /// height H [m], c_v [m^2/s], B [-], m_v [1/Pa], p0 [Pa], ramp time t_r [s].
  TerzaghiColumn(double height, double cv, double b, double mv, double p0, double ramp_time)
      : h_(height), cv_(cv), b_(b), mv_(mv), p0_(p0), ramp_(cv * ramp_time / (height * height)) {}

  /// The time factor T = c_v t / H^2 of a time t [s] since the load started.
  double time_factor(double t) const { return cv_ * t / (h_ * h_); }
  /// The load L(T) / p0.
  double load_fraction(double tf) const { return ramp_ > 0.0 ? std::min(tf / ramp_, 1.0) : 1.0; }
  /// Excess pore pressure [Pa] at depth `depth` below the drained top, time factor tf.
  double excess_pressure(double depth, double tf) const {
    double sum = 0.0;
    for (int m = 0; m < kTerms; ++m) {
      const double M = kPi * (2 * m + 1) / 2;
      sum += 2.0 / M * std::sin(M * depth / h_) * history(M, tf);
    }
    return b_ * p0_ * sum;
  }
  /// Settlement [m] of the top since the load started.
  double settlement(double tf) const {
    return mv_ * h_ * p0_ * (load_fraction(tf) - b_ * storage_sum(tf));
  }
  /// Degree of consolidation U (0 undrained, 1 drained); 0 before the load.
  double degree(double tf) const {
    const double load = load_fraction(tf);
    return load > 0.0 ? 1.0 - storage_sum(tf) / load : 0.0;
  }

 private:
  static constexpr double kPi = 3.14159265358979323846;
  static constexpr int kTerms = 400;  ///< the series converges for T > 0; 400 terms: < 1e-6 at T
                                      ///< = 1e-4 and z' = H

  /// g_m(T): exp(-M^2 T) for a step, its ramp average otherwise.
  double history(double M, double tf) const {
    if (tf <= 0.0) return 0.0;
    const double M2 = M * M;
    if (ramp_ <= 0.0) return std::exp(-M2 * tf);
    return (std::exp(-M2 * (tf - std::min(tf, ramp_))) - std::exp(-M2 * tf)) / (M2 * ramp_);
  }
  /// sum_m (2 / M_m^2) g_m(T).
  double storage_sum(double tf) const {
    double sum = 0.0;
    for (int m = 0; m < kTerms; ++m) {
      const double M = kPi * (2 * m + 1) / 2;
      sum += 2.0 / (M * M) * history(M, tf);
    }
    return sum;
  }

  double h_, cv_, b_, mv_, p0_, ramp_;
};

}  // namespace porosph::validation
