// Writing and restoring a solver's particle container (structure of arrays) in a checkpoint file
// (io/checkpoint_file.h). Every array the container's for_each_array visits is stored, as
// "particles_NN" in visiting order, so an array added to a container is checkpointed without
// further code; restoring checks the array count and each array's element type and width. Arrays
// are only ever added at the end of a container's list: restoring a checkpoint written before an
// array was added fills that array with zeros (value-initialised), so older runs still resume.
// Elements: double, int64, int32, uint8, and fixed-size Eigen matrices of doubles (Vec<D>, 3x3).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "io/checkpoint_file.h"

namespace porosph::sph {

namespace checkpoint_detail {

template <class T, class = void>
struct Element {  // scalars
  using Scalar = T;
  static constexpr std::size_t cols = 1;
};
template <class T>
struct Element<T, std::void_t<typename T::Scalar, decltype(T::SizeAtCompileTime)>> {
  using Scalar = typename T::Scalar;
  static constexpr std::size_t cols = static_cast<std::size_t>(T::SizeAtCompileTime);
  static_assert(sizeof(T) == cols * sizeof(Scalar), "Eigen element must be packed");
};

/// 0 for a scalar, the zero matrix for an Eigen element.
template <class T>
T zero_element() {
  if constexpr (std::is_arithmetic_v<T>) {
    return T{};
  } else {
    return T::Zero();
  }
}

inline std::string array_name(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "particles_%02d", k);
  return name;
}

template <class T, class Alloc>
const typename Element<T>::Scalar* scalars(const std::vector<T, Alloc>& a) {
  return a.empty() ? nullptr : reinterpret_cast<const typename Element<T>::Scalar*>(a.data());
}
template <class T, class Alloc>
typename Element<T>::Scalar* scalars(std::vector<T, Alloc>& a) {
  return a.empty() ? nullptr : reinterpret_cast<typename Element<T>::Scalar*>(a.data());
}

}  // namespace checkpoint_detail

/// Stores every array of `particles` and its n_free / size.
template <class Particles>
void write_particle_arrays(io::CheckpointWriter& out, Particles& particles) {
  using namespace checkpoint_detail;
  int k = 0;
  particles.for_each_array([&](const auto& array) {
    using T = typename std::decay_t<decltype(array)>::value_type;
    out.write(array_name(k++), scalars(array), array.size(), Element<T>::cols);
  });
  out.set("particles_arrays", static_cast<std::int64_t>(k));
  out.set("particles_count", static_cast<std::int64_t>(particles.size()));
  out.set("particles_n_free", static_cast<std::int64_t>(particles.n_free));
}

/// Replaces every array of `particles` (and n_free) with the stored ones. Throws
/// std::runtime_error naming the file if the file holds another set of arrays.
template <class Particles>
void read_particle_arrays(const io::CheckpointReader& in, Particles& particles) {
  using namespace checkpoint_detail;
  const std::int64_t count = in.get_i64("particles_count");
  const std::int64_t stored = in.get_i64("particles_arrays");
  int k = 0;
  particles.for_each_array([&](auto& array) {
    using T = typename std::decay_t<decltype(array)>::value_type;
    if (k >= stored) {  // an array added to the container after the checkpoint was written
      ++k;
      array.assign(static_cast<std::size_t>(count), zero_element<T>());
      return;
    }
    const std::string name = array_name(k++);
    const std::size_t rows = in.rows(name, Element<T>::cols);
    if (static_cast<std::int64_t>(rows) != count) {
      throw std::runtime_error(in.path() + ": " + name + " has " + std::to_string(rows) +
                               " rows, the checkpoint " + std::to_string(count) + " particles");
    }
    array.resize(rows);
    in.read(name, scalars(array), Element<T>::cols);
  });
  if (stored > k) {
    throw std::runtime_error(in.path() + ": written by a solver with another particle layout");
  }
  particles.n_free = static_cast<std::size_t>(in.get_i64("particles_n_free"));
}

}  // namespace porosph::sph
