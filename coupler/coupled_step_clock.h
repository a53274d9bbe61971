// Wall-clock helpers of the coupled step loop (coupled_step.cpp, coupled_step_signals.cpp).
#pragma once

#include <chrono>

namespace porosph::coupler {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// After a signal, the longest the coupler waits for the solvers to reach the checkpoint.
inline constexpr double kSignalGraceSeconds = 30.0;

}  // namespace porosph::coupler
