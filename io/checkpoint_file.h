// A solver's checkpoint file (docs/checkpoints.md): one flat HDF5 file holding named arrays (one
// dataset each, rows x cols, f64 / i64 / i32 / u8) and named scalars (attributes of the root group,
// f64 / i64). Written atomically: everything goes to PATH.tmp, which is closed and then renamed to
// PATH (rename(2)), so a process killed while writing never leaves a half-written file under PATH.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace porosph::io {

class CheckpointWriter {
 public:
  /// Creates PATH.tmp (truncating a stale one). Throws std::runtime_error naming the path.
  explicit CheckpointWriter(const std::string& path);
  /// Without commit(): closes and removes PATH.tmp; PATH is untouched.
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  /// One dataset of rows x cols values (rank 1 when cols == 1); data may be null when rows == 0.
  void write(const std::string& name, const double* data, std::size_t rows, std::size_t cols = 1);
  void write(const std::string& name, const std::int64_t* data, std::size_t rows,
             std::size_t cols = 1);
  void write(const std::string& name, const std::int32_t* data, std::size_t rows,
             std::size_t cols = 1);
  void write(const std::string& name, const std::uint8_t* data, std::size_t rows,
             std::size_t cols = 1);
  /// A scalar attribute of the root group.
  void set(const std::string& name, double value);
  void set(const std::string& name, std::int64_t value);

  /// Flushes and closes PATH.tmp, then renames it to PATH. Throws on failure (PATH untouched).
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class CheckpointReader {
 public:
  /// Opens PATH read-only. Throws std::runtime_error naming the path.
  explicit CheckpointReader(const std::string& path);
  ~CheckpointReader();
  CheckpointReader(const CheckpointReader&) = delete;
  CheckpointReader& operator=(const CheckpointReader&) = delete;

  const std::string& path() const;
  bool has(const std::string& name) const;  ///< a dataset or a scalar of that name exists
  /// Rows of dataset `name`; throws if it does not exist or its columns differ from `cols`.
  std::size_t rows(const std::string& name, std::size_t cols = 1) const;
  /// Reads the whole dataset into `out` (room for rows(name, cols) * cols values). The stored
  /// element type must match exactly. Throws std::runtime_error naming the file and dataset.
  void read(const std::string& name, double* out, std::size_t cols = 1) const;
  void read(const std::string& name, std::int64_t* out, std::size_t cols = 1) const;
  void read(const std::string& name, std::int32_t* out, std::size_t cols = 1) const;
  void read(const std::string& name, std::uint8_t* out, std::size_t cols = 1) const;
  double get_f64(const std::string& name) const;
  std::int64_t get_i64(const std::string& name) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace porosph::io
