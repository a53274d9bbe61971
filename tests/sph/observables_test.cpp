// Observables on hand-made particle sets: every kind with and without a region against values
// computed by hand, the NaN / 0 rules for empty regions and missing fields, and the errors of
// prepare_observable.
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

scene::Observable with_region(scene::Observable o, std::vector<double> lo, std::vector<double> hi) {
  o.region_min = std::move(lo);
  o.region_max = std::move(hi);
  return o;
}

scene::Observable mean_of(const std::string& field) {
  scene::Observable o = make("mean_field");
  o.field = field;
  return o;
}

// The hand-computed values below are sums of at most four terms, so the reductions must reproduce
// them to rounding: 1e-12 relative (absolute for an expected 0).
void expect_close(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::max(1.0, std::abs(expected))) << what;
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
  // r = 1.75 outside. Equal weights -> p = (100 + 200) / 2. (Two particles cannot fix a 2D slope:
  // pressure_at falls back to Shepard; its linear fit: tests/sph/pressure_probe_test.cpp.)
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

/// Four 2D particles with every field. The region [0.5, 2] x [0, 1] holds particles 1 and 3
/// (particle 3 on its corner: the box is closed); 0 (x < 0.5) and 2 (y > 1) are outside.
struct FourParticles {
  std::vector<Vec<2>> x{Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.5), Vec<2>(0.5, 2.0), Vec<2>(2.0, 1.0)};
  std::vector<Vec<2>> v{Vec<2>(1.0, 0.0), Vec<2>(0.0, -2.0), Vec<2>(3.0, 4.0), Vec<2>(-1.0, 3.0)};
  std::vector<double> m{1.0, 2.0, 0.5, 4.0};
  std::vector<double> p{100.0, 200.0, 300.0, 400.0};
  std::vector<double> rho{1000.0, 1010.0, 990.0, 1020.0};
  std::vector<double> n{0.3, 0.4, 0.5, 0.35};
  std::vector<Eigen::Matrix3d> sigma;  // -100 (i + 1) * A, A = [[1 4 5] [4 2 6] [5 6 3]]
  std::vector<Vec<2>> u{Vec<2>(0.3, 0.4), Vec<2>(0.0, -0.7), Vec<2>(1.2, 0.5), Vec<2>(-0.6, 0.8)};
  FourParticles() {
    Eigen::Matrix3d a;
    a << 1, 4, 5, 4, 2, 6, 5, 6, 3;
    for (int i = 0; i < 4; ++i) sigma.push_back(-100.0 * (i + 1) * a);
  }
  ParticleView<2> view() const {
    ParticleView<2> view{x.data(), v.data(), m.data(), p.data(), 4};
    view.density = rho.data();
    view.porosity = n.data();
    view.stress = sigma.data();
    view.displacement = u.data();
    return view;
  }
};

struct Expected {
  scene::Observable observable;
  double all, in_region;  // over all four particles; over particles 1 and 3
};

