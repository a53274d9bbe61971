#include "io/snapshot_reader.h"

#include <algorithm>
#include <stdexcept>

#include "io/hdf5_util.h"
#include "io/snapshot_writer.h"

namespace porosph::io {

using detail::check_hdf5;
using detail::Hdf5ErrorSilencer;
using detail::Hdf5Id;

std::string describe(StoredType type) {
  switch (type) {
    case StoredType::F64:
      return "Float 8";
    case StoredType::I64:
      return "Int 8";
    case StoredType::U8:
      return "UChar 1";
    default:
      return "other type";
  }
}

namespace {

StoredType classify(hid_t type) {
  const H5T_class_t type_class = H5Tget_class(type);
  const std::size_t size = H5Tget_size(type);
  if (type_class == H5T_FLOAT && size == 8) return StoredType::F64;
  if (type_class == H5T_INTEGER) {
    const H5T_sign_t sign = H5Tget_sign(type);
    if (size == 8 && sign == H5T_SGN_2) return StoredType::I64;
    if (size == 1 && sign == H5T_SGN_NONE) return StoredType::U8;
  }
  return StoredType::Other;
}

/// Names of the links in a group, sorted.
std::vector<std::string> link_names(hid_t group, const std::string& where) {
  H5G_info_t info;
  check_hdf5(H5Gget_info(group, &info), where + ": cannot list group");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length =
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length < 0) detail::throw_hdf5_error(where + ": cannot read link name");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

struct SnapshotReader::Impl {
  std::string path;
  Hdf5Id file;

  std::string where(const std::string& object) const {
    return "SnapshotReader('" + path + "') " + object;
  }

  template <class T>
  FieldData<T> read(std::uint32_t index, const std::string& name, StoredType expected,
                    hid_t memory_type) const {
    const std::string dataset_path = snapshot_group(index) + "/" + name;
    const std::string at = where(dataset_path);
    DatasetInfo info = dataset_info(dataset_path);
    if (info.type != expected) {
      throw std::runtime_error(at + ": holds " + describe(info.type) + ", not " +
                               describe(expected));
    }
    if (info.rank != 1 && info.rank != 2) {
      throw std::runtime_error(at + ": rank " + std::to_string(info.rank) + " is not 1 or 2");
    }
    FieldData<T> data;
    data.rows = info.rows;
    data.cols = info.cols;
    data.values.resize(info.rows * info.cols);
    if (data.values.empty()) return data;
    Hdf5ErrorSilencer silence;
    Hdf5Id dataset(H5Dopen2(file.get(), dataset_path.c_str(), H5P_DEFAULT), H5Dclose,
                   at + ": cannot open dataset");
    check_hdf5(
        H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.values.data()),
        at + ": cannot read dataset");
    return data;
  }

  DatasetInfo dataset_info(const std::string& dataset_path) const {
    const std::string at = where(dataset_path);
    Hdf5ErrorSilencer silence;
    Hdf5Id dataset(H5Dopen2(file.get(), dataset_path.c_str(), H5P_DEFAULT), H5Dclose,
                   at + ": cannot open dataset");
    Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose, at + ": cannot get dataspace");
    Hdf5Id type(H5Dget_type(dataset.get()), H5Tclose, at + ": cannot get type");
    DatasetInfo info;
    info.rank = H5Sget_simple_extent_ndims(space.get());
    if (info.rank < 0) detail::throw_hdf5_error(at + ": cannot get rank");
    std::vector<hsize_t> dims(static_cast<std::size_t>(info.rank));
    if (info.rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0) {
      detail::throw_hdf5_error(at + ": cannot get dimensions");
    }
    info.dims.assign(dims.begin(), dims.end());
    info.rows = info.rank >= 1 ? static_cast<std::size_t>(dims[0]) : 1;
    info.cols = info.rank >= 2 ? static_cast<std::size_t>(dims[1]) : 1;
    info.type = classify(type.get());
    return info;
  }
};

