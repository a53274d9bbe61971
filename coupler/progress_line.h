// Progress of a run on stderr: simulated time, percent, steps/s, ETA. On a terminal the line is
// redrawn in place at most 4 times a second; into a file or pipe one line is written per 10% of the
// run (or at most every 60 s), so logs stay short. Rate and ETA count from the first update, so a
// resumed run reports its own speed, not the checkpointed steps over the new wall time.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>

namespace porosph::coupler {

class ProgressLine {
 public:
  ProgressLine(double end_time, bool enabled, std::FILE* stream = stderr);
  void update(double time, std::uint64_t step, double dt);
  void finish(double time, std::uint64_t step);

 private:
  void print(double time, std::uint64_t step, double dt, bool final);
  using Clock = std::chrono::steady_clock;
  static constexpr double kShortestRatePeriod = 0.01;  // s of wall time before a rate is shown
  double end_time_;
  bool enabled_;
  bool terminal_;
  std::FILE* stream_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  int last_decile_ = -1;
  bool has_origin_ = false;
  double origin_time_ = 0.0;       // simulated time at the first update (the resume point)
  std::uint64_t origin_step_ = 0;  // step count at the first update
};

}  // namespace porosph::coupler
