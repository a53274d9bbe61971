// OUT/timeseries.csv (docs/design.md section 6): one header line, then one row per output time.
// Every row is flushed to the operating system as soon as it is appended, so a run that fails or is
// killed keeps every row written before.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace porosph::io {

class TimeSeriesCsv {
 public:
  /// Creates (truncates) the file and writes the header line. Column names containing a comma,
  /// quote or line break are quoted. Throws std::runtime_error naming the path on failure or if
  /// `columns` is empty.
  TimeSeriesCsv(const std::string& path, std::vector<std::string> columns);
  /// Resume (docs/checkpoints.md): keeps the header and the first `keep_rows` rows of the existing
  /// file (the rows written before the checkpoint; later rows are removed, via a temporary file
  /// and rename), then appends from there. Throws std::runtime_error naming the path if the file
  /// is missing, its header differs from `columns` or it has fewer than `keep_rows` rows.
  TimeSeriesCsv(const std::string& path, std::vector<std::string> columns, std::size_t keep_rows);

  /// Appends one row, formatted with %.10g (10 significant digits), and flushes it. Throws
  /// std::runtime_error naming the path if the row length differs from the number of columns or
  /// the write fails.
  void append(const std::vector<double>& row);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  void write_or_throw(const std::string& text);
  std::string header_line() const;

  std::string path_;
  std::vector<std::string> columns_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::string line_;  ///< reused buffer for one formatted row
};

}  // namespace porosph::io
