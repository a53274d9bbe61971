// Messages the coupler's SolverHub drops (no or a wrong run token, a peer that never said a valid
// Hello, a frame it cannot attribute): counted for run.json and logged, rate-limited, so that a
// flood of them neither goes unnoticed nor floods the log.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace porosph::coupler {

class DroppedMessages {
 public:
  using Clock = std::chrono::steady_clock;
  /// Every log line goes to `sink` (default: stderr, prefixed "coupler: ").
  explicit DroppedMessages(std::function<void(const std::string&)> sink = {});

  /// Counts one dropped message; logs it if it is among the first kLoggedOneByOne, else at most
  /// one summary line per kSummarySeconds.
  void add(const std::string& reason, Clock::time_point now = Clock::now());
  std::uint64_t count() const { return count_; }

  static constexpr std::uint64_t kLoggedOneByOne = 3;
  static constexpr double kSummarySeconds = 10.0;

 private:
  std::function<void(const std::string&)> sink_;
  std::uint64_t count_ = 0;
  std::uint64_t logged_count_ = 0;  ///< count_ at the last line
  Clock::time_point last_line_{};
};

}  // namespace porosph::coupler
