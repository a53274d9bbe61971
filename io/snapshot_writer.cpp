#include "io/snapshot_writer.h"

#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "io/hdf5_util.h"

namespace porosph::io {

using detail::check_hdf5;
using detail::Hdf5ErrorSilencer;
using detail::Hdf5Id;

std::string snapshot_group(std::uint32_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "/snapshots/%06u", static_cast<unsigned>(index));
  return name;
}

namespace {

template <class T>
FieldView make_view(const std::string& name, const std::vector<T>& values, std::size_t cols,
                    FieldType type) {
  if (cols == 0 || values.size() % cols != 0) {
    throw std::runtime_error("field_view('" + name + "'): " + std::to_string(values.size()) +
                             " values do not form rows of " + std::to_string(cols) + " columns");
  }
  FieldView view;
  view.name = name;
  view.rows = values.size() / cols;
  view.cols = cols;
  view.type = type;
  return view;
}

/// The element type a field will be written with, after checking the view is well formed.
FieldType checked_type(const FieldView& field, const std::string& where);

}  // namespace

FieldType stored_type(const FieldView& field) {
  if (field.f64 != nullptr) return FieldType::F64;
  if (field.i64 != nullptr) return FieldType::I64;
  if (field.u8 != nullptr) return FieldType::U8;
  return field.type;
}

namespace {

FieldType checked_type(const FieldView& field, const std::string& where) {
  const int pointers_set = (field.f64 != nullptr) + (field.i64 != nullptr) + (field.u8 != nullptr);
  if (pointers_set > 1) throw std::runtime_error(where + ": more than one data pointer is set");
  const FieldType from_pointer = field.f64 != nullptr   ? FieldType::F64
                                 : field.i64 != nullptr ? FieldType::I64
                                 : field.u8 != nullptr  ? FieldType::U8
                                                        : FieldType::FromPointer;
  if (field.name.empty() || field.name.find('/') != std::string::npos || field.name == ".") {
    throw std::runtime_error(where + ": field name must be non-empty and contain no '/'");
  }
  if (field.cols == 0) throw std::runtime_error(where + ": cols must be at least 1");
  if (field.rows > 0 && from_pointer == FieldType::FromPointer) {
    throw std::runtime_error(where + ": " + std::to_string(field.rows) + " rows but no data");
  }
  if (from_pointer != FieldType::FromPointer && field.type != FieldType::FromPointer &&
      field.type != from_pointer) {
    throw std::runtime_error(where + ": `type` contradicts the data pointer that is set");
  }
  const FieldType type = from_pointer != FieldType::FromPointer ? from_pointer : field.type;
  if (type == FieldType::FromPointer) {
    throw std::runtime_error(where + ": empty field without data pointer needs `type`");
  }
  return type;
}

hid_t native_type(FieldType type) {
  switch (type) {
    case FieldType::F64:
      return H5T_NATIVE_DOUBLE;
    case FieldType::I64:
      return H5T_NATIVE_INT64;
    default:
      return H5T_NATIVE_UINT8;
  }
}

const void* data_pointer(const FieldView& field) {
  if (field.f64 != nullptr) return field.f64;
  if (field.i64 != nullptr) return field.i64;
  return field.u8;
}

}  // namespace

FieldView field_view(const std::string& name, const std::vector<double>& values, std::size_t cols) {
  FieldView view = make_view(name, values, cols, FieldType::F64);
  if (!values.empty()) view.f64 = values.data();
  return view;
}

FieldView field_view(const std::string& name, const std::vector<std::int64_t>& values,
                     std::size_t cols) {
  FieldView view = make_view(name, values, cols, FieldType::I64);
  if (!values.empty()) view.i64 = values.data();
  return view;
}

FieldView field_view(const std::string& name, const std::vector<std::uint8_t>& values,
                     std::size_t cols) {
  FieldView view = make_view(name, values, cols, FieldType::U8);
  if (!values.empty()) view.u8 = values.data();
  return view;
}

/// Where a snapshot is written until it is complete; then it is moved (renamed) into /snapshots,
/// so that a reader never sees a half-written snapshot there. A failed write deletes it; a
/// leftover of a killed process is deleted by the next writer.
constexpr const char* kPartialGroup = "/partial_snapshot";
/// Where unchanging fields live (one dataset each, hard-linked from every snapshot).
constexpr const char* kStaticGroup = "/static";

struct SnapshotWriter::Impl {
  std::string path;
  Hdf5Id file;
};

SnapshotWriter::SnapshotWriter(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  Hdf5ErrorSilencer silence;
  const std::string where = "SnapshotWriter: cannot create HDF5 file '" + path + "'";
  impl_->file =
      Hdf5Id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, where);
  Hdf5Id group(H5Gcreate2(impl_->file.get(), "/snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Gclose, where);
  check_hdf5(H5Fflush(impl_->file.get(), H5F_SCOPE_LOCAL), where);
}

SnapshotWriter::SnapshotWriter(const std::string& path, std::uint32_t first_dropped)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  Hdf5ErrorSilencer silence;
  const std::string where = "SnapshotWriter: cannot reopen HDF5 file '" + path + "'";
  if (!std::filesystem::exists(path)) {
    impl_->file =
        Hdf5Id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, where);
  } else {
    impl_->file = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, where);
  }
  const hid_t file = impl_->file.get();
  if (H5Lexists(file, "/snapshots", H5P_DEFAULT) <= 0) {
    Hdf5Id group(H5Gcreate2(file, "/snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 where);
  }
  if (H5Lexists(file, kPartialGroup, H5P_DEFAULT) > 0) {
    check_hdf5(H5Ldelete(file, kPartialGroup, H5P_DEFAULT),
               where + ": cannot delete " + std::string(kPartialGroup));
  }
  // Groups are named by their zero-padded index: probe upwards from first_dropped until a gap of
  // indices no writer leaves (outputs are consecutive).
  for (std::uint32_t index = first_dropped;; ++index) {
    const std::string name = snapshot_group(index);
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) break;
    check_hdf5(H5Ldelete(file, name.c_str(), H5P_DEFAULT), where + ": cannot delete " + name);
  }
  check_hdf5(H5Fflush(file, H5F_SCOPE_LOCAL), where);
}