TEST(SphObservables, EveryKindWithAndWithoutRegion2D) {
  const FourParticles s;
  const CubicSpline<2> kernel(0.1);
  const double r10 = std::sqrt(10.0);
  const std::vector<Expected> cases = {
      // dot(x - 0, -e_x) = 0, -1, -0.5, -2
      {make("front_position", {0.0, 0.0}, {-1.0, 0.0}), 0.0, -1.0},
      // y = 0, 0.5, 2, 1
      {make("max_height", {0.0, 0.0}, {0.0, 1.0}), 2.0, 1.0},
      // |v| = 1, 2, 5, sqrt(10)
      {make("max_speed"), 5.0, r10},
      // m |v|^2 = 1, 8, 12.5, 40
      {make("kinetic_energy"), 0.5 * (1.0 + 8.0 + 12.5 + 40.0), 0.5 * (8.0 + 40.0)},
      {make("particle_count"), 4.0, 2.0},
      // |u| = 0.5, 0.7, 1.3, 1.0
      {make("max_displacement"), 1.3, 1.0},
      {mean_of("density"), (1000.0 + 1010.0 + 990.0 + 1020.0) / 4, (1010.0 + 1020.0) / 2},
      {mean_of("mass"), (1.0 + 2.0 + 0.5 + 4.0) / 4, (2.0 + 4.0) / 2},
      {mean_of("pressure"), 250.0, 300.0},
      {mean_of("porosity"), (0.3 + 0.4 + 0.5 + 0.35) / 4, (0.4 + 0.35) / 2},
      {mean_of("speed"), (1.0 + 2.0 + 5.0 + r10) / 4, (2.0 + r10) / 2},
      {mean_of("velocity_x"), (1.0 + 0.0 + 3.0 - 1.0) / 4, (0.0 - 1.0) / 2},
      {mean_of("velocity_y"), (0.0 - 2.0 + 4.0 + 3.0) / 4, (-2.0 + 3.0) / 2},
      // stress: mean of -100 (i + 1) is -250 over all, -300 over {1, 3}; times A(r, c)
      {mean_of("stress_xx"), -250.0, -300.0},
      {mean_of("stress_yy"), -500.0, -600.0},
      {mean_of("stress_zz"), -750.0, -900.0},
      {mean_of("stress_xy"), -1000.0, -1200.0},
      {mean_of("stress_xz"), -1250.0, -1500.0},
      {mean_of("stress_yz"), -1500.0, -1800.0},
  };
  for (const Expected& c : cases) {
    const std::string what = c.observable.kind + " " + c.observable.field;
    const auto all = prepare_observable<2>(c.observable);
    EXPECT_FALSE(all.region.has_region) << what;
    expect_close(evaluate_observable(all, s.view(), kernel), c.all, what + " (all)");
    const auto boxed = prepare_observable<2>(with_region(c.observable, {0.5, 0.0}, {2.0, 1.0}));
    EXPECT_TRUE(boxed.region.has_region) << what;
    expect_close(evaluate_observable(boxed, s.view(), kernel), c.in_region, what + " (region)");
    // Region far from every particle: NaN for front / height / mean, 0 for the others.
    const auto empty = prepare_observable<2>(with_region(c.observable, {10.0, 10.0}, {11.0, 11.0}));
    const double value = evaluate_observable(empty, s.view(), kernel);
    const bool nan_when_empty = c.observable.kind == "front_position" ||
                                c.observable.kind == "max_height" ||
                                c.observable.kind == "mean_field";
    if (nan_when_empty)
      EXPECT_TRUE(std::isnan(value)) << what << " (empty region) = " << value;
    else
      EXPECT_EQ(value, 0.0) << what << " (empty region)";
  }
  // velocity_z does not exist in 2D.
  EXPECT_TRUE(std::isnan(
      evaluate_observable(prepare_observable<2>(mean_of("velocity_z")), s.view(), kernel)));
}

TEST(SphObservables, MissingFieldsGiveNaN) {
  // A water-like view (no porosity, stress, displacement) and a soil-like one (no pressure).
  FourParticles s;
  const CubicSpline<2> kernel(0.1);
  ParticleView<2> water = s.view();
  water.porosity = nullptr;
  water.stress = nullptr;
  water.displacement = nullptr;
  ParticleView<2> bare{s.x.data(), s.v.data(), s.m.data(), nullptr, 4};
  auto eval = [&](const scene::Observable& o, const ParticleView<2>& view) {
    return evaluate_observable(prepare_observable<2>(o), view, kernel);
  };
  for (const char* field :
       {"porosity", "stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_xz", "stress_yz"})
    EXPECT_TRUE(std::isnan(eval(mean_of(field), water))) << field;
  EXPECT_TRUE(std::isnan(eval(make("max_displacement"), water)));
  EXPECT_TRUE(std::isnan(eval(make("max_displacement"), bare)));
  EXPECT_TRUE(std::isnan(eval(mean_of("density"), bare)));
  EXPECT_TRUE(std::isnan(eval(mean_of("pressure"), bare)));
  EXPECT_TRUE(std::isnan(eval(make("pressure_at", {}, {}, {1.0, 0.5}), bare)));
  // Fields the bare view does have still work: speed over all four particles.
  expect_close(eval(mean_of("speed"), bare), (8.0 + std::sqrt(10.0)) / 4, "speed (bare)");
  expect_close(eval(mean_of("density"), water), 1005.0, "density (water)");
}

