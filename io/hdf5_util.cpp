#include "io/hdf5_util.h"

#include <stdexcept>
#include <utility>
#include <vector>

namespace porosph::io::detail {

Hdf5ErrorSilencer::Hdf5ErrorSilencer() {
  H5Eget_auto2(H5E_DEFAULT, &previous_function_, &previous_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Hdf5ErrorSilencer::~Hdf5ErrorSilencer() {
  H5Eset_auto2(H5E_DEFAULT, previous_function_, previous_data_);
}

namespace {
herr_t collect_description(unsigned, const H5E_error2_t* error, void* client_data) {
  auto* descriptions = static_cast<std::vector<std::string>*>(client_data);
  if (error != nullptr && error->desc != nullptr && error->desc[0] != '\0') {
    std::string text = error->desc;
    for (char& c : text) {
      if (c == '\n' || c == '\r') c = ' ';  // HDF5 embeds ctime() output with its newline
    }
    descriptions->push_back(text);
  }
  return 0;
}
}  // namespace

std::string hdf5_error_details() {
  std::vector<std::string> descriptions;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_description, &descriptions);
  H5Eclear2(H5E_DEFAULT);
  if (descriptions.empty()) return "no HDF5 error details";
  // The outermost entry says what failed, the innermost why (e.g. errno text); the middle of the
  // stack is HDF5-internal.
  if (descriptions.size() == 1) return descriptions.front();
  return descriptions.front() + "; " + descriptions.back();
}

void throw_hdf5_error(const std::string& context) {
  throw std::runtime_error(context + ": " + hdf5_error_details());
}

Hdf5Id::Hdf5Id(hid_t id, Closer closer, const std::string& context) : id_(id), closer_(closer) {
  if (id_ < 0) throw_hdf5_error(context);
}

Hdf5Id::~Hdf5Id() { reset(); }

Hdf5Id::Hdf5Id(Hdf5Id&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

Hdf5Id& Hdf5Id::operator=(Hdf5Id&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

void Hdf5Id::close(const std::string& context) {
  if (id_ < 0) return;
  const hid_t id = std::exchange(id_, H5I_INVALID_HID);
  check_hdf5(closer_(id), context);
}

void Hdf5Id::reset() noexcept {
  if (id_ >= 0 && closer_ != nullptr) {
    Hdf5ErrorSilencer silence;
    closer_(id_);
  }
  id_ = H5I_INVALID_HID;
}

}  // namespace porosph::io::detail
