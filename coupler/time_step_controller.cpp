#include "coupler/time_step_controller.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace porosph::coupler {

namespace {
double harmonic_mean(double a, double b) { return 2.0 * a * b / (a + b); }
}  // namespace

TimeStepController::TimeStepController(double dt0, bool smoothing, double collapse_ratio)
    : dt0_(dt0), dt_(dt0), smoothing_(smoothing), collapse_ratio_(collapse_ratio) {
  if (!(dt0 > 0.0) || !std::isfinite(dt0)) throw std::invalid_argument("dt0 must be > 0");
}

double TimeStepController::next(double dt_min) {
  if (std::isnan(dt_min) || dt_min <= 0.0) {
    std::ostringstream msg;
    msg << "time-step limit is " << dt_min << " (a solver reported a non-positive or NaN limit)";
    throw TimeStepCollapse(msg.str());
  }
  double next_dt;
  if (!smoothing_) {
    next_dt = std::min(dt_min, dt0_);
  } else if (dt_min < dt0_) {
    next_dt = dt_min < dt_ ? dt_min : harmonic_mean(dt_, dt_min);
  } else {
    next_dt = harmonic_mean(dt_, dt0_);
    // Once within round-off of dt0, be exactly dt0 ("== dt0 once there", docs/design.md section 4).
    if (next_dt > dt0_ * (1.0 - 1e-12)) next_dt = dt0_;
  }
  // Round-off guard: the harmonic mean of dt_n <= dt0 and dt0 can exceed dt0 by an ulp.
  next_dt = std::min(next_dt, dt0_);
  if (next_dt < collapse_ratio_ * dt0_) {
    std::ostringstream msg;
    msg << "time step collapsed to " << next_dt << " s, below " << collapse_ratio_
        << " x dt0 = " << collapse_ratio_ * dt0_ << " s: the run is blowing up";
    throw TimeStepCollapse(msg.str());
  }
  dt_ = next_dt;
  return dt_;
}

}  // namespace porosph::coupler
