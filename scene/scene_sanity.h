// Whether a valid scene means something (issue 29, "no silent nonsense"): the rules `coupler
// check` applies after the schema and the relations between keys (scene_sanity.cpp), and the time
// step estimate they and the coupler's size estimate use. docs/reliability.md lists the rules.
#pragma once

#include <toml++/toml.h>

#include "scene/scene.h"

namespace porosph::scene {

/// The Mach number M = |v| / c0 of the water (sph/mach_watch.h): above kMachWarn the coupler warns
/// once and records the maximum in run.json; above kMachLimit the weakly compressible model means
/// nothing (density errors ~ M^2 ~ 10 %): a speed the scene prescribes is refused at check, one
/// the run reaches fails it.
inline constexpr double kMachWarn = 0.1;
inline constexpr double kMachLimit = 0.3;

/// An output interval below this fraction of the expected time step asks for several outputs per
/// step; the coupler writes at most one per step, so such a value means nothing and is refused.
inline constexpr double kMinOutputIntervalOverDt = 0.1;

/// The time step the run can be expected to take at its start [s]: min(dt0, the CFL limit
/// cfl h / c of the fastest sound speed, the viscous limit of the water, the force limit
/// c_a sqrt(h / |g|) of gravity). The run's dt is at most this; accelerations beyond gravity and
/// flow speeds make it smaller.
double expected_time_step(const Scene& scene);

class ErrorContext;  // scene_internal.h

/// The rules of scene_sanity.cpp over a validated scene `root` and its typed form `scene` (loader
/// pipeline, after check_scene_consistency and build_scene). Throws SceneError.
void check_scene_sanity(const toml::table& root, const Scene& scene, const ErrorContext& errors);

}  // namespace porosph::scene
