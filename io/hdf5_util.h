// Internal helpers around the HDF5 C API for porosph_io (not part of the public interface):
// RAII ownership of HDF5 ids, scoped silencing of HDF5's automatic error printing, and turning a
// failed call into a std::runtime_error that carries HDF5's own error stack.
#pragma once

#include <hdf5.h>

#include <string>

namespace porosph::io::detail {

/// Turns off HDF5's automatic printing of error stacks to stderr for the lifetime of the object and
/// restores the previous handler afterwards (so nothing outside porosph_io is affected).
class Hdf5ErrorSilencer {
 public:
  Hdf5ErrorSilencer();
  ~Hdf5ErrorSilencer();
  Hdf5ErrorSilencer(const Hdf5ErrorSilencer&) = delete;
  Hdf5ErrorSilencer& operator=(const Hdf5ErrorSilencer&) = delete;

 private:
  H5E_auto2_t previous_function_ = nullptr;
  void* previous_data_ = nullptr;
};

/// The descriptions on HDF5's current error stack, outermost first, joined by "; ". Clears the
/// stack.
std::string hdf5_error_details();

/// Throws std::runtime_error("<context>: <HDF5 error details>").
[[noreturn]] void throw_hdf5_error(const std::string& context);

/// Owns one HDF5 id and closes it with the matching H5?close function.
class Hdf5Id {
 public:
  using Closer = herr_t (*)(hid_t);
  Hdf5Id() = default;
  /// Takes ownership of `id`; throws (with `context`) if the call that produced it failed (id < 0).
  Hdf5Id(hid_t id, Closer closer, const std::string& context);
  ~Hdf5Id();
  Hdf5Id(Hdf5Id&& other) noexcept;
  Hdf5Id& operator=(Hdf5Id&& other) noexcept;
  Hdf5Id(const Hdf5Id&) = delete;
  Hdf5Id& operator=(const Hdf5Id&) = delete;

  hid_t get() const { return id_; }
  /// Closes now; throws (with `context`) if closing fails (e.g. the final flush of a file).
  void close(const std::string& context);

 private:
  void reset() noexcept;
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// Throws (with `context`) if an HDF5 call returned a negative status.
inline void check_hdf5(herr_t status, const std::string& context) {
  if (status < 0) throw_hdf5_error(context);
}

}  // namespace porosph::io::detail
