// Initial state of the Taylor-Green vortex (Taylor & Green 1937, Proc. R. Soc. A 158, 499-521),
// the decaying periodic solution of the incompressible Navier-Stokes equations:
//   u = U sin(kx) cos(ky) F(t),   v = -U cos(kx) sin(ky) F(t),
//   p = rho0 U^2 / 4 (cos 2kx + cos 2ky) F(t)^2,   F(t) = exp(-2 nu k^2 t),   k = 2 pi / L,
// so its kinetic energy decays as exp(-4 nu k^2 t). initial_particles.cpp sets the velocity at
// t = 0 (F = 1) and adds the pressure to the one already there (hydrostatic, zero without
// gravity), the density being the inverse of eq. 4 at that pressure: the pressure gradient then
// balances the convective acceleration from the first step on and no acoustic transient starts.
// In 3D the field is uniform along z (w = 0), still an exact solution.
#pragma once

#include <cmath>

#include "sph/vector.h"

namespace porosph::water {

/// The Taylor-Green field of amplitude `speed` [m/s] and wavelength `wavelength` [m] at t = 0.
struct TaylorGreenVortex {
  double speed = 0.0;
  double wavelength = 1.0;

  double wavenumber() const { return 2.0 * M_PI / wavelength; }

  template <int D>
  sph::Vec<D> velocity(const sph::Vec<D>& x) const {
    const double k = wavenumber();
    sph::Vec<D> v = sph::Vec<D>::Zero();
    v[0] = speed * std::sin(k * x[0]) * std::cos(k * x[1]);
    v[1] = -speed * std::cos(k * x[0]) * std::sin(k * x[1]);
    return v;
  }

  template <int D>
  double pressure(const sph::Vec<D>& x, double rho0) const {
    const double k = wavenumber();
    return 0.25 * rho0 * speed * speed * (std::cos(2.0 * k * x[0]) + std::cos(2.0 * k * x[1]));
  }
};

}  // namespace porosph::water
