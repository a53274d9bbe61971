#include "io/timeseries_csv.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace porosph::io {

namespace {

std::string csv_quoted(const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
  std::string out = "\"";
  for (char c : name) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

TimeSeriesCsv::TimeSeriesCsv(const std::string& path, std::vector<std::string> columns)
    : path_(path), columns_(std::move(columns)) {
  if (columns_.empty()) {
    throw std::runtime_error("TimeSeriesCsv('" + path_ + "'): no columns");
  }
  file_.reset(std::fopen(path_.c_str(), "w"));
  if (!file_) {
    throw std::runtime_error("TimeSeriesCsv: cannot create '" + path_ +
                             "': " + std::strerror(errno));
  }
  try {
    write_or_throw(header_line() + '\n');
  } catch (const std::runtime_error&) {
    file_.reset();
    std::remove(path_.c_str());  // no empty file without a header left behind (a full disk)
    throw;
  }
}

TimeSeriesCsv::TimeSeriesCsv(const std::string& path, std::vector<std::string> columns,
                             std::size_t keep_rows)
    : path_(path), columns_(std::move(columns)) {
  const std::string where = "TimeSeriesCsv: cannot resume '" + path_ + "'";
  if (columns_.empty()) throw std::runtime_error(where + ": no columns");
  std::ifstream in(path_);
  if (!in) throw std::runtime_error(where + ": " + std::strerror(errno));
  std::string line, kept;
  if (!std::getline(in, line) || line != header_line()) {
    throw std::runtime_error(where + ": its header differs from this run's columns");
  }
  kept = line + '\n';
  std::size_t rows = 0;
  while (rows < keep_rows && std::getline(in, line)) {
    kept += line + '\n';
    ++rows;
  }
  if (rows < keep_rows) {
    throw std::runtime_error(where + ": " + std::to_string(rows) + " rows, the checkpoint needs " +
                             std::to_string(keep_rows));
  }
  in.close();
  const std::string tmp = path_ + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << kept;
    if (!out.flush()) throw std::runtime_error(where + ": cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(where + ": cannot rename " + tmp + ": " + std::strerror(errno));
  }
  file_.reset(std::fopen(path_.c_str(), "a"));
  if (!file_) throw std::runtime_error(where + ": " + std::strerror(errno));
}

std::string TimeSeriesCsv::header_line() const {
  std::string header;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) header += ',';
    header += csv_quoted(columns_[i]);
  }
  return header;
}

void TimeSeriesCsv::append(const std::vector<double>& row) {
  if (row.size() != columns_.size()) {
    throw std::runtime_error("TimeSeriesCsv('" + path_ + "'): row has " +
                             std::to_string(row.size()) + " values, header has " +
                             std::to_string(columns_.size()) + " columns");
  }
  line_.clear();
  char number[32];
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i > 0) line_ += ',';
    std::snprintf(number, sizeof number, "%.10g", row[i]);
    line_ += number;
  }
  line_ += '\n';
  write_or_throw(line_);
}

void TimeSeriesCsv::write_or_throw(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size() ||
      std::fflush(file_.get()) != 0) {
    throw std::runtime_error("TimeSeriesCsv: cannot write '" + path_ +
                             "': " + std::strerror(errno));
  }
}

}  // namespace porosph::io
