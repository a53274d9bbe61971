// The drag a water lattice feels as it slides through a soil lattice of the same spacing in
// registry (the darcy_column's water and soil fill the same box from the same corner).
//
// The coupler's drag on water particle a is sum_i V_i f_ia W_ia over the soil particles
// (coupler/interaction/soil_water_sums.h): for a uniform bed it is the continuum drag times the
// kernel's lattice sum S(o) = sum_j dp^D W(|o - x_j|), o the particle's offset from a soil
// lattice site. S integrates to 1 over all offsets of a cell, but it is not 1 at each: for the
// cubic spline at h = 1.2 dp, from 0.99976 at o = 0 down to 0.99849 at o = (0, 0.325 dp). Gravity
// moves the water along one lattice axis only, so its particles keep o = 0 across the flow and
// sweep o along it: the steady velocity K / S(o) swings with the period dp / K, and its mean over
// that period is K times the mean of 1 / S along the axis (1.00112 here), whatever dp is - the
// error of the kernel's partition of unity, which depends on h / dp, not on dp. (With Forchheimer's
// quadratic term the velocity moves less with S: S (a q + b q^2) = 1.)
#pragma once

#include <cmath>
#include <stdexcept>

#include "sph/lattice_gradient.h"

namespace porosph::validation {

/// S(o) for a kernel of dimension D with o = (offset along `axis`), 0 across it; `kernel.w(r)`.
template <class Kernel>
double lattice_kernel_sum(const Kernel& kernel, double dp, int axis, double offset) {
  constexpr int D = Kernel::kDim;
  if (!(dp > 0.0)) throw std::invalid_argument("lattice_kernel_sum: dp must be > 0");
  const int reach = static_cast<int>(std::ceil(kernel.support() / dp)) + 1;
  const double volume = std::pow(dp, D);
  double sum = 0.0;
  sph::for_each_lattice_site<D>(reach, [&](const int* index) {
    double r2 = 0.0;
    for (int k = 0; k < D; ++k) {
      const double x = index[k] * dp - (k == axis ? offset : 0.0);
      r2 += x * x;
    }
    sum += volume * kernel.w(std::sqrt(r2));
  });
  return sum;
}

/// The mean over one spacing of o along `axis` (midpoint rule, `samples` points) of
/// velocity(S(o)): the steady velocity of a water lattice sliding through the soil lattice in
/// registry, on average over the period, where velocity(S) solves the seepage law with the drag
/// scaled by S (Darcy: K / S; Forchheimer: S (a q + b q^2) = i).
template <class Kernel, class Velocity>
double registry_mean_velocity(const Kernel& kernel, double dp, int axis, const Velocity& velocity,
                              int samples = 64) {
  double sum = 0.0;
  for (int s = 0; s < samples; ++s)
    sum += velocity(lattice_kernel_sum(kernel, dp, axis, (s + 0.5) * dp / samples));
  return sum / samples;
}

}  // namespace porosph::validation
