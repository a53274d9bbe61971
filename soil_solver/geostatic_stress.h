// Geostatic (at-rest) initial stress of a soil column under gravity, tension positive:
//   sigma_v = -gamma' depth = -rho |g| depth          (vertical effective stress, compression)
//   sigma_h = K0 sigma_v                               (every horizontal direction)
//   sigma   = sigma_h delta + (sigma_v - sigma_h) u (x) u,   u = -g / |g|  (the "up" direction)
// with K0 = 1 - sin(phi) (Jaky 1944) or the elastic oedometric value K0 = nu / (1 - nu).
// rho is the density carrying the weight: the dry / moist density above the water table, the
// submerged density (saturated - water) below it (docs/cases.md soil_column); for a layered column
// the caller sums rho |g| dz layer by layer and passes sigma_v directly.
// In 2D plane strain the out-of-plane direction is horizontal too, so sigma_zz = sigma_h (the
// oedometric state: no lateral strain in any horizontal direction). "Up" always comes from the
// gravity vector; no axis is hard-coded.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>

#include "soil_solver/velocity_gradient.h"
#include "sph/vector.h"

namespace porosph::soil {

/// K0 = 1 - sin(phi) (Jaky), phi in radians.
inline double k0_jaky(double friction_angle) { return 1.0 - std::sin(friction_angle); }

/// K0 = nu / (1 - nu) (elastic, laterally confined).
inline double k0_elastic(double poisson) { return poisson / (1.0 - poisson); }

/// The unit up direction u = -g / |g| (throws std::invalid_argument for zero gravity).
template <int D>
inline sph::Vec<D> up_direction(const sph::Vec<D>& gravity) {
  const double g = gravity.norm();
  if (!(g > 0.0)) throw std::invalid_argument("geostatic stress: gravity must be non-zero");
  return -gravity / g;
}

/// Depth of x below a point on the soil surface, measured along the up direction (negative
/// above the surface).
template <int D>
inline double depth_below(const sph::Vec<D>& x, const sph::Vec<D>& surface_point,
                          const sph::Vec<D>& gravity) {
  return (surface_point - x).dot(up_direction<D>(gravity));
}

/// sigma_v = -rho |g| depth (compression negative; zero above the surface).
inline double vertical_geostatic_stress(double density, double gravity_magnitude, double depth) {
  return depth > 0.0 ? -density * gravity_magnitude * depth : 0.0;
}

/// The 3x3 at-rest stress from the vertical stress and K0, principal axes aligned with gravity.
template <int D>
inline Eigen::Matrix3d geostatic_stress(const sph::Vec<D>& gravity, double vertical_stress,
                                        double k0) {
  const Eigen::Vector3d u = embed_in_3d<D>(up_direction<D>(gravity));
  const double horizontal = k0 * vertical_stress;
  return horizontal * Eigen::Matrix3d::Identity() +
         (vertical_stress - horizontal) * u * u.transpose();
}

/// Convenience: stress at x in a homogeneous layer of density rho below surface_point.
template <int D>
inline Eigen::Matrix3d geostatic_stress_at(const sph::Vec<D>& x, const sph::Vec<D>& surface_point,
                                           const sph::Vec<D>& gravity, double density, double k0) {
  const double sv =
      vertical_geostatic_stress(density, gravity.norm(), depth_below<D>(x, surface_point, gravity));
  return geostatic_stress<D>(gravity, sv, k0);
}

}  // namespace porosph::soil
