// Observables on hand-made particle sets.
#include "sph/observables.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sph/kernels.h"

namespace porosph::sph {
namespace {

struct ThreeParticles {
  std::vector<Vec<2>> x{Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.5), Vec<2>(0.5, 2.0)};
  std::vector<Vec<2>> v{Vec<2>(1.0, 0.0), Vec<2>(0.0, -2.0), Vec<2>(3.0, 4.0)};
  std::vector<double> m{1.0, 2.0, 0.5};
  std::vector<double> p{100.0, 200.0, 300.0};
  ParticleView<2> view() const { return {x.data(), v.data(), m.data(), p.data(), 3}; }
};

scene::Observable make(std::string kind, std::vector<double> origin = {},
                       std::vector<double> direction = {}, std::vector<double> point = {}) {
  scene::Observable o;
  o.name = kind;
  o.kind = std::move(kind);
  o.origin = std::move(origin);
  o.direction = std::move(direction);
  o.point = std::move(point);
  return o;
}

TEST(SphObservables, HandMadeSet) {
  const ThreeParticles s;
  const CubicSpline<2> kernel(0.1);
  auto eval = [&](const scene::Observable& o) {
    return evaluate_observable(prepare_observable<2>(o), s.view(), kernel);
  };
  // front along +x from x = 0.25: max(-0.25, 0.75, 0.25) = 0.75
  EXPECT_DOUBLE_EQ(eval(make("front_position", {0.25, 0.0}, {1.0, 0.0})), 0.75);
  // height along +y from y = 0: 2.0
  EXPECT_DOUBLE_EQ(eval(make("max_height", {0.0, 0.0}, {0.0, 1.0})), 2.0);
  EXPECT_DOUBLE_EQ(eval(make("max_speed")), 5.0);
  // KE = 0.5 (1*1 + 2*4 + 0.5*25) = 10.75
  EXPECT_DOUBLE_EQ(eval(make("kinetic_energy")), 10.75);
  EXPECT_DOUBLE_EQ(eval(make("particle_count")), 3.0);
}

TEST(SphObservables, PressureAtIsShepardInterpolated) {
  // Probe at (0.5, 0.25) with h = 0.5 (support 1): particles 0 and 1 at r = 0.559, particle 2 at
  // r = 1.75 outside. Equal weights -> p = (100 + 200) / 2.
  const ThreeParticles s;
  const CubicSpline<2> kernel(0.5);
  const auto probe = prepare_observable<2>(make("pressure_at", {}, {}, {0.5, 0.25}));
  EXPECT_NEAR(evaluate_observable(probe, s.view(), kernel), 150.0, 1e-12);
  // Probe closer to particle 1: weights W(r0), W(r1) by hand.
  const Vec<2> point(0.8, 0.4);
  const double w0 = kernel.w(point.norm()), w1 = kernel.w((point - s.x[1]).norm());
  EXPECT_NEAR(pressure_at(s.view(), point, kernel), (100 * w0 + 200 * w1) / (w0 + w1), 1e-9);
  // Nobody within the support: NaN.
  EXPECT_TRUE(std::isnan(pressure_at(s.view(), Vec<2>(10.0, 10.0), kernel)));
}

TEST(SphObservables, EmptySetAndBadInput) {
  const ParticleView<2> empty;
  EXPECT_TRUE(std::isnan(front_position<2>(empty, Vec<2>(0, 0), Vec<2>(1, 0))));
  EXPECT_EQ(max_speed(empty), 0.0);
  EXPECT_EQ(kinetic_energy(empty), 0.0);
  EXPECT_THROW(prepare_observable<2>(make("bogus")), std::invalid_argument);
  EXPECT_THROW(prepare_observable<2>(make("front_position", {0, 0, 0}, {1, 0, 0})),
               std::invalid_argument);
  EXPECT_THROW(prepare_observable<2>(make("pressure_at")), std::invalid_argument);
}

}  // namespace
}  // namespace porosph::sph
