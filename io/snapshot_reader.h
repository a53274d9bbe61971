// Read side of the snapshot layout written by SnapshotWriter (see snapshot_writer.h), for tests and
// post-processing tools: list the snapshots of a file with their times, list and read their fields,
// and inspect any dataset's shape and element type. Every failure throws std::runtime_error naming
// the file and the dataset.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace porosph::io {

/// One snapshot group /snapshots/NNNNNN and its `time` attribute.
struct SnapshotInfo {
  std::uint32_t index = 0;
  double time = 0;
};

/// Element type of a stored dataset, as the writer produces them.
enum class StoredType {
  F64,   ///< 8-byte float
  I64,   ///< 8-byte signed integer
  U8,    ///< 1-byte unsigned integer
  Other  ///< anything else
};

/// Shape and element type of one dataset. cols is 1 for rank-1 datasets.
struct DatasetInfo {
  int rank = 0;
  std::vector<std::uint64_t> dims;
  std::size_t rows = 0;
  std::size_t cols = 1;
  StoredType type = StoredType::Other;
};

/// A field read back: `values` is row-major, rows x cols.
template <class T>
struct FieldData {
  std::vector<T> values;
  std::size_t rows = 0;
  std::size_t cols = 1;
};

class SnapshotReader {
 public:
  /// Opens the file read-only. Throws std::runtime_error naming the path on failure.
  explicit SnapshotReader(const std::string& path);
  ~SnapshotReader();
  SnapshotReader(const SnapshotReader&) = delete;
  SnapshotReader& operator=(const SnapshotReader&) = delete;

  const std::string& path() const;

  /// All snapshots in the file, sorted by index.
  std::vector<SnapshotInfo> snapshots() const;
  /// Names of the datasets of snapshot `index`, sorted by name.
  std::vector<std::string> fields(std::uint32_t index) const;

  /// Whether an object exists at the absolute HDF5 path (e.g. "/snapshots/000001/position").
  bool exists(const std::string& object_path) const;
  /// Shape and element type of the dataset at an absolute HDF5 path.
  DatasetInfo dataset_info(const std::string& dataset_path) const;

  /// Read field `name` of snapshot `index`. The stored element type must match exactly (no silent
  /// conversion), and the dataset must have rank 1 or 2.
  FieldData<double> read_f64(std::uint32_t index, const std::string& name) const;
  FieldData<std::int64_t> read_i64(std::uint32_t index, const std::string& name) const;
  FieldData<std::uint8_t> read_u8(std::uint32_t index, const std::string& name) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// "Float 8", "Int 8", "UChar 1" or "other type" (for messages).
std::string describe(StoredType type);

}  // namespace porosph::io
