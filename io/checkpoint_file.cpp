#include "io/checkpoint_file.h"

#include <cstdio>
#include <stdexcept>

#include "io/hdf5_util.h"

namespace porosph::io {

using detail::check_hdf5;
using detail::Hdf5ErrorSilencer;
using detail::Hdf5Id;

namespace {

/// Writes one rows x cols dataset of `type` at the root of `file`.
void write_dataset(hid_t file, const std::string& where, const std::string& name, hid_t type,
                   const void* data, std::size_t rows, std::size_t cols) {
  Hdf5ErrorSilencer silence;
  const std::string at = where + " dataset '" + name + "'";
  if (cols == 0) throw std::runtime_error(at + ": cols must be at least 1");
  if (rows > 0 && data == nullptr) throw std::runtime_error(at + ": rows but no data");
  const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)};
  Hdf5Id space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose,
               at + ": cannot create dataspace");
  Hdf5Id dataset(
      H5Dcreate2(file, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, at + ": cannot create dataset");
  if (rows > 0) {
    check_hdf5(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
               at + ": cannot write");
  }
  dataset.close(at + ": cannot close");
}

template <class T>
void write_attribute(hid_t file, const std::string& where, const std::string& name, hid_t type,
                     T value) {
  Hdf5ErrorSilencer silence;
  const std::string at = where + " scalar '" + name + "'";
  Hdf5Id scalar(H5Screate(H5S_SCALAR), H5Sclose, at);
  Hdf5Id attribute(H5Acreate2(file, name.c_str(), type, scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose, at + ": cannot create");
  check_hdf5(H5Awrite(attribute.get(), type, &value), at + ": cannot write");
}

}  // namespace

struct CheckpointWriter::Impl {
  std::string path, tmp;
  Hdf5Id file;
  bool committed = false;
  std::string where() const { return "CheckpointWriter('" + tmp + "')"; }
};

CheckpointWriter::CheckpointWriter(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->tmp = path + ".tmp";
  Hdf5ErrorSilencer silence;
  impl_->file = Hdf5Id(H5Fcreate(impl_->tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                       H5Fclose, impl_->where() + ": cannot create the file");
}

CheckpointWriter::~CheckpointWriter() {
  if (impl_->committed) return;
  impl_->file = Hdf5Id();  // closes (errors silenced by the destructor of Hdf5Id)
  std::remove(impl_->tmp.c_str());
}

void CheckpointWriter::write(const std::string& name, const double* data, std::size_t rows,
                             std::size_t cols) {
  write_dataset(impl_->file.get(), impl_->where(), name, H5T_NATIVE_DOUBLE, data, rows, cols);
}
void CheckpointWriter::write(const std::string& name, const std::int64_t* data, std::size_t rows,
                             std::size_t cols) {
  write_dataset(impl_->file.get(), impl_->where(), name, H5T_NATIVE_INT64, data, rows, cols);
}
void CheckpointWriter::write(const std::string& name, const std::int32_t* data, std::size_t rows,
                             std::size_t cols) {
  write_dataset(impl_->file.get(), impl_->where(), name, H5T_NATIVE_INT32, data, rows, cols);
}
void CheckpointWriter::write(const std::string& name, const std::uint8_t* data, std::size_t rows,
                             std::size_t cols) {
  write_dataset(impl_->file.get(), impl_->where(), name, H5T_NATIVE_UINT8, data, rows, cols);
}
void CheckpointWriter::set(const std::string& name, double value) {
  write_attribute(impl_->file.get(), impl_->where(), name, H5T_NATIVE_DOUBLE, value);
}
void CheckpointWriter::set(const std::string& name, std::int64_t value) {
  write_attribute(impl_->file.get(), impl_->where(), name, H5T_NATIVE_INT64, value);
}

void CheckpointWriter::commit() {
  Hdf5ErrorSilencer silence;
  check_hdf5(H5Fflush(impl_->file.get(), H5F_SCOPE_LOCAL), impl_->where() + ": cannot flush");
  impl_->file.close(impl_->where() + ": cannot close");
  if (std::rename(impl_->tmp.c_str(), impl_->path.c_str()) != 0) {
    throw std::runtime_error(impl_->where() + ": cannot rename to '" + impl_->path + "'");
  }
  impl_->committed = true;
}

struct CheckpointReader::Impl {
  std::string path;
  Hdf5Id file;
  std::string where(const std::string& name) const {
    return "CheckpointReader('" + path + "') '" + name + "'";
  }

  /// Opens dataset `name`, checks its element type and columns; returns it and its rows.
  Hdf5Id open(const std::string& name, hid_t memory_type, std::size_t cols,
              std::size_t* rows) const {
    const std::string at = where(name);
    if (H5Lexists(file.get(), name.c_str(), H5P_DEFAULT) <= 0) {
      throw std::runtime_error(at + ": no such dataset (a checkpoint of another version?)");
    }
    Hdf5Id dataset(H5Dopen2(file.get(), name.c_str(), H5P_DEFAULT), H5Dclose, at);
    Hdf5Id type(H5Dget_type(dataset.get()), H5Tclose, at);
    if (H5Tequal(type.get(), memory_type) <= 0 &&
        (H5Tget_class(type.get()) != H5Tget_class(memory_type) ||
         H5Tget_size(type.get()) != H5Tget_size(memory_type) ||
         (H5Tget_class(type.get()) == H5T_INTEGER &&
          H5Tget_sign(type.get()) != H5Tget_sign(memory_type)))) {
      throw std::runtime_error(at + ": stored with another element type");
    }
    Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose, at);
    hsize_t dims[2] = {0, 1};
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 1 || rank > 2) throw std::runtime_error(at + ": rank must be 1 or 2");
    H5Sget_simple_extent_dims(space.get(), dims, nullptr);
    const std::size_t stored_cols = rank == 1 ? 1 : static_cast<std::size_t>(dims[1]);
    if (stored_cols != cols) {
      throw std::runtime_error(at + ": " + std::to_string(stored_cols) + " columns, expected " +
                               std::to_string(cols));
    }
    *rows = static_cast<std::size_t>(dims[0]);
    return dataset;
  }

  void read(const std::string& name, hid_t memory_type, void* out, std::size_t cols) const {
    Hdf5ErrorSilencer silence;
    std::size_t rows = 0;
    Hdf5Id dataset = open(name, memory_type, cols, &rows);
    if (rows == 0) return;
    check_hdf5(H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out),
               where(name) + ": cannot read");
  }

  template <class T>
  T attribute(const std::string& name, hid_t memory_type) const {
    Hdf5ErrorSilencer silence;
    const std::string at = where(name);
    if (H5Aexists(file.get(), name.c_str()) <= 0) throw std::runtime_error(at + ": no such scalar");
    Hdf5Id attribute(H5Aopen(file.get(), name.c_str(), H5P_DEFAULT), H5Aclose, at);
    T value{};
    check_hdf5(H5Aread(attribute.get(), memory_type, &value), at + ": cannot read");
    return value;
  }
};