SnapshotReader::SnapshotReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  Hdf5ErrorSilencer silence;
  impl_->file = Hdf5Id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                       "SnapshotReader: cannot open HDF5 file '" + path + "'");
}

SnapshotReader::~SnapshotReader() = default;

const std::string& SnapshotReader::path() const { return impl_->path; }

std::vector<SnapshotInfo> SnapshotReader::snapshots() const {
  const std::string at = impl_->where("/snapshots");
  Hdf5ErrorSilencer silence;
  Hdf5Id group(H5Gopen2(impl_->file.get(), "/snapshots", H5P_DEFAULT), H5Gclose,
               at + ": cannot open group");
  std::vector<SnapshotInfo> result;
  for (const std::string& name : link_names(group.get(), at)) {
    const std::string name_at = impl_->where("/snapshots/" + name);
    SnapshotInfo info;
    try {
      std::size_t used = 0;
      const unsigned long index = std::stoul(name, &used);
      if (used != name.size() || index > 0xFFFFFFFFul) throw std::out_of_range(name);
      info.index = static_cast<std::uint32_t>(index);
    } catch (const std::logic_error&) {
      throw std::runtime_error(name_at + ": group name is not a snapshot index");
    }
    Hdf5Id snapshot(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT), H5Gclose,
                    name_at + ": cannot open group");
    Hdf5Id attribute(H5Aopen(snapshot.get(), "time", H5P_DEFAULT), H5Aclose,
                     name_at + ": cannot open attribute `time`");
    check_hdf5(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &info.time),
               name_at + ": cannot read attribute `time`");
    result.push_back(info);
  }
  std::sort(result.begin(), result.end(),
            [](const SnapshotInfo& a, const SnapshotInfo& b) { return a.index < b.index; });
  return result;
}

std::vector<std::string> SnapshotReader::fields(std::uint32_t index) const {
  const std::string group_name = snapshot_group(index);
  const std::string at = impl_->where(group_name);
  Hdf5ErrorSilencer silence;
  Hdf5Id group(H5Gopen2(impl_->file.get(), group_name.c_str(), H5P_DEFAULT), H5Gclose,
               at + ": cannot open group");
  return link_names(group.get(), at);
}

bool SnapshotReader::exists(const std::string& object_path) const {
  if (object_path.empty() || object_path[0] != '/') return false;
  Hdf5ErrorSilencer silence;
  // Walk the path one component at a time: H5Lexists fails (rather than returning 0) if an
  // intermediate group is missing.
  std::string prefix;
  std::size_t start = 1;
  while (start <= object_path.size()) {
    std::size_t end = object_path.find('/', start);
    if (end == std::string::npos) end = object_path.size();
    if (end == start) {  // "//" or a trailing '/': nothing to check
      start = end + 1;
      continue;
    }
    prefix += "/" + object_path.substr(start, end - start);
    if (H5Lexists(impl_->file.get(), prefix.c_str(), H5P_DEFAULT) <= 0) {
      H5Eclear2(H5E_DEFAULT);
      return false;
    }
    start = end + 1;
  }
  return true;
}

DatasetInfo SnapshotReader::dataset_info(const std::string& dataset_path) const {
  return impl_->dataset_info(dataset_path);
}

FieldData<double> SnapshotReader::read_f64(std::uint32_t index, const std::string& name) const {
  return impl_->read<double>(index, name, StoredType::F64, H5T_NATIVE_DOUBLE);
}

FieldData<std::int64_t> SnapshotReader::read_i64(std::uint32_t index,
                                                 const std::string& name) const {
  return impl_->read<std::int64_t>(index, name, StoredType::I64, H5T_NATIVE_INT64);
}

FieldData<std::uint8_t> SnapshotReader::read_u8(std::uint32_t index,
                                                const std::string& name) const {
  return impl_->read<std::uint8_t>(index, name, StoredType::U8, H5T_NATIVE_UINT8);
}

}  // namespace porosph::io
