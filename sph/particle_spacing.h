// The particle spacing every particle solver's parameters start from (issue 24, the shared phase
// core): the scene's dp, smoothing length and particle volume, taken after checking that the scene
// has the solver's phase in the dimension the solver was built for.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace porosph::sph {

struct ParticleSpacing {
  double dp = 0.01;      ///< particle spacing [m]
  double h = 0.012;      ///< smoothing length [m]
  double volume = 1e-4;  ///< particle volume dp^D [m^D]

  /// run.dp, h and dp^D of `s`. Throws std::invalid_argument when the scene lacks `phase` or is
  /// not D-dimensional, naming the "<phase> solver".
  template <int D>
  void take_from_scene(const scene::Scene& s, const std::string& phase) {
    const auto phases = s.phases();
    if (std::find(phases.begin(), phases.end(), phase) == phases.end())
      throw std::invalid_argument(phase + " solver: the scene has no [" + phase + "] phase");
    if (s.run.dimension != D) {
      throw std::invalid_argument(phase + " solver built for D = " + std::to_string(D) +
                                  " but run.dimension = " + std::to_string(s.run.dimension));
    }
    dp = s.run.dp;
    h = s.h();
    volume = std::pow(dp, D);
  }
};

}  // namespace porosph::sph
