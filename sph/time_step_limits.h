// Stability limits of the explicit time step (seed paper section 2.5; Monaghan 1992; Morris 1997):
//   dt_cfl     = C_cfl h / (c + |v|max)
//   dt_viscous = C_visc h^2 / nu,  nu = mu / rho0   (infinite when mu = 0)
//   dt_force   = C_a min_i sqrt(h / |a_i|)          (eq. 21; |a_i| the total acceleration,
//                                                    interaction included; infinite when a = 0)
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace porosph::sph {

struct DtLimits {
  double cfl = std::numeric_limits<double>::infinity();
  double viscous = std::numeric_limits<double>::infinity();
  double force = std::numeric_limits<double>::infinity();
  double min() const { return std::min({cfl, viscous, force}); }
};

/// dt_cfl = C_cfl h / (c + |v|max).
inline double cfl_limit(double c_cfl, double h, double sound_speed, double max_speed) {
  return c_cfl * h / (sound_speed + max_speed);
}

inline DtLimits time_step_limits(double h, double sound_speed, double max_speed,
                                 double kinematic_viscosity, double max_acceleration, double c_cfl,
                                 double c_viscous, double c_a) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  DtLimits l;
  l.cfl = cfl_limit(c_cfl, h, sound_speed, max_speed);
  l.viscous = kinematic_viscosity > 0.0 ? c_viscous * h * h / kinematic_viscosity : inf;
  l.force = max_acceleration > 0.0 ? c_a * std::sqrt(h / max_acceleration) : inf;
  return l;
}

}  // namespace porosph::sph
