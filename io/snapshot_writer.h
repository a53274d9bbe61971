// HDF5 particle snapshots in the layout pinned by DESIGN.md section 6:
//   /snapshots/NNNNNN/            group per output (6-digit zero-padded index), attribute `time`
//   /snapshots/NNNNNN/<field>     one dataset per field, one row per particle (N or N x cols)
// The file is flushed after every snapshot so that a run that fails keeps every snapshot written.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace porosph::io {

/// A read-only view of one per-particle field. Exactly one of the data pointers is set.
struct FieldView {
  std::string name;
  std::size_t rows = 0;  ///< particles
  std::size_t cols = 1;  ///< 1 for scalars, D for vectors, 9 for a 3x3 tensor (row-major)
  const double* f64 = nullptr;
  const std::int64_t* i64 = nullptr;
  const std::uint8_t* u8 = nullptr;
};

class SnapshotWriter {
 public:
  /// Creates (truncates) the file. Throws std::runtime_error naming the path on failure.
  explicit SnapshotWriter(const std::string& path);
  ~SnapshotWriter();
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  /// Writes /snapshots/<index>/ with attribute time and one dataset per field, then flushes.
  void write(std::uint32_t index, double time, const std::vector<FieldView>& fields);

  const std::string& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Group name of snapshot `index`, e.g. "/snapshots/000012".
std::string snapshot_group(std::uint32_t index);

}  // namespace porosph::io
