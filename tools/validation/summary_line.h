// The machine-readable verdict line of porosph_validate, read by tools/validation/report.py.
#pragma once

#include <cstdio>
#include <string>

namespace porosph::validation {

/// Prints "summary<TAB>quantity<TAB>value<TAB>reference<TAB>error<TAB>target<TAB>verdict", the
/// verdict being "met" (met = 1), "not met" (0) or "no target" (-1: a figure beside the verdict).
inline void print_summary(const std::string& quantity, const std::string& value,
                          const std::string& reference, const std::string& error,
                          const std::string& target, int met) {
  std::printf("summary\t%s\t%s\t%s\t%s\t%s\t%s\n", quantity.c_str(), value.c_str(),
              reference.c_str(), error.c_str(), target.c_str(),
              met < 0 ? "no target" : (met ? "met" : "not met"));
}

/// One number through a printf format, as a string.
inline std::string format_value(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace porosph::validation
