// Comparing two runs of the same scene (tests/coupler/checkpoint_resume_test.cpp): their
// timeseries.csv row by row and their last snapshots field by field, to a relative 1e-12 (one
// thread per solver keeps every sum in one order, so in practice bit for bit).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "io/snapshot_reader.h"
#include "tests/support/process_support.h"

namespace porosph::testing {

constexpr double kRelativeTolerance = 1e-12;

/// The rows of a CSV file as numbers (header dropped).
inline std::vector<std::vector<double>> csv_rows(const std::string& path) {
  std::vector<std::vector<double>> rows;
  std::istringstream text(read_text(path));
  std::string line;
  std::getline(text, line);
  while (std::getline(text, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

inline void expect_close(double a, double b, const std::string& what) {
  const double scale = std::max({std::abs(a), std::abs(b), 1e-300});
  if (std::isnan(a) && std::isnan(b)) return;
  EXPECT_LE(std::abs(a - b), kRelativeTolerance * scale) << what << ": " << a << " vs " << b;
}

/// Same t column (no duplicate or missing row) and the same values in every row.
inline void expect_same_timeseries(const std::string& a, const std::string& b) {
  const auto rows_a = csv_rows(a + "/timeseries.csv");
  const auto rows_b = csv_rows(b + "/timeseries.csv");
  ASSERT_EQ(rows_a.size(), rows_b.size()) << read_text(b + "/timeseries.csv");
  for (std::size_t r = 0; r < rows_a.size(); ++r) {
    ASSERT_EQ(rows_a[r].size(), rows_b[r].size());
    EXPECT_EQ(rows_a[r][0], rows_b[r][0]) << "t of row " << r;
    if (r > 0) {
      EXPECT_GT(rows_b[r][0], rows_b[r - 1][0]) << "t must increase (row " << r << ")";
    }
    for (std::size_t c = 1; c < rows_a[r].size(); ++c) {
      expect_close(rows_a[r][c], rows_b[r][c],
                   "row " + std::to_string(r) + " column " + std::to_string(c));
    }
  }
}

/// Same snapshot list, and the last snapshots agree field by field.
inline void expect_same_snapshots(const std::string& a, const std::string& b,
                                  const std::string& file,
                                  const std::vector<std::string>& f64_fields) {
  const io::SnapshotReader ra(a + "/" + file), rb(b + "/" + file);
  const auto sa = ra.snapshots(), sb = rb.snapshots();
  ASSERT_EQ(sa.size(), sb.size()) << file;
  for (std::size_t i = 0; i < sa.size(); ++i) {
    EXPECT_EQ(sa[i].index, sb[i].index) << file;
    EXPECT_EQ(sa[i].time, sb[i].time) << file << " snapshot " << i;
  }
  const std::uint32_t last = sa.back().index;
  EXPECT_EQ(ra.read_i64(last, "id").values, rb.read_i64(last, "id").values) << file;
  for (const std::string& field : f64_fields) {
    const auto fa = ra.read_f64(last, field), fb = rb.read_f64(last, field);
    ASSERT_EQ(fa.values.size(), fb.values.size()) << file << " " << field;
    for (std::size_t k = 0; k < fa.values.size(); ++k) {
      expect_close(fa.values[k], fb.values[k], file + " " + field + "[" + std::to_string(k) + "]");
    }
  }
}

}  // namespace porosph::testing
