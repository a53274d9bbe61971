// ProgressLine: the rate and ETA of a resumed run count from the resume point.
#include "coupler/progress_line.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace porosph::coupler {
namespace {

std::string read_all(std::FILE* file) {
  std::rewind(file);
  std::string text;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, file) != nullptr) text += buffer;
  return text;
}

// Parses "... <number> <unit>" from the last line printed.
double last_value_before(const std::string& text, const std::string& unit) {
  const auto line_start = text.rfind("t = ");
  const auto at = text.find(unit, line_start);
  const auto number_start = text.rfind(' ', at - 2) + 1;
  return std::stod(text.substr(number_start, at - 1 - number_start));
}

TEST(ProgressLine, ResumedRunReportsItsOwnRateAndEta) {
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  {
    // Resumed at t = 100 s, step 1,000,000, of a 1000 s run; 10 steps of 0.1 s in >= 50 ms.
    ProgressLine progress(1000.0, true, log);
    progress.update(100.1, 1'000'001, 0.1);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    progress.finish(101.0, 1'000'010);
  }
  const std::string text = read_all(log);
  std::fclose(log);
  // 10 steps in 50 ms (plus scheduling): ~200 steps/s. Counting the checkpointed million steps
  // would print ~2e7; the bound 1000 leaves a factor 5 for a fast clock reading.
  const double rate = last_value_before(text, "steps/s");
  EXPECT_GT(rate, 0.0);
  EXPECT_LT(rate, 1000.0) << text;
  // 1 s simulated in ~50 ms with 899 s to go: ETA ~45 s. Measured from t = 0 it would be ~0.45 s;
  // the upper bound allows a machine 100x slower than the sleep.
  const double eta = last_value_before(text, "s\n");
  EXPECT_GT(eta, 20.0) << text;
  EXPECT_LT(eta, 5000.0) << text;
}

TEST(ProgressLine, FirstLineOfARunShowsNoRateYet) {
  std::FILE* log = std::tmpfile();
  ASSERT_NE(log, nullptr);
  {
    // Into a file the first update always prints (a new tenth of the run); it comes one step
    // after the resume, microseconds after the clock started.
    ProgressLine progress(300.0, true, log);
    progress.update(11.1418, 441'308, 2.52e-5);
  }
  const std::string text = read_all(log);
  std::fclose(log);
  EXPECT_NE(text.find("step 441308"), std::string::npos) << text;
  EXPECT_NE(text.find("-- steps/s  ETA -- s\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace porosph::coupler
