// The smallest valid water scene, for tests that run the coupler with the dummy solver (which
// ignores the particles; the coupler still validates the scene): a 1 m box, one water block.
#pragma once

#include <string>

namespace porosph::testing {

/// The scene named `name`, its [run] table holding `run_keys` (lines "key = value"; end_time,
/// output_interval, dp and dt0 are required). It starts with an empty line, so [run]'s first key
/// is on line 4.
inline std::string dummy_water_scene(const std::string& name, const std::string& run_keys) {
  return "\n[scene]\nname = \"" + name + "\"\n[run]\n" + run_keys +
         "[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n"
         "[water]\nsound_speed = 10.0\n"
         "[[water.blocks]]\nshape = \"box\"\nmin = [0.1, 0.1]\nmax = [0.2, 0.2]\n";
}

}  // namespace porosph::testing
