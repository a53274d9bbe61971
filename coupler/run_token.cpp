#include "coupler/run_token.h"

#include <sys/random.h>

#include <cerrno>
#include <cstddef>
#include <stdexcept>

namespace porosph::coupler {

std::string fresh_run_token() {
  unsigned char random[32];
  std::size_t got = 0;
  while (got < sizeof random) {
    const ssize_t n = ::getrandom(random + got, sizeof random - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot draw a run token: no random source");
    got += static_cast<std::size_t>(n);
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  token.reserve(2 * sizeof random);
  for (const unsigned char byte : random) {
    token += kHex[byte >> 4];
    token += kHex[byte & 15];
  }
  return token;
}

std::string printable(std::string_view claimed) {
  std::string result;
  for (const char c : claimed.substr(0, 64)) result += (c >= 32 && c < 127) ? c : '?';
  return result;
}

}  // namespace porosph::coupler
