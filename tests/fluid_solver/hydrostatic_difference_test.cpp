// The pressure gradient inside soil in the hydrostatic difference form
// (fluid_solver/hydrostatic_difference.h, water.pressure_gradient_in_soil): exact for still water
// on a disordered lattice where the symmetric form is not, left to the symmetric form at an
// incomplete support, its departure from antisymmetric pairs booked, and the scene key.
#include "fluid_solver/hydrostatic_difference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

#include "fluid_solver/water_rates.h"
#include "fluid_solver/water_solver.h"
#include "sph/kernels.h"
#include "sph/lattice_gradient.h"
#include "sph/neighbour_list.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using Vec2 = sph::Vec<2>;
constexpr double kDp = 0.01, kRho0 = 1000.0, kG = 9.81, kDepth = 0.3;

/// Still water on a 30 x 30 lattice jittered by up to 0.03 dp (a lattice that a flow has
/// strained; tr(L) / D stays above 0.97, a full support), p = rho0 g (depth - y) exactly, rho =
/// rho0, every particle under the same drag (drag rate 200 1/s, drag weight 1).
struct StillWaterInSoil {
  WaterParticles<2> P;
  WaterParams<2> params;
  sph::NeighbourList<2> list;
  StillWaterInSoil() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.03 * kDp, 0.03 * kDp);
    std::vector<Vec2> x;
    for (int i = 0; i < 30; ++i)
      for (int j = 0; j < 30; ++j)
        x.emplace_back((i + 0.5) * kDp + jitter(rng), (j + 0.5) * kDp + jitter(rng));
    P = testing::make_particles<2>(x, x.size(), kRho0, kRho0 * kDp * kDp);
    for (std::size_t i = 0; i < x.size(); ++i) P.pressure[i] = kRho0 * kG * (kDepth - x[i].y());
    std::fill(P.viscosity_cut.begin(), P.viscosity_cut.end(), 1.0);
    std::fill(P.drag_rate.begin(), P.drag_rate.end(), 200.0);
    params.dp = kDp;
    params.h = 1.2 * kDp;
    params.eta2 = 0.01 * params.h * params.h;
    params.eos = TaitEos(kRho0, 20.0, 7.0);
    params.artificial = ArtificialViscosity{0.0, 0.0, params.h, 0.0};
    params.gravity = Vec2(0.0, -kG);
    list.build(P.position.data(), x.size(), x.size(), 2.0 * params.h, sph::DomainBox<2>{});
  }
  void rates(bool hydrostatic_difference) {
    params.hydrostatic_difference_in_soil = hydrostatic_difference;
    // The solver's kernel: the gradient normalised on the square lattice (sph/lattice_gradient.h).
    const sph::CubicSpline<2> plain(params.h);
    compute_water_rates(list,
                        sph::CubicSpline<2>(params.h, 1.0 / sph::lattice_gradient_sum(plain, kDp)),
                        params, P);
  }
  /// Whether particle i's kernel support (2h) lies inside the block.
  bool interior(std::size_t i) const {
    const Vec2& x = P.position[i];
    const double margin = 2.0 * params.h + 0.2 * kDp;
    return x.minCoeff() > margin && x.maxCoeff() < 0.3 - margin;
  }
};

TEST(HydrostaticDifference, StillWaterStaysStillOnADisorderedLatticeWhereTheSymmetricFormDoesNot) {
  StillWaterInSoil w;
  w.rates(false);
  const std::vector<Vec2> symmetric = w.P.acceleration;
  w.rates(true);
  double worst_symmetric = 0.0, worst = 0.0;
  std::size_t interior = 0;
  for (std::size_t i = 0; i < w.P.n_free; ++i) {
    if (!w.interior(i)) continue;
    ++interior;
    worst_symmetric = std::max(worst_symmetric, symmetric[i].norm());
    worst = std::max(worst, w.P.acceleration[i].norm());
  }
  ASSERT_GT(interior, 300u);
  // The symmetric form pushes each particle by 2 p_a grad C_a / rho_a: with a 15 % jitter that is
  // a sizeable part of g (measured 2-3 g at the bottom of the block).
  EXPECT_GT(worst_symmetric, 0.1 * kG);
  // The hydrostatic difference form: p_b - p_a = rho0 g . x_ba exactly, rho = rho0, so only
  // round-off remains of -grad p / rho + g (1e-9 g leaves ~6 orders of margin).
  EXPECT_LT(worst, 1e-9 * kG);
}

TEST(HydrostaticDifference, AnIncompleteSupportKeepsTheSymmetricForm) {
  // The block's corners and edges (a free surface, a seepage face) have tr(L) / D well below
  // 0.90: completeness 0, so their accelerations are exactly the symmetric form's.
  StillWaterInSoil w;
  w.rates(false);
  const std::vector<Vec2> symmetric = w.P.acceleration;
  w.rates(true);
  std::size_t corners = 0;
  for (std::size_t i = 0; i < w.P.n_free; ++i) {
    const Vec2& x = w.P.position[i];
    const bool corner = (x.x() < kDp || x.x() > 0.29) && (x.y() < kDp || x.y() > 0.29);
    if (!corner) continue;
    ++corners;
    EXPECT_EQ(w.P.acceleration[i], symmetric[i]) << i;
    EXPECT_EQ(w.P.pressure_form_acceleration[i], Vec2::Zero()) << i;
  }
  EXPECT_EQ(corners, 4u);
  EXPECT_EQ(SoilPressureSums<2>::completeness(0.90), 0.0);
  EXPECT_NEAR(SoilPressureSums<2>::completeness(0.935), 0.5, 1e-12);
  EXPECT_EQ(SoilPressureSums<2>::completeness(1.0), 1.0);
  EXPECT_EQ(SoilPressureSums<2>::completeness(1.2), 0.0);  // a clump
}

