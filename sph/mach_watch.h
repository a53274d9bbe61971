// The weakly compressible model's own assumption, watched while a water solver runs (issue 29):
// the Mach number M = |v| / c0 of its fastest free particle. Density varies like M^2 (M = 0.1:
// ~1 %, the design value of c0 = 10 |v|max; M = 0.3: ~10 %, where the Tait equation's pressures
// stop meaning anything). Above kMachWarn the coupler warns once and run.json records the
// maximum; above kMachLimit the solver fails, naming the particle (docs/reliability.md). The
// limits are declared with the scene rules (scene/scene_sanity.h).
#pragma once

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene_sanity.h"
#include "sph/vector.h"

namespace porosph::sph {

using scene::kMachLimit;  // scene/scene_sanity.h: the rule check applies to prescribed speeds
using scene::kMachWarn;

/// "Mach number 0.98 ..." when the fastest free particle (fixed[a] == 0) moves faster than
/// kMachLimit c0, naming it (its id in *particle_id), else std::nullopt.
template <int D>
std::optional<std::string> find_mach_violation(const std::vector<Vec<D>>& position,
                                               const std::vector<Vec<D>>& velocity,
                                               const std::vector<std::uint8_t>& fixed,
                                               const std::vector<std::int64_t>& id, double c0,
                                               unsigned long long step, double time,
                                               std::int64_t* particle_id) {
  const double limit_squared = kMachLimit * kMachLimit * c0 * c0;
  std::size_t fastest = velocity.size();
  double fastest_squared = limit_squared;
  for (std::size_t a = 0; a < velocity.size(); ++a) {
    const double v2 = velocity[a].squaredNorm();
    if (v2 > fastest_squared && !fixed[a]) {
      fastest = a;
      fastest_squared = v2;
    }
  }
  if (fastest == velocity.size()) return std::nullopt;
  if (particle_id != nullptr) *particle_id = id[fastest];
  const double speed = velocity[fastest].norm();
  std::ostringstream msg;
  msg.precision(3);
  msg << "Mach number " << speed / c0 << " (|v| = " << speed << " m/s, c0 = " << c0
      << " m/s, water.sound_speed) of water particle " << id[fastest] << " at x = (";
  for (int k = 0; k < D; ++k) msg << (k ? ", " : "") << position[fastest][k];
  msg << ") at step " << step << ", t = " << time << " s exceeds " << kMachLimit
      << ", the limit of the weakly compressible model: raise water.sound_speed (c0 >= 10 |v|max)"
         " or find what drives the water this fast";
  return msg.str();
}

}  // namespace porosph::sph
