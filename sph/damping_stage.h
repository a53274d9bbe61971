// The initial damping (dynamic relaxation) stage t < t_d = soil.damping_duration (docs/cases.md,
// "Conventions"), one clock for every phase (issue 24, the shared phase core): active() during the
// stage, release() true exactly once after it, when the phase zeroes its velocities (checkpointed:
// a resumed run must not release twice). What a phase does in the stage is its own:
// - the soil damps its velocities, a -= D v (soil_solver.cpp), and zeroes them at the first step
//   end at t >= t_d;
// - the free water is frozen: a step that starts before t_d does not integrate it at all, so
//   positions, velocities and densities keep their values (no density filter either), and inflow
//   speeds are 0 (fluid_solver/flow_zones.h). The first step that starts at t >= t_d zeroes every
//   water velocity once (v and v^{n-1}) and is an Euler step: with v^{n-1} = v^n = 0 a Verlet step
//   would give v^{n+1} = 2 dt a.
#pragma once

#include "scene/scene.h"

namespace porosph::sph {

class DampingStage {
 public:
  DampingStage() = default;
  /// duration <= 0: no stage.
  explicit DampingStage(double duration) : duration_(duration > 0.0 ? duration : 0.0) {}
  /// soil.damping_duration when the scene has soil, else no stage.
  static DampingStage from_scene(const scene::Scene& s) {
    return DampingStage(s.soil ? s.soil->damping_duration : 0.0);
  }

  /// End of the stage t_d [s] (0: none).
  double duration() const { return duration_; }
  /// True while `time` lies inside the stage (a step starting then is a stage step).
  bool active(double time) const { return time < duration_; }
  /// True exactly once, for the first call with time >= t_d (never without a stage): the caller
  /// then zeroes its velocities.
  bool release(double time) {
    if (released_ || duration_ <= 0.0 || time < duration_) return false;
    released_ = true;
    return true;
  }
  /// Whether release() has fired (checkpointed: a resumed run must not release twice).
  bool released() const { return released_; }
  void set_released(bool released) { released_ = released; }

 private:
  double duration_ = 0.0;
  bool released_ = false;
};

}  // namespace porosph::sph
