// Deterministic per-particle test data covering every field type and shape the solvers write:
// vectors (N x D), scalars (N), a 3x3 tensor (N x 9), a 4-column matrix, int64 ids and uint8 flags,
// including extreme values (denormals, +-huge, int64 limits, 255) that must survive a round trip.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "io/snapshot_writer.h"
#include "io/xdmf_writer.h"

namespace porosph::test {

struct SampleSnapshot {
  int dimension = 2;
  std::vector<double> position, velocity, density, stress, extra;  // extra: N x 4
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> fixed;

  std::size_t count() const { return density.size(); }

  std::vector<io::FieldView> views() const {
    const auto d = static_cast<std::size_t>(dimension);
    return {io::field_view("position", position, d), io::field_view("velocity", velocity, d),
            io::field_view("density", density),      io::field_view("stress", stress, 9),
            io::field_view("extra", extra, 4),       io::field_view("id", id),
            io::field_view("fixed", fixed)};
  }

  /// The XDMF field list matching views() (position excluded: it is the Geometry).
  std::vector<io::XdmfField> xdmf_fields() const {
    const auto d = static_cast<std::size_t>(dimension);
    return {{"velocity", d, "Float"}, {"density", 1, "Float"}, {"stress", 9, "Float"},
            {"extra", 4, "Float"},    {"id", 1, "Int"},        {"fixed", 1, "UChar"}};
  }
};

/// `n` particles in `dimension` D; `seed` makes snapshots differ.
inline SampleSnapshot make_sample(std::size_t n, int dimension, int seed) {
  SampleSnapshot s;
  s.dimension = dimension;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dimension; ++k) {
      s.position.push_back(seed + 0.1 * static_cast<double>(i) + k / 3.0);
      s.velocity.push_back(-1.0 / (1.0 + static_cast<double>(i + k + seed)));
    }
    s.density.push_back(1000.0 + seed * 1e-9 + static_cast<double>(i) / 7.0);
    for (int k = 0; k < 9; ++k) s.stress.push_back(1e5 * (k - 4) + seed + static_cast<double>(i));
    for (int k = 0; k < 4; ++k) s.extra.push_back(static_cast<double>(k) * 0.25 + seed);
    s.id.push_back(static_cast<std::int64_t>(i) * 1000003 + seed);
    s.fixed.push_back(static_cast<std::uint8_t>((i + seed) % 2));
  }
  if (n >= 3) {
    s.density[0] = std::numeric_limits<double>::denorm_min();
    s.density[1] = -std::numeric_limits<double>::max();
    s.density[2] = 1.0 / 3.0;
    s.id[0] = std::numeric_limits<std::int64_t>::min();
    s.id[1] = std::numeric_limits<std::int64_t>::max();
    s.fixed[0] = 255;
  }
  return s;
}

}  // namespace porosph::test
