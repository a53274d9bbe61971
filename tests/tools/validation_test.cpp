// The validation tool on hand-made run directories with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/kernels.h"
#include "tests/support/process_support.h"
#include "tools/validation/dam_break_check.h"
#include "tools/validation/dam_case_checks.h"
#include "tools/validation/lattice_registry.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/soil_checks.h"

namespace porosph::testing {
namespace {

TEST(Validation, InterpolatesLinearlyAndRefusesToExtrapolate) {
  const std::vector<double> x = {0.0, 1.0, 3.0}, y = {0.0, 2.0, 6.0};
  EXPECT_DOUBLE_EQ(validation::interpolate(x, y, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(validation::interpolate(x, y, 2.0), 4.0);
  EXPECT_TRUE(std::isnan(validation::interpolate(x, y, 3.5)));
}

// A synthetic dam-break run whose front follows Z = 1 + 0.5 T exactly, against a two-point table:
// the errors are known in closed form.
// time_mean integrates the piecewise-linear series exactly: y = 2 t on uneven rows has the mean
// (from + to) over [from, to], ends inside rows included; a step series gives the trapezoid's
// share. standard_error_of_mean: samples 1, 2, 3 have spread 1, so 1 / sqrt(3).
TEST(Validation, TimeMeanAndStandardErrorOfTheMean) {
  const std::vector<double> t{0.0, 0.3, 1.0, 1.1, 2.0}, y{0.0, 0.6, 2.0, 2.2, 4.0};
  EXPECT_NEAR(validation::time_mean(t, y, 0.0, 2.0), 2.0, 1e-14);
  EXPECT_NEAR(validation::time_mean(t, y, 0.2, 1.05), 1.25, 1e-14);
  const std::vector<double> step{0.0, 0.0, 1.0, 1.0, 1.0};  // 0 until 0.3, ramps to 1 at 1.0
  EXPECT_NEAR(validation::time_mean(t, step, 0.0, 2.0), (0.5 * 0.7 + 1.0) / 2.0, 1e-14);
  EXPECT_NEAR(validation::standard_error_of_mean(6.0, 14.0, 3), 1.0 / std::sqrt(3.0), 1e-14);
  EXPECT_EQ(validation::standard_error_of_mean(2.0, 4.0, 1), 0.0);
}

TEST(Validation, DamBreakErrorOfAKnownFront) {
  const std::string dir = fresh_dir("validation-dam");
  const double a = 0.05715, dp = 0.001, g = 9.81;
  write_text(dir + "/run.json", R"({"parameters": {"run": {"dp": 0.001, "gravity": [0, -9.81]},
      "water": {"blocks": [{"min": [0, 0], "max": [0.05715, 0.1143]}]}}})");
  const double scale = std::sqrt(2 * g / a);
  std::string csv = "t,front\n";
  for (int i = 0; i <= 40; ++i) {
    const double t = 0.005 * i, T = t * scale;
    // front stored as the leading particle centre: Z a - dp/2
    csv += std::to_string(t) + "," + std::to_string((1 + 0.5 * T) * a - 0.5 * dp) + "\n";
  }
  write_text(dir + "/timeseries.csv", csv);
  const std::string reference = write_text(dir + "/reference.csv", "T,Z\n1.0,1.6\n2.0,1.8\n");
  const auto c =
      validation::compare_dam_break(dir, reference, validation::DamBreakFront::farthest_particle);
  ASSERT_EQ(c.T.size(), 2u);
  // Z_sim(1) = 1.5 -> |dZ| = 0.1; Z_sim(2) = 2.0 -> |dZ| = 0.2 (to the csv's 6 printed digits).
  EXPECT_NEAR(c.Z_simulated[0], 1.5, 1e-4);
  EXPECT_NEAR(c.mean_abs_error, 0.15, 1e-4);
  EXPECT_NEAR(c.max_abs_error, 0.2, 1e-4);
}

// The bulk front skips a film thinner than the capillary length: dp = 1 mm, a column 3 particles
// deep over x = 0 .. 5 mm, a one-particle film to 8 mm, then three particles stacked in the column
// 9 .. 10 mm (deep enough again) and a fixed (wall) particle column far out that must not count.
TEST(Validation, DamBreakBulkFrontIsTheFarthestColumnAsDeepAsTheCapillaryLength) {
  const double dp = 0.001;
  std::vector<double> position;
  std::vector<std::uint8_t> fixed;
  auto add = [&](double x, double y, bool wall) {
    position.insert(position.end(), {x, y});
    fixed.push_back(wall);
  };
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) add((i + 0.5) * dp, (j + 0.5) * dp, false);
  for (int i = 5; i < 8; ++i) add((i + 0.5) * dp, 0.5 * dp, false);
  std::vector<double> depth;
  const double lc = validation::kCapillaryLengthOfWater;
  EXPECT_DOUBLE_EQ(validation::bulk_front(position, fixed, 0.0, dp, lc, depth), 5 * dp);
  for (int j = 0; j < 4; ++j) add(20.5 * dp, (j + 0.5) * dp, true);
  EXPECT_DOUBLE_EQ(validation::bulk_front(position, fixed, 0.0, dp, lc, depth), 5 * dp);
  for (int j = 0; j < 3; ++j) add(9.5 * dp, (j + 0.5) * dp, false);
  EXPECT_DOUBLE_EQ(validation::bulk_front(position, fixed, 0.0, dp, lc, depth), 10 * dp);
  // Measured from the back wall: the same water shifted by x_wall gives the same front.
  for (std::size_t i = 0; i < fixed.size(); ++i) position[2 * i] += 0.25;
  EXPECT_DOUBLE_EQ(validation::bulk_front(position, fixed, 0.25, dp, lc, depth), 10 * dp);
  // One particle deep is enough where dp itself reaches the capillary length.
  EXPECT_DOUBLE_EQ(validation::bulk_front(position, fixed, 0.25, dp, dp, depth), 10 * dp);
}

// B of the rockfill shell: toe at x = 1.7, crest end at 0.2. Particles: one that moved 30 mm from
// x0 = 1.3 (counts at the 26 mm threshold, not at 52 mm), one that moved 60 mm from x0 = 1.5,
// one under the crest (x0 = 0.1) that moved 100 mm (not part of the slope), one fixed that
// "moved" 1 m, one at rest at x0 = 0.5.
TEST(Validation, RockfillBIsMeasuredFromTheToeToTheMostUpstreamMovedSlopeParticle) {
  validation::SoilParticles2D s;
  auto add = [&](double x0, double y0, double ux, double uy, bool fixed) {
    s.position.insert(s.position.end(), {x0 + ux, y0 + uy});
    s.displacement.insert(s.displacement.end(), {ux, uy});
    s.fixed.push_back(fixed);
    s.material.push_back(0);
  };
  add(1.3, 0.2, 0.018, -0.024, false);  // |u| = 0.030
  add(1.5, 0.1, 0.06, 0.0, false);
  add(0.1, 0.8, 0.0, -0.1, false);
  add(0.9, 0.3, 1.0, 0.0, true);
  add(0.5, 0.5, 0.0, 0.0, false);
  EXPECT_NEAR(validation::rockfill_b(s, 1.7, 0.2, 0.026), 0.4, 1e-12);
  EXPECT_NEAR(validation::rockfill_b(s, 1.7, 0.2, 0.052), 0.2, 1e-12);
  EXPECT_EQ(validation::rockfill_b(s, 1.7, 0.2, 0.2), 0.0);
  // Wet particles only: the one from x0 = 1.3 is dry (saturation 0.05 < 0.1), so B comes from
  // x0 = 1.5; without the saturation field the wet variant is an error, not a silent 0.
  EXPECT_THROW(validation::rockfill_b(s, 1.7, 0.2, 0.026, 0.1), std::runtime_error);
  s.saturation = {0.05, 0.9, 0.9, 0.9, 0.9};
  EXPECT_NEAR(validation::rockfill_b(s, 1.7, 0.2, 0.026, 0.1), 0.2, 1e-12);
  // Lowest free particle of material 0 with 0.4 <= x <= 1.4: the one now at (1.318, 0.176).
  EXPECT_NEAR(validation::lowest_in_band(s, 0, 0.4, 1.4), 0.176, 1e-12);
  EXPECT_TRUE(std::isnan(validation::lowest_in_band(s, 1, 0.0, 3.0)));
}

// The heave's bulk measures on five particles (dp 0.01 m): sand (material 0) left of the pile's
// pit face x = -0.005 counts dp^2 each, free only (the fixed one does not); the gravel
// (material 1) settlement averages -u_y over the free particles that STARTED in the band
// [0.005, 0.025], wherever they are now (the one that moved out of the band at x = 0.04 counts,
// the one that moved into it from x0 = 0.05 does not).
TEST(Validation, HeaveBulkMeasuresCountTheSandInThePitAndTheGravelThatStartedBesideThePile) {
  validation::SoilParticles2D s;
  auto add = [&](double x0, double y0, double ux, double uy, bool fixed, std::int64_t material) {
    s.position.insert(s.position.end(), {x0 + ux, y0 + uy});
    s.displacement.insert(s.displacement.end(), {ux, uy});
    s.fixed.push_back(fixed);
    s.material.push_back(material);
  };
  add(0.00, 0.02, -0.02, 0.01, false, 0);   // sand now at x = -0.02: in the pit
  add(-0.10, 0.05, 0.0, 0.0, true, 0);      // fixed: never counted
  add(-0.20, 0.05, 0.0, 0.0, false, 0);     // sand in the pit from the start
  add(0.01, 0.10, 0.03, -0.004, false, 1);  // started in the band, now at x = 0.04
  add(0.05, 0.10, -0.03, -0.1, false, 1);   // moved into the band: not counted
  add(0.02, 0.12, 0.0, -0.002, false, 1);   // in the band
  EXPECT_NEAR(validation::free_area_left_of(s, 0, -0.005, 0.01), 2e-4, 1e-15);
  EXPECT_NEAR(validation::mean_settlement(s, 1, 0.005, 0.025), 0.003, 1e-12);
  EXPECT_TRUE(std::isnan(validation::mean_settlement(s, 0, 0.3, 0.4)));
}

// The bulk front of a collapsed deposit: three rows (15 mm) up to x = 0.1 m, then single particles
// on the floor out to 0.2 m, and a fixed particle far out. With dp 5 mm and a minimum thickness of
// 10 mm the front is the far edge of the last thick column, 0.1 m; the single particles (5 mm
// thick) count only when 5 mm is enough; the fixed one never.
TEST(Validation, BulkFrontIgnoresSingleParticlesOnTheFloor) {
  const double dp = 0.005;
  std::vector<double> position;
  std::vector<std::uint8_t> fixed;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 3; ++j) {
      position.insert(position.end(), {(i + 0.5) * dp, (j + 0.5) * dp});
      fixed.push_back(0);
    }
  for (double x : {0.12, 0.15, 0.1975}) {
    position.insert(position.end(), {x, 0.5 * dp});
    fixed.push_back(0);
  }
  position.insert(position.end(), {0.5, 0.5});
  fixed.push_back(1);
  EXPECT_NEAR(validation::bulk_front(position, fixed, 0.0, 0.0, dp, 0.01), 0.1, 1e-12);
  EXPECT_NEAR(validation::bulk_front(position, fixed, 0.0, 0.0, dp, 0.005), 0.2, 1e-12);
  EXPECT_EQ(validation::bulk_front(position, fixed, 0.0, 0.0, dp, 0.05), 0.0);
}