CheckpointReader::CheckpointReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  Hdf5ErrorSilencer silence;
  impl_->file = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                       "CheckpointReader: cannot open checkpoint file '" + path + "'");
}

CheckpointReader::~CheckpointReader() = default;

const std::string& CheckpointReader::path() const { return impl_->path; }

bool CheckpointReader::has(const std::string& name) const {
  Hdf5ErrorSilencer silence;
  return H5Lexists(impl_->file.get(), name.c_str(), H5P_DEFAULT) > 0 ||
         H5Aexists(impl_->file.get(), name.c_str()) > 0;
}

std::size_t CheckpointReader::rows(const std::string& name, std::size_t cols) const {
  Hdf5ErrorSilencer silence;
  std::size_t rows = 0;
  // The element type is not known here: accept whatever is stored.
  const std::string at = impl_->where(name);
  if (H5Lexists(impl_->file.get(), name.c_str(), H5P_DEFAULT) <= 0) {
    throw std::runtime_error(at + ": no such dataset (a checkpoint of another version?)");
  }
  Hdf5Id dataset(H5Dopen2(impl_->file.get(), name.c_str(), H5P_DEFAULT), H5Dclose, at);
  Hdf5Id type(H5Dget_type(dataset.get()), H5Tclose, at);
  Hdf5Id native(H5Tget_native_type(type.get(), H5T_DIR_DEFAULT), H5Tclose, at);
  impl_->open(name, native.get(), cols, &rows);
  return rows;
}

void CheckpointReader::read(const std::string& name, double* out, std::size_t cols) const {
  impl_->read(name, H5T_NATIVE_DOUBLE, out, cols);
}
void CheckpointReader::read(const std::string& name, std::int64_t* out, std::size_t cols) const {
  impl_->read(name, H5T_NATIVE_INT64, out, cols);
}
void CheckpointReader::read(const std::string& name, std::int32_t* out, std::size_t cols) const {
  impl_->read(name, H5T_NATIVE_INT32, out, cols);
}
void CheckpointReader::read(const std::string& name, std::uint8_t* out, std::size_t cols) const {
  impl_->read(name, H5T_NATIVE_UINT8, out, cols);
}
double CheckpointReader::get_f64(const std::string& name) const {
  return impl_->attribute<double>(name, H5T_NATIVE_DOUBLE);
}
std::int64_t CheckpointReader::get_i64(const std::string& name) const {
  return impl_->attribute<std::int64_t>(name, H5T_NATIVE_INT64);
}

}  // namespace porosph::io
