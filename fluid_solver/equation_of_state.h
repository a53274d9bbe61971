// Tait equation of state (Batchelor 1967; Monaghan 1994), seed paper eq. 4 with exponent gamma:
//   p = B ((rho / rho0)^gamma - 1),   B = rho0 c0^2 / gamma,
// its inverse  rho = rho0 (1 + p / B)^(1 / gamma)  and the local sound speed
//   c = sqrt(dp/drho) = c0 (rho / rho0)^((gamma - 1) / 2).
#pragma once

#include <algorithm>
#include <cmath>

namespace porosph::water {

class TaitEos {
 public:
  TaitEos() = default;
  TaitEos(double rho0, double c0, double gamma)
      : rho0_(rho0), c0_(c0), gamma_(gamma), b_(rho0 * c0 * c0 / gamma), seven_(gamma == 7.0) {}

  double rho0() const { return rho0_; }
  double c0() const { return c0_; }
  double gamma() const { return gamma_; }
  double b() const { return b_; }

  double pressure(double rho) const { return b_ * (ratio_pow_gamma(rho / rho0_) - 1.0); }

  /// Inverse of pressure(). Pressures below -B (beyond the tension the EOS can represent) give
  /// rho0 / 2, so that a wall interpolated from a torn free surface never gets a zero density.
  double density(double p) const {
    const double base = 1.0 + p / b_;
    const double floor = std::pow(0.5, gamma_);
    return rho0_ * std::pow(std::max(base, floor), 1.0 / gamma_);
  }

  /// Pressure of still water `depth` below its free surface under gravity g: the solution of
  /// dp/dd = rho(p) g with this EOS (the enthalpy int_0^p dp'/rho grows as g d),
  ///   p(d) = B ((1 + (gamma - 1)/gamma rho0 g d / B)^(gamma/(gamma - 1)) - 1)
  ///        = rho0 g d (1 + g d / (2 c0^2) + ...),
  /// the state that the density diffusion leaves alone (density_diffusion.h). Negative depths
  /// (above the surface) give the mirrored tension, as rho0 g d does.
  double still_water_pressure(double depth, double g) const {
    const double r = gamma_ / (gamma_ - 1.0);
    const double base = 1.0 + rho0_ * g * depth / (r * b_);
    if (!(base > 0.0)) return rho0_ * g * depth;  // beyond the tension the EOS can represent
    return b_ * (std::pow(base, r) - 1.0);
  }

  double sound_speed(double rho) const {
    const double s = rho / rho0_;
    if (seven_) return c0_ * s * s * s;
    return c0_ * std::pow(s, 0.5 * (gamma_ - 1.0));
  }

 private:
  double ratio_pow_gamma(double s) const {
    if (seven_) {  // the common case, without pow()
      const double s3 = s * s * s;
      return s3 * s3 * s;
    }
    return std::pow(s, gamma_);
  }

  double rho0_ = 1000.0, c0_ = 20.0, gamma_ = 7.0, b_ = 1000.0 * 400.0 / 7.0;
  bool seven_ = true;
};

}  // namespace porosph::water
