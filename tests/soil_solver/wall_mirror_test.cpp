// Eq. 5 against a straight wall from mirror images of the soil (soil_solver/wall_mirror.h): the
// images are the wall particles while the soil's lattice is in registry with the wall's, and they
// slide with the soil where the wall particles do not.
#include "soil_solver/wall_mirror.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "soil_solver/soil_particles.h"
#include "soil_solver/stress_divergence.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"

namespace porosph::soil {
namespace {

using Eigen::Matrix3d;
using V2 = sph::Vec<2>;

constexpr double kDp = 0.01, kRho = 1800.0;

/// One particle's neighbour list in the layout the solver reads: free pairs, then fixed ones.
struct OneList {
  std::vector<sph::NeighbourPair<2>> pairs;
  std::size_t n_free_pairs = 0;
  auto begin(std::int64_t) const { return pairs.begin(); }
  auto mid(std::int64_t) const { return pairs.begin() + n_free_pairs; }
  auto end(std::int64_t) const { return pairs.end(); }
};

/// Soil rows y = (k + 1/2) dp (k = 0..5) slid along a floor by o; three wall rows below y = 0 at
/// x = m dp. Particle 0 is the soil particle at (o, dp / 2); stress(y) gives each its stress.
struct Floor {
  sph::CubicSpline<2> kernel{1.2 * kDp};
  SoilParticles<2> P;
  OneList list;
  template <class Stress>
  Floor(double o, Stress stress, bool no_slip = false, V2 soil_velocity = V2::Zero()) {
    std::vector<V2> soil, wall;
    soil.push_back(V2(o, 0.5 * kDp));
    for (int k = 0; k < 6; ++k)
      for (int m = -6; m <= 6; ++m)
        if (k != 0 || m != 0) soil.push_back(V2(o + m * kDp, (k + 0.5) * kDp));
    for (int k = 0; k < 3; ++k)
      for (int m = -8; m <= 8; ++m) wall.push_back(V2(m * kDp, -(k + 0.5) * kDp));
    P.n_free = soil.size();
    for (const auto* set : {&soil, &wall}) {
      for (const V2& x : *set) {
        P.position.push_back(x);
        P.stress.push_back(stress(x.y()));
        P.density.push_back(kRho);
        P.mass.push_back(kRho * kDp * kDp);
        P.weight_ratio.push_back(1.0);
        P.no_slip.push_back(set == &wall && no_slip ? 1 : 0);
        P.velocity.push_back(set == &soil ? soil_velocity : V2::Zero());
      }
    }
    for (int pass = 0; pass < 2; ++pass) {  // free, then fixed
      const std::size_t from = pass == 0 ? 1 : P.n_free, to = pass == 0 ? P.n_free : P.size();
      for (std::size_t b = from; b < to; ++b) {
        const V2 x_ab = P.position[0] - P.position[b];
        const double r = x_ab.norm();
        if (r < kernel.support()) list.pairs.push_back({x_ab, r, static_cast<std::int32_t>(b)});
      }
      if (pass == 0) list.n_free_pairs = list.pairs.size();
    }
  }
  MirrorFace<2> face() const {
    MirrorFace<2> f;
    EXPECT_TRUE(find_mirror_face<2>(list, 0, P, kDp, V2(0.0, 1.0), f));
    return f;
  }
  V2 images(const V2& gravity) const {
    return mirror_stress_divergence_acceleration<2>(list, kernel, 0, P, kRho, gravity, face());
  }
  /// (velocity gradient, divergence) from the images, and from the wall particles with their own
  /// velocity in the continuity equation and the free-slip mirrored soil velocity in L.
  std::pair<Eigen::Matrix2d, double> image_kinematics() const {
    Eigen::Matrix2d grad_v = Eigen::Matrix2d::Zero();
    double divergence = 0.0;
    add_mirror_kinematics<2>(list, kernel, 0, P, face(), grad_v, divergence);
    return {grad_v, divergence};
  }
  double wall_particle_divergence() const {
    double divergence = 0.0;
    for (auto it = list.mid(0); it != list.end(0); ++it)
      divergence +=
          kDp * kDp *
          (P.velocity[0] - P.velocity[it->b]).dot(V2(kernel.grad_factor(it->r) * it->x_ab));
    return divergence;
  }
  V2 wall_particles() const {  // the symmetric form with the wall particles' own stress
    V2 a = V2::Zero();
    for (auto it = list.mid(0); it != list.end(0); ++it)
      a += stress_divergence_acceleration<2>(P.mass[it->b], P.stress[0], P.stress[it->b], kRho,
                                             kRho, V2(kernel.grad_factor(it->r) * it->x_ab));
    return a;
  }
  V2 soil_pairs() const {
    V2 a = V2::Zero();
    for (auto it = list.begin(0); it != list.mid(0); ++it)
      a += stress_divergence_acceleration<2>(P.mass[it->b], P.stress[0], P.stress[it->b], kRho,
                                             kRho, V2(kernel.grad_factor(it->r) * it->x_ab));
    return a;
  }
};

Matrix3d compression(double sxx, double syy) {
  Matrix3d s = Matrix3d::Zero();
  s(0, 0) = sxx;
  s(1, 1) = syy;
  s(2, 2) = sxx;
  return s;
}

TEST(WallMirror, FaceHalfASpacingBeyondTheNearestLayer) {
  const Floor floor(0.3 * kDp, [](double) { return compression(-4e3, -9e3); });
  const MirrorFace<2> f = floor.face();
  EXPECT_NEAR(f.distance, 0.5 * kDp, 1e-15);
  EXPECT_DOUBLE_EQ(f.normal.y(), 1.0);  // from the wall into the soil
}

TEST(WallMirror, NoFaceWithWallsOnBothSidesOrANoSlipOne) {
  Floor floor(0.0, [](double) { return compression(-4e3, -9e3); });
  MirrorFace<2> f;
  auto both_sides = floor.list;  // a wall particle above i as well (a gap between two walls)
  both_sides.pairs.push_back({V2(0.0, -kDp), kDp, static_cast<std::int32_t>(floor.P.n_free)});
  EXPECT_FALSE(find_mirror_face<2>(both_sides, 0, floor.P, kDp, V2(0.0, 1.0), f));
  floor.P.no_slip[floor.list.pairs.back().b] = 1;  // one no-slip wall particle
  EXPECT_FALSE(find_mirror_face<2>(floor.list, 0, floor.P, kDp, V2(0.0, 1.0), f));
}

TEST(WallMirror, TheImagesAreTheWallParticlesInRegistry) {
  // A uniform state, no gravity: in registry the images sit where the wall particles sit and,
  // mirrored, carry their stress (a shear changes sign on a free-slip face), so the two sums agree.
  Matrix3d sigma = compression(-4e3, -9e3);
  sigma(0, 1) = sigma(1, 0) = 250.0;
  Matrix3d mirrored = sigma;
  mirrored(0, 1) = mirrored(1, 0) = -250.0;
  Floor floor(0.0, [&](double y) { return y > 0 ? sigma : mirrored; });
  const V2 images = floor.images(V2::Zero()), walls = floor.wall_particles();
  EXPECT_LE((images - walls).norm(), 1e-12 * walls.norm());
  EXPECT_GT(walls.y(), 0.0);  // the floor holds the compressed soil up
}

TEST(WallMirror, TheImagesSlideWithTheSoil) {
  // Uniform compression, slid by 0.2 dp along the floor. The wall particles' normal sum changes
  // by the lattice sum's share (0.88 % at o = 0.2 dp, h = 1.2 dp; the soil_column's defect); the
  // images do not change, and with the soil pairs they hold the uniform state in exact balance
  // (the images continue the soil's own lattice), to round-off of the ~1e5 m/s^2 pair terms.
  const auto uniform = [](double) { return compression(-4e3, -9e3); };
  const Floor aligned(0.0, uniform), slid(0.2 * kDp, uniform);
  const double scale = aligned.wall_particles().norm();
  EXPECT_GT(std::abs(slid.wall_particles().y() - aligned.wall_particles().y()), 5e-3 * scale);
  EXPECT_LE((slid.images(V2::Zero()) - aligned.images(V2::Zero())).norm(), 1e-12 * scale);
  EXPECT_LE((slid.images(V2::Zero()) + slid.soil_pairs()).norm(), 1e-12 * scale);
}

TEST(WallMirror, TheFloorCarriesTheWeightWhateverTheRegistry) {
  // A geostatic column, sigma_yy = -rho g (H - y), sigma_xx = K0 sigma_yy, on a floor: the images
  // continue the weight into the floor (sigma_j' - sigma_j = -rho g . (x_j' - x_j)), so the first
  // row's eq. 5 leaves the same residual as a particle inside the soil (the lattice's first-moment
  // error, -0.9 % of g here), in registry and slid by 0.37 dp. The wall particles, given the same
  // linear stress, agree in registry and are off by 2.3 g once slid.
  const V2 gravity(0.0, -9.81);
  const double H = 1.0, k0 = 0.5;
  const auto geostatic = [&](double y) {
    const double syy = -kRho * 9.81 * (H - y);
    return compression(k0 * syy, syy);
  };
  const sph::CubicSpline<2> kernel(1.2 * kDp);
  V2 interior = gravity;  // a particle at y0 with the full lattice around it
  const double y0 = 0.5;
  for (int k = -3; k <= 3; ++k) {
    for (int m = -3; m <= 3; ++m) {
      const V2 x_ij(-m * kDp, -k * kDp);
      const double r = x_ij.norm();
      if (r == 0.0 || r >= kernel.support()) continue;
      interior += stress_divergence_acceleration<2>(kRho * kDp * kDp, geostatic(y0),
                                                    geostatic(y0 + k * kDp), kRho, kRho,
                                                    V2(kernel.grad_factor(r) * x_ij));
    }
  }
  EXPECT_GT(std::abs(interior.y()), 1e-3 * 9.81);  // the residual compared against is not zero
  for (double o : {0.0, 0.37 * kDp}) {
    const Floor floor(o, geostatic);
    const V2 images = floor.soil_pairs() + floor.images(gravity) + gravity;
    EXPECT_LE((images - interior).norm(), 1e-9 * 9.81) << "o = " << o;
    const V2 walls = floor.soil_pairs() + floor.wall_particles() + gravity;
    if (o == 0.0) EXPECT_LE((walls - interior).norm(), 1e-9 * 9.81);
    if (o > 0.0) EXPECT_GT((walls - interior).norm(), 9.81);
  }
}

TEST(WallMirror, SlidingAlongAFreeSlipWallNeitherCompressesNorShears) {
  // The soil slides along a free-slip floor at 1 mm/s, slid by 0.2 dp: its images slide with it,
  // so the velocity gradient and the divergence from them are zero (to round-off of the ~0.1 1/s
  // single-pair terms). The wall particles at rest give the continuity equation v . sum_w V grad W,
  // the lattice ripple that made the soil_column's wall columns denser as they settled.
  const auto uniform = [](double) { return compression(-4e3, -9e3); };
  const Floor slid(0.2 * kDp, uniform, false, V2(1e-3, 0.0));
  const auto [grad_v, divergence] = slid.image_kinematics();
  EXPECT_LE(grad_v.norm(), 1e-15);
  EXPECT_LE(std::abs(divergence), 1e-15);
  EXPECT_GT(std::abs(slid.wall_particle_divergence()), 1e-5);
}

TEST(WallMirror, ApproachingTheWallCompresses) {
  // Moving towards a free-slip floor at 1 mm/s: the images approach (v_y falls from +1 mm/s below
  // the face to -1 mm/s above it), so dv_y/dy < 0 and the density rate is positive: the stress
  // update compresses and the images keep the soil out of the wall. (`divergence` is
  // sum_j V_j (v_i - v_j) . grad_i W_ij = -div v, drho/dt = rho times it.)
  const Floor approaching(
      0.0, [](double) { return compression(-4e3, -9e3); }, false, V2(0.0, -1e-3));
  const auto [grad_v, density_rate] = approaching.image_kinematics();
  EXPECT_GT(density_rate, 0.0);
  EXPECT_LT(grad_v(1, 1), 0.0);
  EXPECT_NEAR(density_rate, -grad_v.trace(), 1e-12);
}

TEST(WallMirror, NoImagesOnANoSlipWall) {
  // No-slip walls keep the wall particles (wall_mirror.h: the images went unstable in the granular
  // collapse on its rough base).
  const Floor rough(
      0.0, [](double) { return compression(-4e3, -9e3); }, true);
  MirrorFace<2> f;
  EXPECT_FALSE(find_mirror_face<2>(rough.list, 0, rough.P, kDp, V2(0.0, 1.0), f));
}

TEST(WallMirror, NothingFromTheOtherSideOfTheFace) {
  // A free neighbour below the face (the other side of a thin wall, were it in the list) has no
  // image on i's side.
  Floor floor(0.0, [](double) { return compression(-4e3, -9e3); });
  const V2 before = floor.images(V2::Zero());
  floor.P.position.push_back(V2(0.0, -0.5 * kDp));
  floor.P.stress.push_back(compression(-1e6, -1e6));
  floor.P.density.push_back(kRho);
  floor.P.mass.push_back(kRho * kDp * kDp);
  floor.P.weight_ratio.push_back(1.0);
  floor.P.no_slip.push_back(0);
  floor.list.pairs.insert(floor.list.pairs.begin(),
                          {V2(0.0, kDp), kDp, static_cast<std::int32_t>(floor.P.size() - 1)});
  ++floor.list.n_free_pairs;
  EXPECT_EQ(floor.images(V2::Zero()), before);
}

}  // namespace
}  // namespace porosph::soil
