// Many particles: momentum balance of the interaction (the conservation the issue asks for),
// agreement of the cell-list sums with a brute-force O(N M) evaluation, the saturation inside and
// far from water, the overlap zones and the ledger.
#include <gtest/gtest.h>

#include <random>

#include "coupler/interaction/overlap_region.h"
#include "coupler/interaction/soil_water_interaction.h"
#include "coupler/run_record.h"
#include "porous/seepage_law.h"
#include "porous/submerged_density.h"
#include "tests/coupler/interaction_fixtures.h"

namespace porosph::testing {
namespace {

using coupler::SoilWaterInteraction;
using coupling::StepState;

/// 3D Wendland C2 with support 2h (Dehnen & Aly 2012), written out.
double wendland_3d(double r, double h) {
  const double q = r / h;
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return 21.0 / (16.0 * kPi * h * h * h) * t * t * t * t * (2.0 * q + 1.0);
}

/// Five materials: Kozeny-Carman (variable), conductivity, Den Adel (variable), none, and a fixed
/// Kozeny-Carman bed with a given saturated density.
scene::Scene cloud_scene(int dimension) {
  scene::SoilMaterial kc = kozeny_carman_material();
  kc.variable_permeability = true;
  scene::Scene s = two_phase_scene(kc, dimension);
  s.soil->materials.push_back(conductivity_material(5e-3));
  scene::SoilMaterial da = den_adel_material();
  da.variable_permeability = true;
  da.density = 1900.0;
  s.soil->materials.push_back(da);
  scene::SoilMaterial none = kozeny_carman_material();
  none.seepage = "none";
  s.soil->materials.push_back(none);
  scene::SoilMaterial bed = kozeny_carman_material(0.35, 2e-3);
  bed.fixed = true;
  bed.saturated_density = 2050.0;
  s.soil->materials.push_back(bed);
  s.domain.max.assign(dimension, 0.2);
  s.run.periodic.assign(dimension, true);
  s.run.periodic[dimension - 1] = false;  // periodic along every axis but the vertical one
  if (dimension == 3) s.run.kernel = "wendland_c2";
  return s;
}

/// Random soil and water clouds overlapping in the middle of the box (soil velocity 0 for the
/// fixed bed, as the soil solver sends it).
void random_clouds(int d, std::size_t n_soil, std::size_t n_water, StepState& soil,
                   StepState& water) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Particle volumes that fill each cloud's box once: the saturation is ~1 inside the water and
  // its random fluctuations put soil particles on both sides of the submerged threshold.
  const double base = std::pow(0.2, d - 1);
  const double soil_volume = base * 0.09 / n_soil, water_volume = base * 0.13 / n_water;
  auto point = [&](double lo, double hi) {
    std::vector<double> x(d);
    for (int k = 0; k < d; ++k) x[k] = 0.2 * unit(rng);
    x[d - 1] = lo + (hi - lo) * unit(rng);
    return x;
  };
  auto velocity = [&] {
    std::vector<double> v(d);
    for (double& c : v) c = 0.1 * (unit(rng) - 0.5);
    return v;
  };
  for (std::size_t i = 0; i < n_soil; ++i) {
    const int material = static_cast<int>(i % 5);
    const double rho = 1500.0 + 500.0 * unit(rng);
    auto v = velocity();
    if (material == 4) std::fill(v.begin(), v.end(), 0.0);
    add_particle(soil, point(0.03, 0.12), v, rho, rho * soil_volume * (0.9 + 0.2 * unit(rng)),
                 0.3 + 0.2 * unit(rng), material);
  }
  for (std::size_t a = 0; a < n_water; ++a) {
    const double rho = 990.0 + 20.0 * unit(rng);
    add_particle(water, point(0.07, 0.2), velocity(), rho,
                 rho * water_volume * (0.9 + 0.2 * unit(rng)));
  }
}

/// The cloud test in D dimensions: balance, brute-force agreement, ledger.
void check_cloud(int d, std::size_t n_soil, std::size_t n_water) {
  const scene::Scene scene = cloud_scene(d);
  StepState soil, water;
  random_clouds(d, n_soil, n_water, soil, water);
  SoilWaterInteraction interaction(scene);
  const auto summary = interaction.compute(water, soil, 1.0);
  const auto& sat = interaction.saturation();
  const auto& a_soil = interaction.soil_acceleration();
  const auto& a_water = interaction.water_acceleration();
  ASSERT_EQ(a_soil.size(), n_soil * d);
  ASSERT_EQ(a_water.size(), n_water * d);

  // Brute force over all pairs (minimum image on the periodic axes).
  const double h = scene.h(), L = 0.2, thr = scene.coupling.submerged_saturation;
  const double gamma_w = 1000.0 * 9.81;
  std::vector<double> ref_soil(n_soil * d, 0.0), ref_water(n_water * d, 0.0), ref_sat(n_soil, 0.0);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n_soil; ++i) {
    const auto& m = scene.soil->materials[soil.overlap_material[i]];
    const auto law = porous::SeepageLaw::from_material(m, 9.81, 1e-6);
    const auto c = law.coefficients(soil.overlap_porosity[i]);
    for (std::size_t a = 0; a < n_water; ++a) {
      std::vector<double> dx(d), vr(d);
      double r2 = 0.0, speed2 = 0.0;
      for (int k = 0; k < d; ++k) {
        dx[k] = water.overlap_position[a * d + k] - soil.overlap_position[i * d + k];
        if (scene.run.periodic[k]) dx[k] -= L * std::round(dx[k] / L);
        r2 += dx[k] * dx[k];
        vr[k] = water.overlap_velocity[a * d + k] - soil.overlap_velocity[i * d + k];
        speed2 += vr[k] * vr[k];
      }
      const double r = std::sqrt(r2);
      if (r >= 2.0 * h) continue;
      ++pairs;
      const double w = d == 2 ? cubic_spline_2d(r, h) : wendland_3d(r, h);
      const double v_a = water.overlap_mass[a] / water.overlap_density[a];
      const double v_i = soil.overlap_mass[i] / soil.overlap_density[i];
      ref_sat[i] += v_a * w;
      for (int k = 0; k < d; ++k) {
        const double f = gamma_w * (c.a + c.b * std::sqrt(speed2)) * vr[k];  // eq. 13
        ref_soil[i * d + k] += v_a * f * w;                                  // / rho^s below
        ref_water[a * d + k] -= v_i * f * w / water.overlap_density[a];
      }
    }
  }
  EXPECT_EQ(summary.pair_count, pairs);
  ASSERT_GT(pairs, 10 * (n_soil + n_water) / 4) << "the clouds must overlap substantially";