TEST(SphObservables, ThreeDimensionalRegionAndFields) {
  // Particle 1 inside [0.5, 2]^3, particle 0 (at the origin) outside.
  const std::vector<Vec<3>> x{Vec<3>(0, 0, 0), Vec<3>(1, 1, 1)};
  const std::vector<Vec<3>> v{Vec<3>(1, 2, 2), Vec<3>(0, 0, -1)};
  const std::vector<double> m{2.0, 3.0};
  const std::vector<Vec<3>> u{Vec<3>(1, 2, 2), Vec<3>(0, 0, 0.5)};
  std::vector<Eigen::Matrix3d> sigma(2);
  sigma[0] << -1, 0, 7, 0, -2, 8, 7, 8, -3;
  sigma[1] << -5, 0, 9, 0, -6, 10, 9, 10, -11;
  ParticleView<3> view{x.data(), v.data(), m.data(), nullptr, 2};
  view.stress = sigma.data();
  view.displacement = u.data();
  const CubicSpline<3> kernel(0.1);
  const std::vector<Expected> cases = {
      {make("front_position", {0, 0, 0}, {0, 0, -1}), 0.0, -1.0},
      {make("max_speed"), 3.0, 1.0},
      {make("kinetic_energy"), 0.5 * (2.0 * 9.0 + 3.0 * 1.0), 0.5 * 3.0},
      {make("particle_count"), 2.0, 1.0},
      {make("max_displacement"), 3.0, 0.5},
      {mean_of("velocity_z"), 0.5, -1.0},
      {mean_of("speed"), 2.0, 1.0},
      {mean_of("stress_zz"), -7.0, -11.0},
      {mean_of("stress_xz"), 8.0, 9.0},
      {mean_of("stress_yz"), 9.0, 10.0},
  };
  for (const Expected& c : cases) {
    const std::string what = c.observable.kind + " " + c.observable.field;
    expect_close(evaluate_observable(prepare_observable<3>(c.observable), view, kernel), c.all,
                 what + " (all)");
    const auto boxed =
        prepare_observable<3>(with_region(c.observable, {0.5, 0.5, 0.5}, {2.0, 2.0, 2.0}));
    expect_close(evaluate_observable(boxed, view, kernel), c.in_region, what + " (region)");
  }
}

TEST(SphObservables, PrepareDecodesFieldAndRegion) {
  using Field = PreparedObservable<2>::Field;
  const auto o = prepare_observable<2>(with_region(mean_of("stress_yy"), {0.0, 0.1}, {0.5, 0.2}));
  EXPECT_EQ(o.kind, PreparedObservable<2>::Kind::MeanField);
  EXPECT_EQ(o.field, Field::StressYY);
  EXPECT_TRUE(o.region.has_region);
  EXPECT_EQ(o.region.lo, Vec<2>(0.0, 0.1));
  EXPECT_EQ(o.region.hi, Vec<2>(0.5, 0.2));
  EXPECT_EQ(prepare_observable<2>(make("max_displacement")).kind,
            PreparedObservable<2>::Kind::MaxDisplacement);
  EXPECT_EQ(prepare_observable<2>(mean_of("velocity_x")).field, Field::VelocityX);
  EXPECT_EQ(prepare_observable<3>(mean_of("porosity")).field, Field::Porosity);
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

TEST(SphObservables, PrepareRejectsBadFieldsAndRegions) {
  auto message = [](const scene::Observable& o) -> std::string {
    try {
      prepare_observable<2>(o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  scene::Observable half = make("max_speed");
  half.region_min = {0.0, 0.0};
  EXPECT_TRUE(contains(message(half), "region_min and region_max together")) << message(half);
  half.region_min.clear();
  half.region_max = {1.0, 1.0};
  EXPECT_TRUE(contains(message(half), "region_min and region_max together")) << message(half);
  const std::string wrong_length =
      message(with_region(make("particle_count"), {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}));
  EXPECT_TRUE(contains(wrong_length, "region_min: expected 2 components, got 3")) << wrong_length;
  const std::string wrong_max = message(with_region(make("particle_count"), {0.0, 0.0}, {1.0}));
  EXPECT_TRUE(contains(wrong_max, "region_max: expected 2 components, got 1")) << wrong_max;
  const std::string inverted = message(with_region(make("particle_count"), {0.0, 1.0}, {1.0, 1.0}));
  EXPECT_TRUE(contains(inverted, "greater than region_min")) << inverted;
  const std::string probe =
      message(with_region(make("pressure_at", {}, {}, {0.5, 0.5}), {0.0, 0.0}, {1.0, 1.0}));
  EXPECT_TRUE(contains(probe, "pressure_at takes no region")) << probe;
  EXPECT_TRUE(contains(message(make("bogus")), "unknown kind 'bogus'"));
  EXPECT_TRUE(contains(message(mean_of("stress_yyy")), "unknown field 'stress_yyy'"));
  EXPECT_TRUE(contains(message(mean_of("")), "field is required"));
  scene::Observable stray = make("max_speed");
  stray.field = "density";
  EXPECT_TRUE(contains(message(stray), "only allowed for kind mean_field")) << message(stray);
}

}  // namespace
}  // namespace porosph::sph