// The Dupuit-Forchheimer water table against the Darcy closed form (b = 0: H = sqrt(2 a q L)) and
// against an independent integration of its ODE -dH/dx = a q / H + b q^2 / H^2 (RK4 upstream from
// a small exit height, whose own contribution is below 1e-6 m): the bisection's 1e-12 relative
// tolerance and the 1e-5 m step leave errors far below 1e-6 m, so 1e-5 m catches any wrong term
// (dropping b or a changes H at 1.6 m by centimetres for the rockfill gravel).
TEST(Validation, DupuitForchheimerWaterTable) {
  EXPECT_NEAR(validation::dupuit_forchheimer_height(1.5, 0.01, 0.2, 0.0),
              std::sqrt(2 * 0.2 * 0.01 * 1.5), 1e-12);
  EXPECT_EQ(validation::dupuit_forchheimer_height(0.0, 0.01, 0.2, 5.0), 0.0);
  const double a = 0.1142, b = 9.33, q = 7.74e-3;  // rockfill gravel (Den Adel), Q 19.36 l/s
  const auto slope = [&](double h) { return a * q / h + b * q * q / (h * h); };
  double h = 1e-3, distance = h * h * h / (3 * b * q * q);  // exact near the exit: b dominates
  const double dx = 1e-5;
  for (double target : {0.2, 0.7, 1.6}) {
    while (distance < target - 0.5 * dx) {
      const double k1 = slope(h), k2 = slope(h + 0.5 * dx * k1), k3 = slope(h + 0.5 * dx * k2),
                   k4 = slope(h + dx * k3);
      h += dx * (k1 + 2 * k2 + 2 * k3 + k4) / 6;
      distance += dx;
    }
    EXPECT_NEAR(validation::dupuit_forchheimer_height(target, q, a, b), h, 1e-5) << target;
  }
  // Both terms matter here: Darcy alone or the quadratic term alone give other tables.
  const double h16 = validation::dupuit_forchheimer_height(1.6, q, a, b);
  EXPECT_GT(h16 - validation::dupuit_forchheimer_height(1.6, q, a, 0.0), 0.05);
  EXPECT_GT(h16 - validation::dupuit_forchheimer_height(1.6, q, 0.0, b), 0.005);
  // Pure Forchheimer (a = 0): H = (3 b q^2 L)^(1/3).
  EXPECT_NEAR(validation::dupuit_forchheimer_height(1.6, q, 0.0, b), std::cbrt(3 * b * q * q * 1.6),
              1e-9);
}