  // Balance: sum_i m_i^s a_i + sum_a m_a a_a = 0 relative to the sum of |terms|.
  std::vector<double> total(d, 0.0), on_soil(d, 0.0), on_water(d, 0.0);
  double magnitude = 0.0, soil_scale = 0.0, water_scale = 0.0;
  int submerged = 0;
  for (std::size_t i = 0; i < n_soil; ++i) {
    const auto& m = scene.soil->materials[soil.overlap_material[i]];
    const double rho = soil.overlap_density[i];
    const double rho_s =
        porous::submerged_density(rho, sat[i], thr, porous::submerged_density_ratio(m, 1000.0));
    submerged += rho_s != rho;
    EXPECT_NEAR(sat[i], ref_sat[i], 1e-12 * std::max(1.0, ref_sat[i]));
    const double mass_s = soil.overlap_mass[i] * rho_s / rho;  // m_i^s
    double term2 = 0.0;
    for (int k = 0; k < d; ++k) {
      const double term = mass_s * a_soil[i * d + k];
      term2 += term * term;
      on_soil[k] += term;
      ref_soil[i * d + k] /= rho_s;
      soil_scale = std::max(soil_scale, std::abs(ref_soil[i * d + k]));
    }
    magnitude += std::sqrt(term2);
  }
  for (std::size_t a = 0; a < n_water; ++a) {
    double term2 = 0.0;
    for (int k = 0; k < d; ++k) {
      const double term = water.overlap_mass[a] * a_water[a * d + k];
      term2 += term * term;
      on_water[k] += term;
      water_scale = std::max(water_scale, std::abs(ref_water[a * d + k]));
    }
    magnitude += std::sqrt(term2);
  }
  EXPECT_GT(submerged, 0) << "some soil particles must be submerged";
  EXPECT_LT(submerged, static_cast<int>(n_soil)) << "and some not";
  const auto& out = interaction.outputs();
  for (int k = 0; k < d; ++k) {
    // Round-off only: each pair term cancels its partner exactly up to a few ulps, and the sums
    // of ~1e3 terms add ~1e-16 x sqrt(1e3) relative to the magnitude sum; 1e-12 is the bar.
    EXPECT_LT(std::abs(on_soil[k] + on_water[k]), 1e-12 * magnitude) << "axis " << k;
    EXPECT_NEAR(out.force_on_soil[k], on_soil[k], 1e-12 * magnitude);
    EXPECT_NEAR(out.force_on_water[k], on_water[k], 1e-12 * magnitude);
    EXPECT_GT(std::abs(on_soil[k]), 1e-6 * magnitude) << "a net force must exist to balance";
  }
  EXPECT_NEAR(out.force_magnitude_sum, magnitude, 1e-12 * magnitude);
  // Cell-list sums against the brute force (same terms in another order: a few ulps of the
  // largest acceleration of the phase).
  for (std::size_t j = 0; j < a_soil.size(); ++j) {
    EXPECT_NEAR(a_soil[j], ref_soil[j], 1e-12 * soil_scale) << "soil value " << j;
  }
  for (std::size_t j = 0; j < a_water.size(); ++j) {
    EXPECT_NEAR(a_water[j], ref_water[j], 1e-12 * water_scale) << "water value " << j;
  }

