#include "coupler/progress_line.h"

#include <unistd.h>

#include <algorithm>

namespace porosph::coupler {

ProgressLine::ProgressLine(double end_time, bool enabled, std::FILE* stream)
    : end_time_(end_time),
      enabled_(enabled),
      terminal_(isatty(fileno(stream)) != 0),
      stream_(stream),
      start_(Clock::now()),
      last_print_(start_) {}

void ProgressLine::update(double time, std::uint64_t step, double dt) {
  if (!enabled_) return;
  if (!has_origin_) {
    // The first step of this process: one step back is where the run started or resumed.
    has_origin_ = true;
    origin_time_ = std::max(0.0, time - dt);
    origin_step_ = step > 0 ? step - 1 : 0;
    start_ = Clock::now();
  }
  const auto now = Clock::now();
  const double since_print = std::chrono::duration<double>(now - last_print_).count();
  if (terminal_) {
    if (since_print < 0.25) return;
  } else {
    const int decile = static_cast<int>(10.0 * time / end_time_);
    if (decile <= last_decile_ && since_print < 60.0) return;
    last_decile_ = decile;
  }
  last_print_ = now;
  print(time, step, dt, false);
}

void ProgressLine::finish(double time, std::uint64_t step) {
  if (!enabled_) return;
  print(time, step, 0.0, true);
}

void ProgressLine::print(double time, std::uint64_t step, double dt, bool final) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double fraction = std::clamp(time / end_time_, 0.0, 1.0);
  const double done_here = time - origin_time_;
  const std::uint64_t steps_here = step - std::min(step, origin_step_);
  std::fprintf(stream_, "%st = %.4g / %.4g s  %5.1f%%  step %llu  dt %.3g s  ",
               terminal_ ? "\r" : "", time, end_time_, 100.0 * fraction,
               static_cast<unsigned long long>(step), dt);
  // The first line comes one step after start: a rate from one step over microseconds would be
  // noise (it printed 1.25e7 steps/s on a resumed run), so rate and ETA wait for a measurable
  // stretch.
  if (elapsed >= kShortestRatePeriod && steps_here >= 2 && done_here > 1e-12) {
    const double eta = elapsed * std::max(0.0, end_time_ - time) / done_here;
    std::fprintf(stream_, "%.0f steps/s  ETA %.0f s", static_cast<double>(steps_here) / elapsed,
                 eta);
  } else {
    std::fputs("-- steps/s  ETA -- s", stream_);
  }
  std::fputs(terminal_ ? (final ? "\n" : "   ") : "\n", stream_);
  std::fflush(stream_);
}

}  // namespace porosph::coupler
