// Columns of equal length written as one CSV file (porosph_validate --series; the report and plot
// tools read them).
#pragma once

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::validation {

/// Writes `columns` under the header `names`, one row per index; nothing when path is empty.
inline void write_series(const std::string& path, const std::vector<std::string>& names,
                         const std::vector<const std::vector<double>*>& columns) {
  if (path.empty()) return;
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  for (std::size_t k = 0; k < names.size(); ++k) out << (k ? "," : "") << names[k];
  out << "\n";
  for (std::size_t i = 0; i < columns[0]->size(); ++i) {
    for (std::size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << (*columns[k])[i];
    out << "\n";
  }
}

}  // namespace porosph::validation