  // The ledger books the step; its imbalance is the "below 1e-10 relative".
  coupler::ConservationLedger ledger(d);
  ledger.add_step(1e-4, out.force_on_water, out.force_on_soil, out.force_magnitude_sum);
  ledger.add_step(2e-4, out.force_on_water, out.force_on_soil, out.force_magnitude_sum);
  EXPECT_LT(ledger.relative_imbalance(), 1e-12);
  EXPECT_NEAR(ledger.impulse_to_soil[0], 3e-4 * out.force_on_soil[0], 1e-15 * magnitude);
  EXPECT_NEAR(ledger.impulse_magnitude_sum, 3e-4 * magnitude, 1e-15 * magnitude);
}

// Above SoilWaterSums::kParallelFrom (2048): the threaded path with per-thread soil sums.
TEST(InteractionCloud, MomentumBalancesAndMatchesBruteForce2D) { check_cloud(2, 2500, 3000); }

// Below kParallelFrom: the single-thread path.
TEST(InteractionCloud, MomentumBalancesAndMatchesBruteForce3DWendland) {
  check_cloud(3, 1500, 1500);
}

TEST(InteractionSaturation, IsOneInsideAWaterLatticeAndZeroFarFromIt) {
  // Water on a square lattice of spacing dp = 0.01 filling [0.3, 0.7]^2 (V_a = dp^2); h = 1.2 dp.
  scene::Scene scene = two_phase_scene(kozeny_carman_material());
  StepState water, soil;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      add_particle(water, {0.305 + 0.01 * i, 0.305 + 0.01 * j}, {0.0, 0.0}, 1000.0, 0.1);
    }
  }
  // Soil at lattice points, half-way between and at arbitrary offsets, well inside the water,
  // and one 0.1 m (> 2h) away from the lattice.
  const std::vector<std::vector<double>> inside = {
      {0.505, 0.505}, {0.5, 0.5}, {0.5, 0.505}, {0.4537, 0.5219}, {0.5491, 0.4702}};
  for (const auto& x : inside) add_particle(soil, x, {0.0, 0.0}, 1600.0, 0.16, 0.4, 0);
  add_particle(soil, {0.5, 0.8}, {0.0, 0.0}, 1600.0, 0.16, 0.4, 0);
  SoilWaterInteraction interaction(scene);
  interaction.compute(water, soil, 1.0);
  const auto& s = interaction.saturation();
  ASSERT_EQ(s.size(), inside.size() + 1);
  // The lattice sum dp^2 sum_a W(x - x_a) of the 2D cubic spline with h = 1.2 dp is not exactly
  // 1: by Poisson summation its error is the kernel's Fourier transform at the reciprocal lattice
  // vectors (2 pi / dp), which is 3.7e-3 at worst over all offsets for h / dp = 1.2 (evaluated
  // on an 11 x 11 grid of offsets). 5e-3 admits that; one missing neighbour row would cost > 0.1.
  for (std::size_t i = 0; i < inside.size(); ++i) EXPECT_NEAR(s[i], 1.0, 5e-3) << "particle " << i;
  EXPECT_EQ(s.back(), 0.0);
}

