// pressure_at (sph/observable_reductions.h) is first-order: a linear pressure field is reproduced
// to round-off at a probe beside a wall, in a corner and inside the water, where the Shepard
// average of the same stencil is off by the pressure difference between the probe and the
// stencil's centroid; a stencil that cannot fix a slope falls back to the Shepard value.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sph/kernels.h"
#include "sph/observable_reductions.h"

namespace porosph::sph {
namespace {

/// Water on the lattice (i + 1/2) dp filling [0, 0.2] x [0, 0.1] (a floor at y = 0 and a wall at
/// x = 0 bound it), with the pressure of a still pool plus a horizontal gradient.
struct Pool {
  static constexpr double dp = 0.01;
  std::vector<Vec<2>> x, v;
  std::vector<double> m, p;
  static double field(const Vec<2>& at) { return 1000.0 + 9810.0 * (0.1 - at[1]) + 500.0 * at[0]; }
  explicit Pool(int rows = 10) {
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < rows; ++j) {
        x.emplace_back((i + 0.5) * dp, (j + 0.5) * dp);
        p.push_back(field(x.back()));
      }
    v.assign(x.size(), Vec<2>::Zero());
    m.assign(x.size(), 0.1);
  }
  ParticleView<2> view() const {
    ParticleView<2> view;
    view.position = x.data();
    view.velocity = v.data();
    view.mass = m.data();
    view.pressure = p.data();
    view.count = x.size();
    return view;
  }
  /// The Shepard average of the same stencil, written out.
  double shepard(const Vec<2>& at, const CubicSpline<2>& kernel) const {
    double sum_pw = 0.0, sum_w = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double w = kernel.w((x[i] - at).norm());
      sum_pw += p[i] * w;
      sum_w += w;
    }
    return sum_pw / sum_w;
  }
};

TEST(PressureProbe, ReproducesALinearFieldBesideWallsAndInCorners) {
  const Pool pool;
  const CubicSpline<2> kernel(1.2 * Pool::dp);
  for (const Vec<2>& at : {Vec<2>(0.1, 0.05), Vec<2>(0.1, 0.002), Vec<2>(0.003, 0.003),
                           Vec<2>(0.1, 0.098), Vec<2>(0.1, 0.0)}) {
    const double exact = Pool::field(at);
    EXPECT_NEAR(pressure_at(pool.view(), at, kernel), exact, 1e-9 * exact) << at.transpose();
  }
  // The Shepard value beside the floor is the pressure at the stencil's centroid, ~1 cm higher:
  // ~60 Pa low at (0.1, 0.002), against 2.3 kPa of pressure there.
  const Vec<2> floor(0.1, 0.002);
  EXPECT_LT(pool.shepard(floor, kernel), Pool::field(floor) - 30.0);
}

TEST(PressureProbe, FallsBackToShepardWhereNoSlopeCanBeFitted) {
  const Pool row(1);  // a single row: no vertical slope can be fitted
  const CubicSpline<2> kernel(1.2 * Pool::dp);
  const Vec<2> above(0.1, 0.012);
  EXPECT_NEAR(pressure_at(row.view(), above, kernel), row.shepard(above, kernel), 1e-9);
  EXPECT_TRUE(std::isnan(pressure_at(row.view(), Vec<2>(1.0, 1.0), kernel)));
}

}  // namespace
}  // namespace porosph::sph