TEST(Validation, MissingRunDirectoryIsAClearError) {
  try {
    validation::read_run_json("/nonexistent/run");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/run/run.json"), std::string::npos);
  }
}

// The cubic spline's lattice sum S(o) on a square lattice at h = 1.2 dp, along one axis: the
// values computed independently (numpy, the kernel written out) are 0.999757 at o = 0, 0.998595
// at o = dp/2 and 0.998493 at o = 0.325 dp (the smallest), and the mean of 1 / S over a
// spacing 1.0011229 (64 midpoints): what the darcy column's period mean is measured against
// (docs/accuracy.md). Bounds 1e-6: a wrong volume, h or reach changes them by 1e-4 or more.
TEST(LatticeRegistry, CubicSplineSumsAtTheScenesRatio) {
  const double dp = 0.0025;
  const sph::CubicSpline<2> kernel(1.2 * dp);
  EXPECT_NEAR(validation::lattice_kernel_sum(kernel, dp, 1, 0.0), 0.999757, 1e-6);
  EXPECT_NEAR(validation::lattice_kernel_sum(kernel, dp, 1, 0.5 * dp), 0.998595, 1e-6);
  EXPECT_NEAR(validation::lattice_kernel_sum(kernel, dp, 1, 0.325 * dp), 0.998493, 1e-6);
  EXPECT_NEAR(validation::lattice_kernel_sum(kernel, dp, 0, 0.5 * dp),
              validation::lattice_kernel_sum(kernel, dp, 1, 0.5 * dp), 1e-12);  // square lattice
  const double factor =
      validation::registry_mean_velocity(kernel, dp, 1, [](double s) { return 1.0 / s; });
  EXPECT_NEAR(factor, 1.0011229, 1e-6);
}

}  // namespace
}  // namespace porosph::testing
