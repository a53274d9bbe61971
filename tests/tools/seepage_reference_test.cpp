// The 2D seepage references (tools/validation/laplace_fv.h, sheet_pile.h, rectangular_dam.h,
// grid_series.h) against exact answers, Harr's closed forms and Dupuit-Charnyi, on CI-size grids.
#include <gtest/gtest.h>

#include <cmath>

#include "tools/validation/grid_series.h"
#include "tools/validation/laplace_fv.h"
#include "tools/validation/rectangular_dam.h"
#include "tools/validation/rectangular_dam_exact.h"
#include "tools/validation/sheet_pile.h"

namespace porosph::testing {
namespace {

namespace v = validation;
constexpr double kPi = 3.14159265358979323846;

TEST(GridSeries, RichardsonRecoversTheOrderAndTheLimitOfAKnownSeries) {
  // f(h) = 1 + 0.3 h^2 on h = 1, 1/2, 1/4, 1/8.
  const auto e = v::richardson({1.3, 1.075, 1.01875, 1.0046875});
  EXPECT_NEAR(e.order, 2.0, 1e-12);
  EXPECT_NEAR(e.extrapolated, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(v::richardson({1.0, 2.0, 1.5}).order));  // not monotone
}

TEST(LaplaceFv, UniformFlowBetweenTwoFixedHeadsIsExact) {
  v::LaplaceProblem p;
  p.x1 = 2.0, p.y1 = 0.5, p.cells_x = 8, p.cells_y = 3, p.conductivity = 3.0;
  p.fixed_heads = {{v::Side::kLeft, 0.0, 0.5, 1.0}, {v::Side::kRight, 0.0, 0.5, 0.2}};
  const auto s = v::solve_laplace(p);
  const double q = 3.0 * 0.8 / 2.0 * 0.5;  // K dh / L times the height
  EXPECT_NEAR(s.discharge_across_vertical(1.0, 0.0, 0.5), q, 1e-12);
  EXPECT_NEAR(s.discharge_across_vertical(0.3, 0.0, 0.5), q, 1e-12);  // between grid lines
  EXPECT_NEAR(s.head(0.7, 0.41), 1.0 - 0.8 * 0.7 / 2.0, 1e-12);
  EXPECT_NEAR(s.head(0.0, 0.2), 1.0, 1e-12);
  EXPECT_NEAR(s.mean_outward_gradient(v::Side::kRight, 0.0, 0.5), 0.4, 1e-12);
  EXPECT_NEAR(s.discharge_across_horizontal(0.25, 0.0, 2.0), 0.0, 1e-12);
}

TEST(LaplaceFv, AFullHeightBarrierStopsTheFlowAndSplitsTheHead) {
  v::LaplaceProblem p;
  p.cells_x = 10, p.cells_y = 4;
  p.fixed_heads = {{v::Side::kLeft, 0.0, 1.0, 1.0}, {v::Side::kRight, 0.0, 1.0, 0.0}};
  p.barriers = {{true, 0.5, 0.0, 1.0}};
  const auto s = v::solve_laplace(p);
  EXPECT_NEAR(s.discharge_across_vertical(0.5, 0.0, 1.0), 0.0, 1e-12);
  EXPECT_NEAR(s.head(0.5 - 1e-9, 0.3), 1.0, 1e-12);
  EXPECT_NEAR(s.head(0.5 + 1e-9, 0.3), 0.0, 1e-12);
  p.barriers = {{true, 0.55, 0.0, 1.0}};
  EXPECT_THROW(v::solve_laplace(p), std::invalid_argument);  // off the grid lines
}

TEST(LaplaceFv, ASolidBlockNarrowsTheSectionAndCarriesNoHead) {
  // A solid over the whole length of the upper half: uniform flow through the lower half only.
  v::LaplaceProblem p;
  p.x1 = 2.0, p.cells_x = 8, p.cells_y = 4;
  p.fixed_heads = {{v::Side::kLeft, 0.0, 1.0, 1.0}, {v::Side::kRight, 0.0, 1.0, 0.0}};
  p.solids = {{0.0, 2.0, 0.5, 1.0}};
  const auto s = v::solve_laplace(p);
  EXPECT_NEAR(s.discharge_across_vertical(1.0, 0.0, 1.0), 0.5 * 1.0 / 2.0, 1e-12);
  EXPECT_NEAR(s.head(0.5, 0.2), 0.75, 1e-12);
  EXPECT_TRUE(std::isnan(s.cell_head(3, 3)));
  EXPECT_NEAR(s.discharge_across_horizontal(0.5, 0.0, 2.0), 0.0, 1e-12);  // its faces: no flow
  // A block in the middle makes the flow go round it: less discharge than without it.
  p.solids = {{0.75, 1.25, 0.25, 1.0}};
  const double around = v::solve_laplace(p).discharge_across_vertical(0.5, 0.0, 1.0);
  EXPECT_GT(around, 0.0);
  EXPECT_LT(around, 0.5);
  p.solids = {{0.8, 1.25, 0.25, 1.0}};
  EXPECT_THROW(v::solve_laplace(p), std::invalid_argument);  // off the grid lines
}

TEST(SheetPile, HarrsDischargeHasItsLimitsAndSymmetry) {
  EXPECT_NEAR(v::harr_discharge_factor(0.2, 0.1), 0.5, 1e-12);  // m = m' at s = T / 2
  EXPECT_TRUE(std::isinf(v::harr_discharge_factor(0.2, 0.0)));
  EXPECT_EQ(v::harr_discharge_factor(0.2, 0.2), 0.0);
  EXPECT_GT(v::harr_discharge_factor(0.2, 1e-4), 2.0);  // ~ ln(8 T / (pi s)) / pi: grows as s -> 0
  // m(T - s) = m'(s): q(s) q(T - s) = 1/4.
  for (double s : {0.02, 0.07, 0.13})
    EXPECT_NEAR(v::harr_discharge_factor(0.2, s) * v::harr_discharge_factor(0.2, 0.2 - s), 0.25,
                1e-12);
}

TEST(SheetPile, TheExitGradientTendsToTheInfinitelyDeepLayerAndThePileFaceHeadEndsRight) {
  const double s = 0.1, dh = 0.05;
  EXPECT_NEAR(
      v::harr_exit_gradient(1000 * s, s, dh, 0.0) / v::harr_infinite_depth_exit_gradient(s, dh),
      1.0, 1e-4);
  // The infinitely deep layer: i(x) = dh / (pi sqrt(x^2 + s^2)).
  EXPECT_NEAR(v::harr_exit_gradient(1000 * s, s, dh, 0.05), dh / (kPi * std::hypot(0.05, s)), 1e-6);
  const v::SheetPile pile;  // T 0.2, s 0.1, h1 0.05, h2 0
  EXPECT_NEAR(v::harr_pile_face_head(pile, 0.2, true), 0.0, 1e-12);
  EXPECT_NEAR(v::harr_pile_face_head(pile, 0.1, true), 0.025, 1e-9);
  EXPECT_NEAR(v::harr_pile_face_head(pile, 0.15, false) + v::harr_pile_face_head(pile, 0.15, true),
              0.05, 1e-12);
  EXPECT_NEAR(v::harr_mean_exit_gradient(0.2, s, dh, 1e-6), v::harr_exit_gradient(0.2, s, dh, 0),
              1e-9);
}

// L = 6 T: the FV discharge, exit gradient and pile-face head on 120 x 20 and 240 x 40 cells,
// extrapolated with the observed order 1 (the pile tip's singularity), against Harr.
TEST(SheetPile, FiniteVolumesConvergeToHarrForAWideLayer) {
  const v::SheetPile pile;
  const std::vector<std::array<double, 2>> probes = {{0.6 + 1e-9, 0.15}, {0.5, 0.05}, {0.7, 0.05}};
  const auto coarse = v::measure_sheet_pile(pile, 120, 20, probes, 0.005);
  const auto fine = v::measure_sheet_pile(pile, 240, 40, probes, 0.005);
  auto limit = [](double c, double f) { return 2 * f - c; };
  EXPECT_NEAR(limit(coarse.discharge_factor, fine.discharge_factor), 0.5, 0.5 * 2e-3);
  EXPECT_LT(fine.discharge_factor, 0.5);  // converges from below
  EXPECT_NEAR(limit(coarse.exit_gradient_cell, fine.exit_gradient_cell),
              v::harr_exit_gradient(0.2, 0.1, 0.05, 0.0), 0.15 * 3e-3);
  EXPECT_NEAR(limit(coarse.heads[0], fine.heads[0]), v::harr_pile_face_head(pile, 0.15, true),
              2e-4);
  // Antisymmetry about the pile: h(L/2 - a) + h(L/2 + a) = h1 + h2.
  EXPECT_NEAR(fine.heads[1] + fine.heads[2], 0.05, 1e-12);
  EXPECT_THROW(v::measure_sheet_pile(pile, 120, 15, probes, 0.005), std::invalid_argument);
}

TEST(RectangularDam, BaiocchisSolutionCarriesCharnyisDischargeAboveDupuitsParabola) {
  const v::RectangularDam dam;  // L 0.4, h1 0.3, h2 0.05
  EXPECT_NEAR(dam.charnyi_discharge(), (0.09 - 0.0025) / 0.8, 1e-15);
  const auto s = v::solve_rectangular_dam(dam, 32, 24);
  EXPECT_NEAR(s.discharge(0.2) / dam.charnyi_discharge(), 1.0, 1e-3);
  EXPECT_NEAR(s.discharge(0.1) / dam.charnyi_discharge(), 1.0, 1e-3);
  double previous = dam.head_upstream;
  for (double f : {0.25, 0.5, 0.75, 0.9}) {
    const double phi = s.free_surface(f * dam.length);
    EXPECT_GT(phi, dam.dupuit_height(f * dam.length)) << f;
    EXPECT_LT(phi, previous) << f;
    previous = phi;
  }
  // Grid-converged values (docs/verification.md) within the coarse grid's error.
  EXPECT_NEAR(s.free_surface(0.1), 0.2713, 1e-3);
  EXPECT_NEAR(s.free_surface(0.2), 0.2313, 1e-3);
  EXPECT_GT(s.exit_height(), dam.head_downstream);
  EXPECT_LT(s.exit_height(), s.free_surface(0.9 * dam.length));
  for (int j = 0; j <= 24; ++j)
    for (int i = 0; i <= 32; ++i) EXPECT_GE(s.w(i, j), 0.0);
}

// Polubarinova-Kochina's exact dam: its own boundary data, then Baiocchi's solution against it.
TEST(RectangularDam, TheExactSolutionMeetsItsDataAndBaiocchisFreeSurface) {
  const v::RectangularDam dam;
  const v::RectangularDamExact exact(dam);
  EXPECT_NEAR(exact.free_surface(0.0), 0.3, 1e-12);
  EXPECT_NEAR(exact.free_surface(1e-9), 0.3, 1e-6);  // x(psi) reaches 0 at psi = pi/2: h1
  EXPECT_GT(exact.exit_height(), dam.head_downstream);
  EXPECT_NEAR(exact.exit_height(), 0.0921, 1e-4);  // docs/verification.md
  const auto s = v::solve_rectangular_dam(dam, 64, 48);
  for (double f : {0.25, 0.5, 0.75, 0.9})
    EXPECT_NEAR(s.free_surface(f * dam.length), exact.free_surface(f * dam.length), 6e-4) << f;
}

}  // namespace
}  // namespace porosph::testing
