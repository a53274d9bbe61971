// The check a solver makes on a string key of a scene it did not load itself (a scene built in
// code skips the loader's allowed values): one way to say which values a key takes.
#pragma once

#include <initializer_list>
#include <stdexcept>
#include <string>

namespace porosph::scene {

/// `value` when it is one of `allowed`; otherwise throws std::invalid_argument
/// "<key>: expected a, b or c, got '<value>'".
inline const std::string& checked_choice(const std::string& key, const std::string& value,
                                         std::initializer_list<const char*> allowed) {
  std::string list;
  std::size_t i = 0;
  for (const char* option : allowed) {
    if (value == option) return value;
    list += (i == 0 ? "" : (i + 1 == allowed.size() ? " or " : ", ")) + std::string(option);
    ++i;
  }
  throw std::invalid_argument(key + ": expected " + list + ", got '" + value + "'");
}

}  // namespace porosph::scene