TEST(OverlapRegion, IsTheOtherPhaseBoxInflatedBy2hAndTheDomainOnPeriodicAxes) {
  scene::Scene scene = two_phase_scene(kozeny_carman_material());
  scene.run.periodic = {true, false};
  scene.domain.min = {-0.1, 0.0};
  scene.domain.max = {0.9, 1.0};
  StepState other;
  other.region_min = {0.2, 0.4};
  other.region_max = {0.3, 0.6};
  std::vector<double> lo, hi;
  coupler::overlap_region_for(other, scene, lo, hi);
  const double support = 2.0 * 0.012;
  ASSERT_EQ(lo.size(), 2u);
  ASSERT_EQ(hi.size(), 2u);
  EXPECT_EQ(lo[0], -0.1);  // periodic x: whole domain
  EXPECT_EQ(hi[0], 0.9);
  EXPECT_DOUBLE_EQ(lo[1], 0.4 - support);
  EXPECT_DOUBLE_EQ(hi[1], 0.6 + support);
  scene.run.periodic = {false, false};
  coupler::overlap_region_for(other, scene, lo, hi);
  EXPECT_DOUBLE_EQ(lo[0], 0.2 - support);
  EXPECT_DOUBLE_EQ(hi[0], 0.3 + support);
  // No particle (min > max, as a solver reports an empty phase): nothing to send.
  other.region_min = {INFINITY, INFINITY};
  other.region_max = {-INFINITY, -INFINITY};
  coupler::overlap_region_for(other, scene, lo, hi);
  EXPECT_TRUE(lo.empty());
  EXPECT_TRUE(hi.empty());
}

TEST(InteractionCloud, EmptyOverlapGivesNoOutput) {
  SoilWaterInteraction interaction(two_phase_scene(kozeny_carman_material()));
  StepState water, soil;
  add_particle(soil, {0.5, 0.5}, {0.0, 0.0}, 1600.0, 0.16, 0.4, 0);
  const auto summary = interaction.compute(water, soil, 1.0);
  EXPECT_FALSE(summary.evaluated);
  EXPECT_EQ(summary.pair_count, 0u);
  EXPECT_TRUE(interaction.saturation().empty());
  EXPECT_TRUE(interaction.soil_acceleration().empty());
  EXPECT_EQ(interaction.outputs().force_on_soil, std::vector<double>(2, 0.0));
}

}  // namespace
}  // namespace porosph::testing
