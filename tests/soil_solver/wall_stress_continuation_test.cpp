// The soil's stress continued into its wall particles (soil_solver/wall_stress_continuation.h,
// soil_walls.h): the linear continuation reproduces a geostatic state, K0 included, in a corner's
// and a floor's wall particles; the weight continuation compresses them sideways by
// (1 - K0) rho g dy too much.
#include "soil_solver/wall_stress_continuation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "soil_solver/soil_walls.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using V2 = sph::Vec<2>;

constexpr double kDp = 0.01, kRho = 2000.0, kG = 9.81, kHeight = 0.2, kK0 = 0.45;

/// Geostatic stress of a column of height kHeight, tension positive: sigma_yy = -rho g (H - y),
/// sigma_xx = sigma_zz = K0 sigma_yy (a linear field).
Matrix3d geostatic(const V2& x) {
  const double v = -kRho * kG * (kHeight - x.y());
  Matrix3d s = Matrix3d::Zero();
  s(0, 0) = s(2, 2) = kK0 * v;
  s(1, 1) = v;
  return s;
}

/// Soil filling 0 < x, y < 0.1 m at spacing dp, a floor and a left wall three layers thick
/// (the corner block included), all no-slip, each particle carrying the geostatic stress.
struct Corner {
  sph::CubicSpline<2> kernel{1.2 * kDp};
  SoilParticles<2> P;
  sph::NeighbourList<2> list;
  SoilParams<2> params;

  explicit Corner(bool linear) {
    std::vector<V2> soil, wall;
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j) soil.emplace_back((i + 0.5) * kDp, (j + 0.5) * kDp);
    for (int i = -3; i < 12; ++i)
      for (int j = -3; j < 12; ++j)
        if (i < 0 || j < 0) wall.emplace_back((i + 0.5) * kDp, (j + 0.5) * kDp);
    P.n_free = soil.size();
    for (const auto* set : {&soil, &wall})
      for (const V2& x : *set) {
        P.position.push_back(x);
        P.velocity.push_back(V2::Zero());
        P.wall_velocity.push_back(V2::Zero());
        P.wall_normal.push_back(V2::Zero());
        P.stress.push_back(set == &soil ? geostatic(x) : Matrix3d::Zero());
        P.density.push_back(kRho);
        P.reference_density.push_back(kRho);
        P.mass.push_back(kRho * kDp * kDp);
        P.no_slip.push_back(1);
      }
    list.build(P.position.data(), P.size(), P.n_free, 2.4 * kDp, sph::DomainBox<2>{});
    params.gravity = V2(0.0, -kG);
    params.volume = kDp * kDp;
    params.linear_wall_stress = linear;
    std::vector<StressGradient<2>> scratch;
    update_soil_wall_state<2>(list, kernel, params, P, scratch);
  }

  /// Largest |sigma_w - geostatic(x_w)| component over the wall particles with soil neighbours,
  /// in units of rho g dp; `component` (r, c) or the whole tensor when r < 0.
  double worst_error(int r = -1, int c = -1) const {
    double worst = 0.0;
    for (std::size_t w = P.n_free; w < P.size(); ++w) {
      if (list.begin(w) == list.mid(w)) continue;  // no soil within reach: keeps zero stress
      const Matrix3d e = P.stress[w] - geostatic(P.position[w]);
      worst = std::max(worst, r < 0 ? e.cwiseAbs().maxCoeff() : std::abs(e(r, c)));
    }
    return worst / (kRho * kG * kDp);
  }
};

TEST(WallStressContinuation, TheGradientOfALinearFieldIsExactNextToAWall) {
  const Corner c(true);
  // The soil particle in the corner (its neighbours on a quarter of the support) and one on the
  // floor: the corrected gradient is exact for a linear field (round-off only).
  for (const std::int64_t f : {0, 5 * 10}) {
    const StressGradient<2> g = corrected_stress_gradient<2>(c.list, c.kernel, c.P, f);
    ASSERT_TRUE(g.trusted) << "particle " << f;
    EXPECT_NEAR(g.d[0].cwiseAbs().maxCoeff(), 0.0, 1e-9 * kRho * kG);
    EXPECT_NEAR(g.d[1](1, 1), kRho * kG, 1e-9 * kRho * kG);
    EXPECT_NEAR(g.d[1](0, 0), kK0 * kRho * kG, 1e-9 * kRho * kG);
  }
}

TEST(WallStressContinuation, LinearContinuationReproducesTheGeostaticStateInACorner) {
  // Exact to round-off in every wall particle, the corner's included (relative to rho g dp).
  EXPECT_LT(Corner(true).worst_error(), 1e-9);
}

TEST(WallStressContinuation, WeightContinuationOverCompressesTheWallsSideways) {
  const Corner c(false);
  // The vertical stress is continued exactly by the weight (the Shepard mean of a linear field
  // in y and its exact weight term), while sigma_xx of a wall particle below the soil grows with
  // rho g instead of K0 rho g: (1 - K0) rho g dy too compressed, up to ~2.4 dp below the soil.
  EXPECT_LT(c.worst_error(1, 1), 1e-9);
  EXPECT_GT(c.worst_error(0, 0), 0.5 * (1.0 - kK0));
}

TEST(WallStressContinuation, TheLimiterKeepsTheSmallerChangeOfTheWeightsSign) {
  const Matrix3d linear = Eigen::Vector3d(0.5, 2.0, -1.0).asDiagonal();
  const Matrix3d limited = limited_change(linear, 1.0);
  EXPECT_EQ(limited(0, 0), 0.5);  // same sign, smaller: the linear change (a K0 < 1)
  EXPECT_EQ(limited(1, 1), 1.0);  // larger: the weight's (never further than the weight)
  EXPECT_EQ(limited(2, 2), 1.0);  // opposite sign: the weight's
  // Off the diagonal the weight form has no change, and neither has the limited one.
  Matrix3d shear = Matrix3d::Zero();
  shear(0, 1) = shear(1, 0) = 3.0;
  EXPECT_EQ(limited_change(shear, 1.0), Matrix3d::Identity());
  // Where the weight does not change the stress (a side wall, g . x_wf = 0) nothing does: an
  // oscillating soil stress is averaged, never extrapolated into the wall.
  EXPECT_EQ(limited_change(linear, 0.0), Matrix3d::Zero());
}

}  // namespace
}  // namespace porosph::soil
