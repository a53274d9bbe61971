// The one shared time step of a coupled run: the paper's Fig. 1 smoothing algorithm (docs/design.md
// section 4).
#pragma once

#include <stdexcept>
#include <string>

namespace porosph::coupler {

/// The step has collapsed below `collapse_ratio * dt0`: the run is blowing up.
class TimeStepCollapse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Fig. 1 of the seed paper, reconstructed in docs/design.md section 4. With dt0 the scene's
/// initial step, dt_n the current one and dt_min the smallest stability limit now:
///   dt_min < dt0 and dt_min < dt_n : dt_{n+1} = dt_min                        (decrease at once)
///   dt_min < dt0 and dt_min >= dt_n: dt_{n+1} = 2 dt_n dt_min / (dt_n + dt_min) (harmonic rise)
///   dt_min >= dt0                  : dt_{n+1} = 2 dt_n dt0 / (dt_n + dt0)      (relax back to dt0)
/// The harmonic mean of two numbers lies between them, so dt never exceeds any limit or dt0.
/// With smoothing off, dt_{n+1} = min(dt_min, dt0).
class TimeStepController {
 public:
  explicit TimeStepController(double dt0, bool smoothing = true, double collapse_ratio = 1e-5);

  /// Next step from the minimum of all limits now. Throws TimeStepCollapse below
  /// collapse_ratio*dt0.
  double next(double dt_min);

  double current() const { return dt_; }
  /// Sets the current step dt_n (resume from a checkpoint: the run goes on as before).
  void restore(double current) { dt_ = current; }
  double dt0() const { return dt0_; }

 private:
  double dt0_;
  double dt_;
  bool smoothing_;
  double collapse_ratio_;
};

}  // namespace porosph::coupler
