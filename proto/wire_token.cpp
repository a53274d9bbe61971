#include "proto/wire_token.h"

#include <limits>

#include "proto/porosph.pb.h"
#include "proto/wire_field_codec.h"

namespace porosph::wire {
using namespace field;

namespace {

constexpr int kTokenField = Envelope::kRunTokenFieldNumber;

/// Skips one top-level field after its tag; false when it does not parse.
bool skip_field(CodedInputStream& in, std::uint32_t tag) {
  switch (WireFormatLite::GetTagWireType(tag)) {
    case WireFormatLite::WIRETYPE_VARINT: {
      std::uint64_t ignored = 0;
      return in.ReadVarint64(&ignored);
    }
    case WireFormatLite::WIRETYPE_FIXED64:
      return in.Skip(8);
    case WireFormatLite::WIRETYPE_FIXED32:
      return in.Skip(4);
    case WireFormatLite::WIRETYPE_LENGTH_DELIMITED: {
      std::uint32_t length = 0;
      return in.ReadVarint32(&length) && in.BytesUntilLimit() >= 0 &&
             static_cast<std::int64_t>(length) <= in.BytesUntilLimit() &&
             in.Skip(static_cast<int>(length));
    }
    default:
      return false;  // groups: no Envelope has them
  }
}

}  // namespace

std::size_t token_field_bytes(std::string_view token) {
  return token.empty() ? 0 : delimited_bytes(kTokenField, token.size());
}

std::uint8_t* write_token_field(std::string_view token, std::uint8_t* out) {
  if (token.empty()) return out;
  out = write_length(kTokenField, token.size(), out);
  std::memcpy(out, token.data(), token.size());
  return out + token.size();
}

bool split_run_token(const void* data, std::size_t size, std::string_view* token,
                     const std::uint8_t** rest, std::size_t* rest_size) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  CodedInputStream in(bytes, static_cast<int>(size));
  const CodedInputStream::Limit limit = in.PushLimit(static_cast<int>(size));
  std::size_t token_begin = 0, token_end = 0, token_value = 0;
  int tokens = 0;
  while (in.BytesUntilLimit() > 0) {
    const auto begin = static_cast<std::size_t>(in.CurrentPosition());
    const std::uint32_t tag = in.ReadTag();
    if (tag == 0) return false;
    if (tag == WireFormatLite::MakeTag(kTokenField, kDelimited)) {
      std::uint32_t length = 0;
      if (!in.ReadVarint32(&length) || static_cast<std::int64_t>(length) > in.BytesUntilLimit()) {
        return false;
      }
      token_value = static_cast<std::size_t>(in.CurrentPosition());
      if (!in.Skip(static_cast<int>(length))) return false;
      token_begin = begin;
      token_end = static_cast<std::size_t>(in.CurrentPosition());
      ++tokens;
    } else if (!skip_field(in, tag)) {
      return false;
    }
  }
  in.PopLimit(limit);
  if (tokens != 1) return false;
  *token =
      std::string_view(reinterpret_cast<const char*>(bytes) + token_value, token_end - token_value);
  if (token_end == size) {  // last: the usual place
    *rest = bytes;
    *rest_size = token_begin;
    return true;
  }
  if (token_begin == 0) {
    *rest = bytes + token_end;
    *rest_size = size - token_end;
    return true;
  }
  return false;
}

bool same_token(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  unsigned char difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    difference |= static_cast<unsigned char>(a[i] ^ b[i]);
  }
  return difference == 0;
}

}  // namespace porosph::wire
