// Snapshot fields of particle arrays (io::FieldView with its unit), the one way every particle
// solver lists what its snapshot file holds (snapshot_fields(); the coupler's run.xdmf and
// run.json take the declaration from it).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/snapshot_writer.h"
#include "sph/vector.h"

namespace porosph::sph {

/// One value per particle (double, std::int64_t or std::uint8_t), in SI `unit` ("" for none).
template <class T>
io::FieldView scalar_field(const std::string& name, const std::vector<T>& values,
                           const std::string& unit = "") {
  io::FieldView field = io::field_view(name, values);
  field.unit = unit;
  return field;
}

/// One fixed-size Eigen value per particle (a D-vector, a 3x3 tensor stored as 9 doubles;
/// Eigen's fixed-size storage is contiguous), `cols` doubles each.
template <class Value>
io::FieldView packed_field(const std::string& name, const std::vector<Value>& values,
                           const std::string& unit = "") {
  io::FieldView field;
  field.name = name;
  field.unit = unit;
  field.rows = values.size();
  field.cols = static_cast<std::size_t>(Value::SizeAtCompileTime);
  field.f64 = values.empty() ? nullptr : values[0].data();
  field.type = io::FieldType::F64;
  return field;
}

}  // namespace porosph::sph
