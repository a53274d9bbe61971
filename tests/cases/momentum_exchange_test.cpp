// The soil-water momentum exchange is exact (issue 23, section 3): a closed periodic box of water
// and soil with no external force (no gravity, no walls, no in/outflow) keeps the total momentum
// of both phases, read from the HDF5 snapshots, to 1e-12 of the largest phase momentum over 1,000
// coupled steps - with the paper's explicit drag and with the pairwise implicit drag
// (coupler/interaction/soil_water_interaction.h) - the explicit drag with k = 1e-2 m/s (lambda dt
// ~ 0.1, where it is stable), the implicit one with k = 1e-4 m/s (lambda dt ~ 10). The water starts
// in a Taylor-Green vortex (zero net momentum), the soil at rest in a block that covers a quarter
// wavelength across the flow, so the drag hands the soil a net momentum and the water its
// opposite. Round-off bounds the error: ~1e-16 per step per unit of the exchanged impulse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/snapshot_reader.h"
#include "tests/cases/case_runner.h"
#include "tools/validation/run_directory.h"

namespace porosph::testing {
namespace {

const char* const kBox = R"(
[scene]
name = "momentum_box"
[run]
dimension = 2
end_time = 10.0
max_steps = 1000
output_interval = 5.0e-4
h_factor = 1.2
dt0 = 1.0e-4
dp = 0.005
gravity = [0.0, 0.0]
periodic = [true, true]
[domain]
min = [0.0, 0.0]
max = [0.1, 0.1]
[water]
rho0 = 1000.0
sound_speed = 2.0
viscosity = 1.0e-3
hydrostatic_initial = false
initial_velocity = "taylor_green"
taylor_green_speed = 0.1
taylor_green_wavelength = 0.1
[[water.blocks]]
shape = "box"
min = [0.0, 0.0]
max = [0.1, 0.1]
[soil]
[[soil.materials]]
name = "sand"
density = 1600.0
saturated_density = 2600.0   # rho_sat - rho_w = rho_dry: the submerged ratio is 1, so the soil's
                             # inertia is its mass m = rho dp^2 and the momentum is sum m v
porosity = 0.4
young_modulus = 1.0e5
poisson_ratio = 0.3
friction_angle = 30.0
cohesion = 1.0e4
seepage = "darcy_conductivity"
hydraulic_conductivity = 1.0e-4
variable_permeability = false
[[soil.blocks]]
shape = "box"
min = [0.0, 0.0]
max = [0.05, 0.025]
material = "sand"
)";

/// sum_i m_i v_i of every snapshot of `file` (all particles free: no walls): m_i from the file's
/// "mass" field (water: rho(t = 0) dp^2, which the Taylor-Green pressure makes vary), else `mass`.
std::vector<std::vector<double>> momenta(const std::string& file, double mass) {
  io::SnapshotReader reader(file);
  std::vector<std::vector<double>> out;
  for (const auto& s : reader.snapshots()) {
    const auto v = reader.read_f64(s.index, "velocity");
    const auto fields = reader.fields(s.index);
    std::vector<double> m(v.rows, mass);
    if (std::find(fields.begin(), fields.end(), "mass") != fields.end())
      m = reader.read_f64(s.index, "mass").values;
    std::vector<double> p(v.cols, 0.0);
    for (std::size_t i = 0; i < v.rows; ++i)
      for (std::size_t k = 0; k < v.cols; ++k) p[k] += m[i] * v.values[i * v.cols + k];
    out.push_back(p);
  }
  return out;
}

void expect_momentum_kept(bool implicit_drag, const std::string& drag_step = "backward_euler") {
  const std::string flag = implicit_drag ? "true" : "false";
  const std::string k = implicit_drag ? "1e-4" : "1e-2";
  const auto run =
      run_scene_text("momentum_box_" + flag + "_" + drag_step, kBox,
                     {"coupling.implicit_drag=" + flag, "coupling.drag_step=" + drag_step,
                      "soil.materials.0.hydraulic_conductivity=" + k});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  ASSERT_EQ(run.record.at("steps").get<int>(), 1000);
  const double dp2 = 0.005 * 0.005;
  const auto water = momenta(run.out + "/water.h5", 1000.0 * dp2);
  const auto soil = momenta(run.out + "/soil.h5", 1600.0 * dp2);
  ASSERT_EQ(water.size(), soil.size());
  ASSERT_GT(water.size(), 5u);
  double largest = 0.0, worst = 0.0;
  for (std::size_t s = 0; s < water.size(); ++s) {
    for (int k = 0; k < 2; ++k) {
      largest = std::max({largest, std::abs(water[s][k]), std::abs(soil[s][k])});
      worst = std::max(worst, std::abs(water[s][k] + soil[s][k] - water[0][k] - soil[0][k]));
    }
  }
  // The exchange must be real for the test to mean anything: the soil gained a net momentum.
  EXPECT_GT(largest, 1e-5) << "no momentum exchanged";
  EXPECT_LT(worst, 1e-12 * largest) << "largest phase momentum " << largest;
  // The ledger books what the solvers applied: opposite impulses, and the soil's equals its
  // momentum change (HDF5) to round-off.
  const auto& ledger = run.record.at("ledger");
  EXPECT_LT(ledger.at("relative_imbalance").get<double>(), 1e-12);
  // The external-impulse ledger closes each phase's balance as well (nothing external acts but the
  // Verlet chain switch of the water; docs/coupling.md): measured 1.2e-16 (water), 1.7e-15 (soil).
  for (const char* phase : {"water", "soil"}) {
    const auto& balance = ledger.at("momentum_balance").at(phase);
    EXPECT_LT(balance.at("relative_residual_max_over_outputs").get<double>(), 1e-12) << phase;
  }
  for (int k = 0; k < 2; ++k) {
    const double booked = ledger.at("impulse_to_soil").at(k).get<double>();
    EXPECT_NEAR(booked, soil.back()[k] - soil.front()[k], 1e-12 * largest) << "axis " << k;
  }
  const auto& shares = ledger.at("implicit_share").at("impulse_to_soil");
  const double implicit_share = std::hypot(shares.at(0).get<double>(), shares.at(1).get<double>());
  if (implicit_drag) {
    EXPECT_GT(implicit_share, 1e-3 * largest);  // lambda dt >> 1: far from the explicit drag
  } else {
    EXPECT_EQ(implicit_share, 0.0);
  }
}

// Open to outside forces: the darcy_column water (periodic, no walls) feels gravity and the drag of
// a fixed bed (which absorbs its share: an external body). Its momentum change must equal the
// gravity impulse M g t plus the impulse the ledger booked to it: at the end from run.json (full
// precision) to 1e-10 of the largest term, at every output from timeseries.csv to its 10
// significant digits (1e-8): the interaction's booking is what the water applied, and the Verlet
// span dt_previous + dt makes the gravity impulse exact under a varying dt.
TEST(MomentumExchange, DarcyColumnWaterMomentumIsGravityPlusTheBookedDrag) {
  const auto run = run_case("darcy_column", {"run.end_time=0.02", "run.output_interval=0.002"});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const double g = -9.81;
  const auto& water = run.record.at("phases").at("water");
  const double mass = water.at("mass").at("initial").get<double>();
  const double t_end = run.record.at("simulated_time").get<double>();
  const double booked = run.record.at("ledger").at("impulse_to_water").at(1).get<double>();
  const double change = water.at("final").at("momentum").at(1).get<double>() -
                        water.at("initial").at("momentum").at(1).get<double>();
  const double scale = std::max(std::abs(mass * g * t_end), std::abs(booked));
  EXPECT_NEAR(change, mass * g * t_end + booked, 1e-10 * scale);
  EXPECT_GT(std::abs(booked), 0.5 * std::abs(mass * g * t_end));  // the drag acts
  const auto series = validation::read_timeseries(run.out);
  const auto& t = series.column("t");
  const auto& momentum = series.column("water_momentum_y");
  const auto& impulse = series.column("impulse_to_water_y");
  ASSERT_GT(t.size(), 5u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(momentum[i] - momentum[0], mass * g * t[i] + impulse[i], 1e-8 * scale)
        << "t = " << t[i];
  }
}

TEST(MomentumExchange, ExplicitDragKeepsTheTotalMomentum) { expect_momentum_kept(false); }
TEST(MomentumExchange, ImplicitDragKeepsTheTotalMomentum) { expect_momentum_kept(true); }
// The exponential weights of coupling.drag_step are applied pair by pair like backward Euler's.
TEST(MomentumExchange, ExponentialDragStepKeepsTheTotalMomentum) {
  expect_momentum_kept(true, "exponential");
}

}  // namespace
}  // namespace porosph::testing
