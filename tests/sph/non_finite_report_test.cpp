// The solvers' non-finite pre-check (sph/non_finite_report.h): every non-finite value is caught,
// wherever it sits in the array (the pass is vectorised: head, body and tail of the lanes).
#include "sph/non_finite_report.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace porosph::sph {
namespace {

TEST(NonFinite, AllFiniteFindsEveryNaNAndInfinity) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (std::size_t n : {1u, 7u, 8u, 9u, 64u, 1001u}) {
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = (k % 2 ? -1.0 : 1.0) * 1e300 * (k + 1) / n;
    v[0] = -0.0;  // finite, and 0 x -0 = -0 must still count as finite
    EXPECT_TRUE(all_finite(v.data(), n)) << n;
    for (std::size_t at : {std::size_t{0}, n / 2, n - 1}) {
      for (const double b : bad) {
        std::vector<double> w = v;
        w[at] = b;
        EXPECT_FALSE(all_finite(w.data(), n)) << "n " << n << ", at " << at << ", " << b;
      }
    }
  }
  EXPECT_TRUE(all_finite(nullptr, 0));
}

}  // namespace
}  // namespace porosph::sph
