// Progress of a run on stderr: simulated time, percent, steps/s, ETA. On a terminal the line is
// redrawn in place at most 4 times a second; into a file or pipe one line is written per 10% of the
// run (or at most every 60 s), so logs stay short.
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
  double end_time_;
  bool enabled_;
  bool terminal_;
  std::FILE* stream_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  int last_decile_ = -1;
};

}  // namespace porosph::coupler
