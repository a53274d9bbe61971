// SPH smoothing kernels, used as template parameters of the particle loops.
//
// Every kernel K<D> offers, for a smoothing length h fixed at construction:
//   w(r)            W(r, h)
//   dw_dr(r)        dW/dr
//   grad_factor(r)  (1/r) dW/dr, finite at r -> 0, so that grad_a W_ab = grad_factor(r) x_ab
//   gradient(x_ab, r)  grad_a W_ab with x_ab = x_a - x_b, r = |x_ab|
//   support()       radius beyond which W = 0 (2h for both kernels here)
//   gradient_scale() the factor applied to dw_dr and grad_factor (1 unless the kernel is
//                    lattice-normalised, sph/lattice_gradient.h)
#pragma once

#include <algorithm>
#include <cmath>

#include "sph/vector.h"

namespace porosph::sph {

/// Cubic B-spline (M4) kernel of Monaghan (1992), "Smoothed particle hydrodynamics",
/// Annu. Rev. Astron. Astrophys. 30, 543-574; the kernel of the seed paper. With q = r/h:
///   W = sigma (1 - 3/2 q^2 + 3/4 q^3)   0 <= q < 1
///   W = sigma / 4 (2 - q)^3             1 <= q < 2,   0 beyond,
/// sigma = 10 / (7 pi h^2) in 2D and 1 / (pi h^3) in 3D.
template <int D>
class CubicSpline {
  static_assert(D == 2 || D == 3, "CubicSpline: D must be 2 or 3");

 public:
  static constexpr const char* kName = "cubic_spline";
  static constexpr int kDim = D;

  /// gradient_scale multiplies dW/dr (and only dW/dr): 1 is Monaghan's kernel.
  explicit CubicSpline(double h, double gradient_scale = 1.0)
      : h_(h),
        inv_h_(1.0 / h),
        sigma_(D == 2 ? 10.0 / (7.0 * M_PI * h * h) : 1.0 / (M_PI * h * h * h)),
        gradient_scale_(gradient_scale),
        sigma_grad_(sigma_ * gradient_scale) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double gradient_scale() const { return gradient_scale_; }

  /// Branch-free like grad_factor().
  double w(double r) const {
    const double q = r * inv_h_;
    const double t = std::max(0.0, 2.0 - q);  // this argument order maps a NaN q to 0
    const double inner = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
    const double outer = 0.25 * t * t * t;
    return sigma_ * (q < 1.0 ? inner : outer);
  }

  double dw_dr(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_grad_ * inv_h_ * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) {
      const double t = 2.0 - q;
      return -0.75 * sigma_grad_ * inv_h_ * t * t;
    }
    return 0.0;
  }

  /// Both branches are evaluated and one is selected (no data-dependent jump: the inner/outer
  /// test is a coin toss per pair in a neighbour loop); the outer one is guarded against q = 0.
  double grad_factor(double r) const {
    const double q = r * inv_h_;
    const double t = std::max(0.0, 2.0 - q);  // this argument order maps a NaN q to 0
    const double inner = -3.0 + 2.25 * q;
    const double outer = -0.75 * t * t / std::max(1.0, q);
    return sigma_grad_ * inv_h_ * inv_h_ * (q < 1.0 ? inner : outer);
  }

  Vec<D> gradient(const Vec<D>& x_ab, double r) const { return grad_factor(r) * x_ab; }

 private:
  double h_, inv_h_, sigma_, gradient_scale_, sigma_grad_;
};

/// Wendland C2 kernel (Wendland 1995, Adv. Comput. Math. 4, 389-396), in the support-2h form of
/// Dehnen & Aly (2012) / DualSPHysics. With q = r/h:
///   W = alpha (1 - q/2)^4 (2 q + 1)    0 <= q < 2,   0 beyond,
/// alpha = 7 / (4 pi h^2) in 2D and 21 / (16 pi h^3) in 3D;  dW/dr = -5 alpha q (1 - q/2)^3 / h.
template <int D>
class WendlandC2 {
  static_assert(D == 2 || D == 3, "WendlandC2: D must be 2 or 3");

 public:
  static constexpr const char* kName = "wendland_c2";
  static constexpr int kDim = D;

  /// gradient_scale multiplies dW/dr (and only dW/dr): 1 is Wendland's kernel.
  explicit WendlandC2(double h, double gradient_scale = 1.0)
      : h_(h),
        inv_h_(1.0 / h),
        alpha_(D == 2 ? 7.0 / (4.0 * M_PI * h * h) : 21.0 / (16.0 * M_PI * h * h * h)),
        gradient_scale_(gradient_scale),
        alpha_grad_(alpha_ * gradient_scale) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double gradient_scale() const { return gradient_scale_; }

  double w(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    const double t2 = t * t;
    return alpha_ * t2 * t2 * (2.0 * q + 1.0);
  }

  double dw_dr(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * alpha_grad_ * inv_h_ * q * t * t * t;
  }

  double grad_factor(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * alpha_grad_ * inv_h_ * inv_h_ * t * t * t;
  }

  Vec<D> gradient(const Vec<D>& x_ab, double r) const { return grad_factor(r) * x_ab; }

 private:
  double h_, inv_h_, alpha_, gradient_scale_, alpha_grad_;
};

}  // namespace porosph::sph
