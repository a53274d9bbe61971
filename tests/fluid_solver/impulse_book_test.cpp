// The water solver's external-impulse book (fluid_solver/water_impulse_book.h): in a walled tank
// with an inflow zone, an outflow zone and two reservoirs (one refilling, one removing), over
// Euler and Verlet steps, a slowly varying dt and jumps of it, the momentum the solver reports
// changes in every step by exactly the sum of the books (no interaction here) - every source of
// the water at work but the damping stage's (covered by the coupled cases).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fluid_solver/water_solver.h"
#include "water_fixtures.h"

namespace porosph::water {
namespace {

using testing::box;

scene::ReservoirZone reservoir(std::vector<double> lo, std::vector<double> hi, double level) {
  scene::ReservoirZone z;
  z.min = std::move(lo);
  z.max = std::move(hi);
  z.level = level;
  return z;
}

double norm(const double* v) { return std::hypot(v[0], v[1]); }

TEST(WaterImpulseBook, MomentumChangesByTheBookedImpulsesEveryStep) {
  scene::Scene s = testing::water_scene(0.01, {-0.05, -0.05}, {0.35, 0.35});
  s.run.dt0 = 1e-4;
  s.water->sound_speed = 25.0;
  s.water->blocks = {box({0, 0}, {0.3, 0.1})};
  s.water->inflows = {testing::inflow({0.1, 0.0}, {0.14, 0.04}, {1.0, 0.0}, 0.5)};
  s.water->outflows = {testing::outflow({0.26, 0}, {0.3, 0.03})};
  s.water->reservoirs = {reservoir({0, 0}, {0.08, 0.3}, 0.14),      // refills every column
                         reservoir({0.18, 0}, {0.24, 0.3}, 0.07)};  // removes the top
  s.walls = {testing::container({0, 0}, {0.3, 0.3}, 3)};
  WaterSolver<2> f(s);
  coupling::StepState state;
  const std::vector<double> none;
  const std::vector<std::string> sources = f.impulse_sources();
  ASSERT_EQ(sources.size(), static_cast<std::size_t>(kWaterImpulseCount));
  f.compute_rates();
  f.fill_state(state, none, none);
  ASSERT_EQ(state.diagnostics.external_impulse, std::vector<double>(2 * sources.size(), 0.0));
  std::vector<double> before = state.diagnostics.momentum, first = before;
  std::vector<double> total(2 * sources.size(), 0.0);  // summed over the steps
  double worst = 0.0;
  for (int n = 0; n < 300; ++n) {
    // A slowly varying dt (Verlet steps over the span dt_previous + dt), and every 50th step a
    // jump (an Euler step; the step after it one too).
    double dt = std::min(s.run.dt0, f.dt_limits().min()) * (0.9 + 0.005 * std::sin(0.1 * n));
    if (n % 50 == 49) dt *= 0.5;
    f.advance(dt);
    f.fill_state(state, none, none);
    const std::vector<double>& J = state.diagnostics.external_impulse;
    ASSERT_EQ(J.size(), 2 * sources.size());
    double scale = 0.0, residual[2];
    for (int k = 0; k < 2; ++k) residual[k] = state.diagnostics.momentum[k] - before[k];
    for (std::size_t j = 0; j < sources.size(); ++j) {
      scale = std::max(scale, norm(&J[2 * j]));
      for (int k = 0; k < 2; ++k) {
        residual[k] -= J[2 * j + k];
        total[2 * j + k] += J[2 * j + k];
      }
    }
    worst = std::max(worst, norm(residual) / scale);
    before = state.diagnostics.momentum;
    f.compute_rates();
  }
  double scale = 0.0, residual[2];
  for (int k = 0; k < 2; ++k) residual[k] = before[k] - first[k];
  for (std::size_t j = 0; j < sources.size(); ++j) {
    scale = std::max(scale, norm(&total[2 * j]));
    for (int k = 0; k < 2; ++k) residual[k] -= total[2 * j + k];
    std::printf("%-13s %+.6e %+.6e\n", sources[j].c_str(), total[2 * j], total[2 * j + 1]);
  }
  std::printf("worst step residual %.3g, whole run %.3g of the largest term\n", worst,
              norm(residual) / scale);
  // Round-off of the particle sums: the pair forces cancel pair by pair, and the books add what
  // the integrator applied. Measured 1.8e-13 per step (of that step's largest term: the pair
  // forces are ~100x one step's impulse) and 1.3e-16 over the run; a source left out would show
  // at its own size (the smallest here, the reservoir's, is 8e-4 of the largest over the run).
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(norm(residual) / scale, 1e-12);
  for (const WaterImpulse j : {kWaterGravity, kWaterWalls, kWaterInflow, kWaterOutflow,
                               kWaterReservoir, kWaterVerletChain})
    EXPECT_GT(norm(&total[2 * j]), 0.0) << sources[j];
  EXPECT_GT(f.born_count(), 0u);
  EXPECT_GT(f.removed_count(), 0u);
}

}  // namespace
}  // namespace porosph::water
