// The time weights of the pairwise implicit drag (soil_water_implicit.h, docs/coupling.md).
//
// Over one step a pair's relative velocity v obeys dv/dt = d - lambda v (d: the relative
// acceleration of the solvers' own forces, lambda = lambda_a + lambda_i the pair's drag rate,
// the other pairs' rates on the diagonal). With v0 the relative velocity at the start of the step
// and v* = v0 + dt d the one the own forces alone would reach, the step's mean drag per unit of
// the drag coefficient is, with x = lambda dt,
//   exact (exponential):  v0 phi(x) + (v* - v0) psi(x),
//       phi = (1 - e^-x) / x,  psi = (1 - phi) / x        (phi -> 1, psi -> 1/2 as x -> 0);
//   backward Euler:       v* / (1 + x) = v0 / (1 + x) + (v* - v0) / (1 + x).
// Both keep a steady state (v0 = d / lambda) exactly and both tend to v* / x for x >> 1 (the pair
// relaxes within the step); for x << 1 backward Euler weighs the own forces' change v* - v0 by
// ~1 where the exact mean weighs it by 1/2: a first-order error in dt that the exponential
// weights do not have. For the nonlinear eq. 13 the weights apply to f(v0) and f(v*) - f(v0).
#pragma once

#include <cmath>

namespace porosph::coupler {

/// coupling.drag_step: how the pairwise implicit drag weighs the pair's state over the step.
enum class DragStep { kBackwardEuler, kExponential };

/// The weights (on f(v0), on f(v*) - f(v0)) of one pair over a step with x = lambda dt >= 0.
struct DragStepWeights {
  double start = 1.0;   ///< weight of the drag at the start of the step, f(v0)
  double change = 1.0;  ///< weight of the own forces' change over the step, f(v*) - f(v0)
};

inline DragStepWeights drag_step_weights(DragStep step, double x) {
  if (step == DragStep::kBackwardEuler) {
    const double w = 1.0 / (1.0 + x);
    return {w, w};
  }
  if (x < 1e-4) {  // series: the closed forms cancel to round-off as x -> 0
    return {1.0 - x / 2.0 + x * x / 6.0, 0.5 - x / 6.0 + x * x / 24.0};
  }
  const double phi = -std::expm1(-x) / x;
  return {phi, (1.0 - phi) / x};
}

}  // namespace porosph::coupler
