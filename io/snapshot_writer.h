// HDF5 particle snapshots in the layout pinned by docs/design.md section 6:
//   /snapshots/NNNNNN/            group per output (6-digit zero-padded index), attribute `time`
//   /snapshots/NNNNNN/<field>     one dataset per field, one row per particle (N or N x cols)
//   /static/<field>               an unchanging field (FieldView::unchanging), stored once; every
//                                 snapshot's <field> is an HDF5 hard link to it, which every reader
//                                 (h5py, ParaView through run.xdmf, io::SnapshotReader) opens as an
//                                 ordinary dataset of that snapshot
// The file is flushed after every snapshot so that a run that fails keeps every snapshot written.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace porosph::io {

/// Element type of a field's dataset: f64 -> H5T_NATIVE_DOUBLE, i64 -> H5T_NATIVE_INT64,
/// u8 -> H5T_NATIVE_UINT8. `FromPointer` takes it from whichever data pointer is set.
enum class FieldType { FromPointer, F64, I64, U8 };

/// A read-only view of one per-particle field. Exactly one of the data pointers is set, except for
/// an empty field (rows == 0), whose pointer may be null: then `type` must say what it holds (the
/// field_view() helpers below always set it).
struct FieldView {
  std::string name;
  std::size_t rows = 0;  ///< particles
  std::size_t cols = 1;  ///< 1 for scalars, D for vectors, 9 for a 3x3 tensor (row-major)
  const double* f64 = nullptr;
  const std::int64_t* i64 = nullptr;
  const std::uint8_t* u8 = nullptr;
  FieldType type = FieldType::FromPointer;
  /// The field holds the same values in every snapshot of the file (a rigid skeleton's position,
  /// its zero stress): the first write stores it as /static/<name>, every snapshot links it there.
  bool unchanging = false;
  /// SI unit, for the field list the solver declares (run.json, docs); empty: none.
  std::string unit;
};

/// The element type a field's dataset gets (from its data pointer or `type`); FromPointer for an
/// empty field that says neither.
FieldType stored_type(const FieldView& field);

/// Views of a row-major array of rows x cols values (rows = values.size() / cols); they set `type`,
/// so they also work for empty vectors. Throw std::runtime_error if values.size() % cols != 0.
FieldView field_view(const std::string& name, const std::vector<double>& values,
                     std::size_t cols = 1);
FieldView field_view(const std::string& name, const std::vector<std::int64_t>& values,
                     std::size_t cols = 1);
FieldView field_view(const std::string& name, const std::vector<std::uint8_t>& values,
                     std::size_t cols = 1);

class SnapshotWriter {
 public:
  /// Creates (truncates) the file. Throws std::runtime_error naming the path on failure.
  explicit SnapshotWriter(const std::string& path);
  /// Resume (docs/checkpoints.md): opens the existing file and deletes the snapshot groups with
  /// index >= first_dropped (written after the checkpoint the run resumes from); a missing file is
  /// created. Throws std::runtime_error naming the path on failure.
  SnapshotWriter(const std::string& path, std::uint32_t first_dropped);
  ~SnapshotWriter();
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  /// Writes /snapshots/<index>/ with attribute time and one dataset per field, then flushes.
  /// Dataset shape: (rows) if cols == 1 else (rows, cols); rows may be 0. An `unchanging` field is
  /// written to /static/<name> the first time (also when the file was reopened for a resume
  /// without it) and hard-linked afterwards; a later snapshot whose unchanging field has another
  /// shape or type throws. All fields are validated before anything is written. Throws
  /// std::runtime_error naming the file (and the field) if a field is malformed, the index was
  /// already written, or HDF5 fails.
  void write(std::uint32_t index, double time, const std::vector<FieldView>& fields);

  const std::string& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Group name of snapshot `index`, e.g. "/snapshots/000012".
std::string snapshot_group(std::uint32_t index);

}  // namespace porosph::io
