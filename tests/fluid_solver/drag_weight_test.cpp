// The drag weight s_a = min(1, lambda_a / (0.5 lambda_max,a)) (fluid_solver/drag_weight.h): 1
// inside soil at every resolution, a ramp over the soil's surface layer, 0 in free water; and the
// artificial viscosity that the drag replaces (water.artificial_viscosity_in_soil =
// "drag_replaced") taking it in the rates and in the solver.
#include "fluid_solver/drag_weight.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "fluid_solver/artificial_viscosity.h"
#include "fluid_solver/water_rates.h"
#include "fluid_solver/water_solver.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;

/// A column of 6 x 20 particles at spacing dp: drag rate 196 1/s (the seepage weir's sand, g / K)
/// in the bottom 10 rows, 20 1/s in row 10 (the soil's thinning kernel sum at its surface), 0
/// above.
struct SoilSurfaceColumn {
  std::vector<Vec2> x;
  std::vector<double> drag_rate;
  sph::NeighbourList<2> list;
  explicit SoilSurfaceColumn(double dp) {
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 20; ++j) {
        x.emplace_back((i + 0.5) * dp, (j + 0.5) * dp);
        drag_rate.push_back(j < 10 ? 196.0 : j == 10 ? 20.0 : 0.0);
      }
    list.build(x.data(), x.size(), x.size(), 2.4 * dp, sph::DomainBox<2>{});
  }
  int row(std::size_t a) const { return static_cast<int>(a % 20); }
};

TEST(DragWeight, OneInsideSoilAtEveryResolutionARampAtItsSurfaceZeroAbove) {
  for (double dp : {0.01, 0.005, 0.0025}) {
    SoilSurfaceColumn c(dp);
    std::vector<double> w(c.x.size(), -1.0);
    DragWeight::compute(c.list, c.x.size(), c.drag_rate, w);
    for (std::size_t a = 0; a < c.x.size(); ++a) {
      const int j = c.row(a);
      // Row 10's neighbours reach 196 1/s: 20 / (0.5 196) = 0.204 by hand.
      const double expected = j < 10 ? 1.0 : j == 10 ? 20.0 / 98.0 : 0.0;
      EXPECT_NEAR(w[a], expected, 1e-15) << "dp " << dp << " row " << j;
    }
    // The drag-limited share of the same sand falls with h (alpha 0.05, c0 20 m/s, h = 1.2 dp):
    // at dp 2.5 mm it removes only 0.48 of the artificial viscosity where the weight removes all.
    const double r_av = ArtificialViscosity::kernel_damping_rate(0.05, 20.0, 1.2 * dp, 2);
    const double share = ArtificialViscosity::drag_share(196.0, r_av);
    if (dp < 0.003) EXPECT_NEAR(share, 0.48, 0.01);
  }
  EXPECT_EQ(DragWeight::of(0.0, 100.0), 0.0);
  EXPECT_EQ(DragWeight::of(-1.0, 100.0), 0.0);
  EXPECT_EQ(DragWeight::of(50.0, 100.0), 1.0);
  EXPECT_NEAR(DragWeight::of(10.0, 100.0), 0.2, 1e-15);
}

/// 300 water particles at random places with random velocities (pressure and gravity zero, so the
/// accelerations are the artificial viscosity alone) under a uniform drag.
WaterParticles<2> random_cloud(sph::NeighbourList<2>& list, double h) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(300);
  for (auto& p : x) p = Vec2(0.1 * u(rng), 0.1 * u(rng));
  WaterParticles<2> P = testing::make_particles<2>(x, x.size(), 1000.0, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    P.mass[i] = 0.02 + 0.01 * u(rng);
    P.sound_speed[i] = 20.0;
    P.velocity[i] = Vec2(u(rng) - 0.5, u(rng) - 0.5);
  }
  list.build(P.position.data(), x.size(), x.size(), 2.0 * h, sph::DomainBox<2>{});
  return P;
}

TEST(DragWeight, ReplacedArtificialViscosityIsOffUnderUniformDragAndWholeWithout) {
  const double h = 0.006;
  sph::NeighbourList<2> list;
  WaterParticles<2> P = random_cloud(list, h);
  WaterParams<2> params;
  params.h = h;
  params.eta2 = 0.01 * h * h;
  params.artificial = ArtificialViscosity{0.1, 0.0, h, 0.0};
  params.artificial_replaced_by_drag = true;
  compute_water_rates(list, sph::CubicSpline<2>(h), params, P);  // no drag: the whole term
  const std::vector<Vec2> full = P.acceleration;
  double largest = 0.0;
  for (const Vec2& a : full) largest = std::max(largest, a.norm());
  ASSERT_GT(largest, 1.0);  // the term is there
  params.artificial_replaced_by_drag = false;
  compute_water_rates(list, sph::CubicSpline<2>(h), params, P);
  for (std::size_t i = 0; i < full.size(); ++i) EXPECT_EQ(P.acceleration[i], full[i]) << i;
  // A uniform drag, of any rate (here far below r_av = 1028 1/s): the weight is 1, the term off.
  params.artificial_replaced_by_drag = true;
  std::fill(P.drag_rate.begin(), P.drag_rate.end(), 5.0);
  compute_water_rates(list, sph::CubicSpline<2>(h), params, P);
  for (std::size_t i = 0; i < full.size(); ++i) {
    EXPECT_EQ(P.viscosity_cut[i], 1.0) << i;
    EXPECT_EQ(P.acceleration[i].norm(), 0.0) << i;
  }
}

TEST(DragWeight, SolverRecomputesTheWeightFromTheCouplersDragRates) {
  // Two isolated particles, one inside the overlap box: "drag_replaced" turns the term off at
  // the one under drag however weak its rate; an empty rate list (no drag) gives it back.
  scene::Scene s = testing::water_scene(0.01, {-1, -1}, {1, 1});
  s.water->artificial_viscosity_in_soil = "drag_replaced";
  s.water->blocks.push_back(testing::box({0.0, 0.0}, {0.01, 0.01}));
  s.water->blocks.push_back(testing::box({0.5, 0.0}, {0.51, 0.01}));
  WaterSolver<2> f(s);
  EXPECT_TRUE(f.params().artificial_replaced_by_drag);
  EXPECT_EQ(f.params().artificial.damping_rate, 0.0);  // not drag-limited
  coupling::StepState state;
  f.compute_rates();
  f.fill_state(state, {0.4, -0.1}, {0.6, 0.1});
  ASSERT_EQ(state.overlap_id.size(), 1u);
  f.set_drag_rate({0.5});
  f.compute_rates();
  const auto& P = f.particles();
  for (std::size_t i = 0; i < 2; ++i) {
    const bool in_overlap = P.id[i] == state.overlap_id[0];
    EXPECT_EQ(P.viscosity_cut[i], in_overlap ? 1.0 : 0.0) << i;
  }
  f.set_drag_rate({});
  f.compute_rates();
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(P.viscosity_cut[i], 0.0);
}

}  // namespace
}  // namespace porosph::water
