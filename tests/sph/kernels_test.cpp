// Kernels: normalisation, gradient consistency on a lattice, dW/dr against finite differences.
#include "sph/kernels.h"

#include <gtest/gtest.h>

#include <cmath>

namespace porosph::sph {
namespace {

template <class K>
class SphKernel : public ::testing::Test {};
using Kernels = ::testing::Types<CubicSpline<2>, CubicSpline<3>, WendlandC2<2>, WendlandC2<3>>;
TYPED_TEST_SUITE(SphKernel, Kernels);

/// Calls fn(x) for the lattice points k * dx (k integer) within radius `reach` of the origin.
template <int D, class Fn>
void for_each_lattice_point(double dx, double reach, Fn&& fn) {
  const int m = static_cast<int>(std::ceil(reach / dx));
  int idx[3] = {-m, -m, -m};
  while (true) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = idx[k] * dx;
    fn(x);
    int k = 0;
    while (k < D && ++idx[k] > m) idx[k++] = -m;
    if (k == D) return;
  }
}

TYPED_TEST(SphKernel, RadialIntegralIsOne) {
  // Simpson quadrature of W(r) |S^{D-1}| r^{D-1} over [0, 2h]: exact to ~1e-10 for a piecewise
  // polynomial with 4000 intervals; tolerance 1e-8.
  constexpr int D = TypeParam::kDim;
  const TypeParam kernel(0.37);
  const double surface = D == 2 ? 2.0 * M_PI : 4.0 * M_PI;
  const int n = 4000;
  const double dr = kernel.support() / n;
  double integral = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = i * dr;
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    integral += weight * kernel.w(r) * surface * std::pow(r, D - 1);
  }
  integral *= dr / 3.0;
  EXPECT_NEAR(integral, 1.0, 1e-8);
}

TYPED_TEST(SphKernel, LatticeSumOfVolumeTimesWIsOne) {
  // sum_b dx^D W(|x_b|) over a lattice of spacing h/8: a midpoint-rule integral of a smooth kernel,
  // accurate far below the 1e-3 tolerance.
  constexpr int D = TypeParam::kDim;
  const double h = 0.01, dx = h / 8.0;
  const TypeParam kernel(h);
  double sum = 0.0;
  for_each_lattice_point<D>(dx, kernel.support(),
                            [&](const Vec<D>& x) { sum += std::pow(dx, D) * kernel.w(x.norm()); });
  EXPECT_NEAR(sum, 1.0, 1e-3);
}

/// sum_b V_b (x_a - x_b) (x) grad_a W_ab over a lattice of spacing dx around a particle at the
/// origin (the SPH gradient of the position field, written with x_a - x_b).
template <class K>
Eigen::Matrix<double, K::kDim, K::kDim> lattice_gradient_moment(double dx, double h) {
  constexpr int D = K::kDim;
  const K kernel(h);
  Eigen::Matrix<double, D, D> sum = Eigen::Matrix<double, D, D>::Zero();
  for_each_lattice_point<D>(dx, kernel.support(), [&](const Vec<D>& xb) {
    const Vec<D> x_ab = -xb;
    const double r = x_ab.norm();
    if (r > 0.0) sum += std::pow(dx, D) * x_ab * kernel.gradient(x_ab, r).transpose();
  });
  return sum;
}

TYPED_TEST(SphKernel, GradientConsistencyOnLattice) {
  // sum_b V_b (x_a - x_b) (x) grad_a W_ab = -I for an interior lattice particle. At h = 3 dx the
  // lattice sums of both kernels are within 2.5e-4 of -I (computed independently); tolerance 1e-3.
  constexpr int D = TypeParam::kDim;
  const auto minus_identity = -Eigen::Matrix<double, D, D>::Identity();
  const auto fine = lattice_gradient_moment<TypeParam>(0.01, 0.03);
  EXPECT_LT((fine - minus_identity).cwiseAbs().maxCoeff(), 1e-3) << fine;
  // At the scenes' h = 1.2 dx the lattice sum is off by 1-4 % (cubic 2D 0.9 %, 3D 1.8 %; Wendland
  // 2D 3.6 %, 3D 1.5 %): a property of the kernels on a coarse lattice, bounded here at 5 %.
  const auto coarse = lattice_gradient_moment<TypeParam>(0.01, 0.012);
  EXPECT_LT((coarse - minus_identity).cwiseAbs().maxCoeff(), 5e-2) << coarse;
}

TYPED_TEST(SphKernel, DerivativeMatchesFiniteDifference) {
  // Central difference with step 1e-6 h: truncation ~1e-12 h^-2, round-off ~1e-10 of W/h; points
  // avoid the spline knots q = 1, 2. Tolerance 1e-6 of max |dW/dr|.
  const double h = 0.02;
  const TypeParam kernel(h);
  const double scale = std::abs(kernel.dw_dr(0.8 * h));
  for (double q : {0.05, 0.3, 0.7, 0.95, 1.2, 1.5, 1.9}) {
    const double r = q * h, e = 1e-6 * h;
    const double fd = (kernel.w(r + e) - kernel.w(r - e)) / (2.0 * e);
    EXPECT_NEAR(kernel.dw_dr(r), fd, 1e-6 * scale) << "q = " << q;
    EXPECT_NEAR(kernel.grad_factor(r), kernel.dw_dr(r) / r, 1e-12 * scale / r) << "q = " << q;
  }
  EXPECT_EQ(kernel.w(2.0 * h), 0.0);
  EXPECT_EQ(kernel.dw_dr(2.0 * h + 1e-9), 0.0);
  EXPECT_LT(kernel.dw_dr(0.5 * h), 0.0);  // W decreases with r
}

TYPED_TEST(SphKernel, GradientVectorIsRadial) {
  constexpr int D = TypeParam::kDim;
  const TypeParam kernel(0.01);
  Vec<D> x_ab = Vec<D>::Zero();
  x_ab[0] = 0.003;
  x_ab[1] = -0.004;  // r = 0.005
  const Vec<D> g = kernel.gradient(x_ab, 0.005);
  const Vec<D> expected = kernel.dw_dr(0.005) * x_ab / 0.005;
  EXPECT_LT((g - expected).norm(), 1e-12 * expected.norm());
}

TEST(SphKernelValues, CubicSplineNormalisationConstants) {
  // W(0) = sigma: 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D (Monaghan 1992).
  const double h = 0.5;
  EXPECT_NEAR(CubicSpline<2>(h).w(0.0), 10.0 / (7.0 * M_PI * h * h), 1e-14);
  EXPECT_NEAR(CubicSpline<3>(h).w(0.0), 1.0 / (M_PI * h * h * h), 1e-14);
  // q = 1: sigma / 4.
  EXPECT_NEAR(CubicSpline<2>(h).w(h), 0.25 * 10.0 / (7.0 * M_PI * h * h), 1e-14);
  // Wendland C2 W(0) = alpha: 7 / (4 pi h^2), 21 / (16 pi h^3).
  EXPECT_NEAR(WendlandC2<2>(h).w(0.0), 7.0 / (4.0 * M_PI * h * h), 1e-14);
  EXPECT_NEAR(WendlandC2<3>(h).w(0.0), 21.0 / (16.0 * M_PI * h * h * h), 1e-14);
}

}  // namespace
}  // namespace porosph::sph