SnapshotWriter::~SnapshotWriter() = default;  // Hdf5Id closes the file (errors silenced).

const std::string& SnapshotWriter::path() const { return impl_->path; }

namespace {

/// Creates dataset `name` of `field` under `location` and writes its values.
void write_dataset(hid_t location, const FieldView& field, FieldType field_type,
                   const std::string& where) {
  const hsize_t dims[2] = {static_cast<hsize_t>(field.rows), static_cast<hsize_t>(field.cols)};
  const int rank = field.cols == 1 ? 1 : 2;
  Hdf5Id space(H5Screate_simple(rank, dims, nullptr), H5Sclose,
               where + ": cannot create dataspace");
  const hid_t type = native_type(field_type);
  Hdf5Id dataset(H5Dcreate2(location, field.name.c_str(), type, space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, where + ": cannot create dataset");
  if (field.rows > 0) {
    check_hdf5(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data_pointer(field)),
               where + ": cannot write dataset");
  }
  dataset.close(where + ": cannot close dataset");
}

/// /static/<name> for an unchanging field: written on first use, else checked to have the
/// field's shape and element type. Returns its path.
std::string static_dataset(hid_t file, const FieldView& field, FieldType field_type,
                           const std::string& where) {
  if (H5Lexists(file, kStaticGroup, H5P_DEFAULT) <= 0) {
    Hdf5Id group(H5Gcreate2(file, kStaticGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 where + ": cannot create " + kStaticGroup);
  }
  const std::string path = std::string(kStaticGroup) + "/" + field.name;
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) {
    Hdf5Id group(H5Gopen2(file, kStaticGroup, H5P_DEFAULT), H5Gclose, where + ": cannot open");
    write_dataset(group.get(), field, field_type, where + " (" + path + ")");
    return path;
  }
  Hdf5Id dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose, where + ": cannot open");
  Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose, where + ": cannot read the shape");
  Hdf5Id type(H5Dget_type(dataset.get()), H5Tclose, where + ": cannot read the type");
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank >= 1 && rank <= 2) H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (rank != (field.cols == 1 ? 1 : 2) || dims[0] != field.rows ||
      (rank == 2 && dims[1] != field.cols) || H5Tequal(type.get(), native_type(field_type)) <= 0) {
    throw std::runtime_error(where + ": an unchanging field whose shape or type differs from " +
                             path + "'s");
  }
  return path;
}

/// Writes a snapshot into kPartialGroup.
void write_partial_group(hid_t file, double time, const std::vector<FieldView>& fields,
                         const std::vector<FieldType>& types, const std::string& where) {
  Hdf5Id group(H5Gcreate2(file, kPartialGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               where + ": cannot create group");
  {
    Hdf5Id scalar(H5Screate(H5S_SCALAR), H5Sclose, where + ": attribute `time`");
    Hdf5Id attribute(
        H5Acreate2(group.get(), "time", H5T_NATIVE_DOUBLE, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose, where + ": cannot create attribute `time`");
    check_hdf5(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &time),
               where + ": cannot write attribute `time`");
  }

  for (std::size_t f = 0; f < fields.size(); ++f) {
    const FieldView& field = fields[f];
    const std::string field_where = where + "/" + field.name;
    if (!field.unchanging) {
      write_dataset(group.get(), field, types[f], field_where);
      continue;
    }
    const std::string target = static_dataset(file, field, types[f], field_where);
    check_hdf5(H5Lcreate_hard(file, target.c_str(), group.get(), field.name.c_str(), H5P_DEFAULT,
                              H5P_DEFAULT),
               field_where + ": cannot link " + target);
  }
  group.close(where + ": cannot close group");
}

}  // namespace

void SnapshotWriter::write(std::uint32_t index, double time, const std::vector<FieldView>& fields) {
  const std::string group_name = snapshot_group(index);
  const std::string where = "SnapshotWriter('" + impl_->path + "') " + group_name;

  std::vector<FieldType> types;
  std::set<std::string> names;
  for (const FieldView& field : fields) {
    types.push_back(checked_type(field, where + "/" + field.name));
    if (!names.insert(field.name).second) {
      throw std::runtime_error(where + ": field '" + field.name + "' given twice");
    }
  }

  Hdf5ErrorSilencer silence;
  const hid_t file = impl_->file.get();
  if (H5Lexists(file, group_name.c_str(), H5P_DEFAULT) > 0) {
    throw std::runtime_error(where + ": snapshot " + std::to_string(index) + " already written");
  }
  if (H5Lexists(file, kPartialGroup, H5P_DEFAULT) > 0) H5Ldelete(file, kPartialGroup, H5P_DEFAULT);
  try {
    write_partial_group(file, time, fields, types, where);
    check_hdf5(H5Lmove(file, kPartialGroup, file, group_name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
               where + ": cannot move the complete snapshot into place");
  } catch (...) {
    H5Ldelete(file, kPartialGroup, H5P_DEFAULT);  // best effort: no half snapshot stays
    throw;
  }
  check_hdf5(H5Fflush(file, H5F_SCOPE_LOCAL), where + ": cannot flush file");
}

}  // namespace porosph::io
