#include "tools/validation/rectangular_dam_exact.h"

#include <cmath>
#include <stdexcept>

#include "tools/validation/rectangular_dam.h"

namespace porosph::validation {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

/// int_a^b f by tanh-sinh quadrature (step 1/64: double precision for these integrands).
template <class F>
double tanh_sinh(const F& f, double a, double b) {
  const double h = 1.0 / 64;
  double sum = 0.0;
  for (int k = -400; k <= 400; ++k) {
    const double u = kHalfPi * std::sinh(k * h), ch = std::cosh(u);
    const double weight = kHalfPi * std::cosh(k * h) / (ch * ch);
    const double x = 0.5 * (a + b) + 0.5 * (b - a) * std::tanh(u);
    if (weight < 1e-300 || x <= a || x >= b) continue;
    sum += weight * f(x);
  }
  return sum * h * 0.5 * (b - a);
}

/// K(m) of parameter m < 1.
double k_param(double m) { return std::comp_ellint_1(std::sqrt(m)); }
/// K(cos^2 p), with its logarithmic limit ln(4 / sin p) where cos p rounds to 1.
double k_cos2(double p) {
  return p < 1e-5 ? std::log(4.0 / std::sin(p)) : std::comp_ellint_1(std::cos(p));
}
/// K(sin^2 p), with its limit ln(4 / cos p) near pi/2.
double k_sin2(double p) {
  const double q = kHalfPi - p;
  return q < 1e-5 ? std::log(4.0 / std::sin(q)) : std::comp_ellint_1(std::sin(p));
}

double length_integral(double a, double b) {
  return tanh_sinh(
      [&](double p) {
        const double s2 = std::sin(p) * std::sin(p);
        return k_param(a + (b - a) * s2) / std::sqrt(1 - a - (b - a) * s2);
      },
      0.0, kHalfPi);
}
double downstream_integral(double a, double b) {
  return std::sqrt(a) * tanh_sinh(
                            [&](double p) {
                              const double s = std::sin(p);
                              return k_param(a * s * s) * s /
                                     std::sqrt((1 - a * s * s) * (b - a * s * s));
                            },
                            0.0, kHalfPi);
}
double seepage_face_integral(double a, double b) {
  return tanh_sinh(
      [&](double p) {
        const double s = std::sin(p), c = std::cos(p);
        return k_cos2(p) * s * c / std::sqrt((1 - (1 - a) * s * s) * (1 - (1 - b) * s * s));
      },
      0.0, kHalfPi);
}
/// int_0^psi K(c^2) s / sqrt(...): the rise of the free surface from the exit point.
double rise_integral(double a, double b, double psi) {
  return tanh_sinh(
      [&](double p) {
        const double s = std::sin(p);
        return k_cos2(p) * s / std::sqrt((1 - a * s * s) * (1 - b * s * s));
      },
      0.0, psi);
}
/// int_0^psi K(s^2) s / sqrt(...): the distance of the free surface from the face.
double run_integral(double a, double b, double psi) {
  return tanh_sinh(
      [&](double p) {
        const double s = std::sin(p);
        return k_sin2(p) * s / std::sqrt((1 - a * s * s) * (1 - b * s * s));
      },
      0.0, psi);
}

double logistic(double t) { return 1.0 / (1.0 + std::exp(-t)); }

}  // namespace

RectangularDamExact::RectangularDamExact(const RectangularDam& dam)
    : length_(dam.length), h1_(dam.head_upstream), h2_(dam.head_downstream) {
  // Unknowns beta = logistic(v), alpha = beta logistic(u): 0 < alpha < beta < 1 always.
  auto residual = [&](double u, double v, double r[2]) {
    const double b = logistic(v), a = b * logistic(u), c = length_ / length_integral(a, b);
    r[0] = (c * downstream_integral(a, b) - h2_) / h1_;
    r[1] = (h2_ + c * (seepage_face_integral(a, b) + rise_integral(a, b, kHalfPi)) - h1_) / h1_;
  };
  double u = -3.0, v = 0.0, r[2], ru[2], rv[2];
  for (int step = 0; step < 100; ++step) {
    residual(u, v, r);
    if (std::hypot(r[0], r[1]) < 1e-13) {
      beta_ = logistic(v), alpha_ = beta_ * logistic(u);
      c_ = length_ / length_integral(alpha_, beta_);
      return;
    }
    const double e = 1e-7;
    residual(u + e, v, ru), residual(u, v + e, rv);
    const double j00 = (ru[0] - r[0]) / e, j01 = (rv[0] - r[0]) / e;
    const double j10 = (ru[1] - r[1]) / e, j11 = (rv[1] - r[1]) / e;
    const double det = j00 * j11 - j01 * j10;
    double du = (-r[0] * j11 + r[1] * j01) / det, dv = (-j00 * r[1] + j10 * r[0]) / det;
    const double norm = std::hypot(du, dv);
    if (norm > 1.0) du /= norm, dv /= norm;  // damped: at most 1 in the logistic variables
    u += du, v += dv;
  }
  throw std::runtime_error("RectangularDamExact: Newton did not converge");
}

double RectangularDamExact::exit_height() const {
  return h2_ + c_ * seepage_face_integral(alpha_, beta_);
}

double RectangularDamExact::free_surface(double x) const {
  if (x <= 0.0) return h1_;
  if (x >= length_) return exit_height();
  double lo = 0.0, hi = kHalfPi;  // x(psi) falls from L to 0 as psi grows
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (length_ - c_ * run_integral(alpha_, beta_, mid) > x ? lo : hi) = mid;
  }
  return exit_height() + c_ * rise_integral(alpha_, beta_, 0.5 * (lo + hi));
}

}  // namespace porosph::validation