TEST(HydrostaticDifference, TheDepartureFromAntisymmetricPairsIsWhatIsBooked) {
  // Disturb the pressures so that the form's residual is not zero: the water's total internal
  // force sum m (a - g) then equals the booked sum m a_form to round-off, as the external-impulse
  // ledger needs (water_impulse_book.h, "pressure_form"), with the full weight everywhere and
  // with drag rates that vary from particle to particle (weights between 0.2 and 1).
  StillWaterInSoil w;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-50.0, 50.0);
  for (double& p : w.P.pressure) p += noise(rng);
  std::uniform_real_distribution<double> rate(20.0, 200.0);
  for (int pass : {0, 1}) {
    if (pass == 1) {
      for (double& lambda : w.P.drag_rate) lambda = rate(rng);
    }
    w.rates(true);
    Vec2 internal = Vec2::Zero(), booked = Vec2::Zero();
    double scale = 0.0;
    for (std::size_t i = 0; i < w.P.n_free; ++i) {
      const double m = w.P.mass[i];
      internal += m * (w.P.acceleration[i] - w.params.gravity);
      booked += m * w.P.pressure_form_acceleration[i];
      scale += m * (w.P.acceleration[i] - w.params.gravity).norm();
    }
    EXPECT_GT(booked.norm(), 1e-6 * scale) << pass;  // not trivially zero
    EXPECT_LT((internal - booked).norm(), 1e-12 * scale) << pass;
  }
}

TEST(HydrostaticDifference, TheDragWeightRampsOverTheSoilsSurfaceLayerOnly) {
  using S = SoilPressureSums<2>;
  EXPECT_EQ(S::drag_weight(0.0, 100.0), 0.0);  // no drag: the symmetric form
  EXPECT_EQ(S::drag_weight(100.0, 100.0), 1.0);
  EXPECT_EQ(S::drag_weight(50.0, 100.0), 1.0);  // from half the neighbours' largest drag
  EXPECT_NEAR(S::drag_weight(10.0, 100.0), 0.2, 1e-15);
  // Only the ratio counts: the same soil surface at another conductivity gets the same weights.
  EXPECT_EQ(S::drag_weight(1e-3, 1e-2), S::drag_weight(1e4, 1e5));
}

TEST(HydrostaticDifference, TheWeightInsideSoilDoesNotFallWithTheSmoothingLength) {
  // Until 2026-12-06 the weight was the artificial viscosity's drag share min(1, lambda / r_av),
  // r_av ~ alpha c0 / h: at a drag rate below r_av (the seepage weir at dp 2.5 mm) the symmetric
  // form came back inside the soil. Now a uniform drag gives the full form whatever r_av: on the
  // jittered still-water block the interior keeps only round-off, as at drag share 1.
  StillWaterInSoil w;
  w.params.artificial = ArtificialViscosity{0.05, 0.0, w.params.h, 0.0};
  w.params.drag_share_rate = 1e6;  // r_av far above the drag rate of 200 1/s
  std::fill(w.P.viscosity_cut.begin(), w.P.viscosity_cut.end(), 200.0 / 1e6);
  w.P.velocity.assign(w.P.size(), Vec2::Zero());
  w.rates(true);
  double worst = 0.0;
  for (std::size_t i = 0; i < w.P.n_free; ++i)
    if (w.interior(i)) worst = std::max(worst, w.P.acceleration[i].norm());
  EXPECT_LT(worst, 1e-9 * kG);
}

TEST(HydrostaticDifference, SceneKeyAndDragShare) {
  scene::Scene s = testing::water_scene(0.01, {-1, -1}, {1, 1});
  s.water->blocks.push_back(testing::box({0.0, 0.0}, {0.01, 0.01}));
  EXPECT_FALSE(WaterSolver<2>(s).params().hydrostatic_difference_in_soil);  // default symmetric
  s.water->pressure_gradient_in_soil = "hydrostatic_difference";
  const WaterSolver<2> f(s);
  EXPECT_TRUE(f.params().hydrostatic_difference_in_soil);
  const double r_av = f.params().drag_share_rate;
  EXPECT_GT(r_av, 0.0);
  EXPECT_NEAR(f.params().drag_share(0.5 * r_av), 0.5, 1e-15);
  EXPECT_EQ(f.params().drag_share(3.0 * r_av), 1.0);
  EXPECT_EQ(f.params().drag_share(0.0), 0.0);
  const auto terms = f.active_terms();
  EXPECT_NE(
      std::find(terms.begin(), terms.end(), "pressure_gradient_hydrostatic_difference_in_soil"),
      terms.end());
  s.water->alpha = 0.0;  // no artificial viscosity: the share is 1 wherever there is drag
  EXPECT_EQ(WaterSolver<2>(s).params().drag_share(1e-3), 1.0);
  s.water->pressure_gradient_in_soil = "sometimes";
  EXPECT_THROW(WaterSolver<2>{s}, std::invalid_argument);
}

}  // namespace
}  // namespace porosph::water
