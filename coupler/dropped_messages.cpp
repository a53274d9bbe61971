#include "coupler/dropped_messages.h"

#include <cstdio>
#include <utility>

namespace porosph::coupler {

DroppedMessages::DroppedMessages(std::function<void(const std::string&)> sink)
    : sink_(std::move(sink)) {
  if (!sink_) {
    sink_ = [](const std::string& line) { std::fprintf(stderr, "coupler: %s\n", line.c_str()); };
  }
}

void DroppedMessages::add(const std::string& reason, Clock::time_point now) {
  ++count_;
  if (count_ <= kLoggedOneByOne) {
    std::string line = "dropped a message: " + reason;
    if (count_ == kLoggedOneByOne) {
      line += " (further drops are summed up at most every " +
              std::to_string(static_cast<int>(kSummarySeconds)) + " s)";
    }
    sink_(line);
    logged_count_ = count_;
    last_line_ = now;
    return;
  }
  if (std::chrono::duration<double>(now - last_line_).count() < kSummarySeconds) return;
  sink_("dropped " + std::to_string(count_ - logged_count_) + " more messages (" +
        std::to_string(count_) + " in all; the latest: " + reason + ")");
  logged_count_ = count_;
  last_line_ = now;
}

}  // namespace porosph::coupler
