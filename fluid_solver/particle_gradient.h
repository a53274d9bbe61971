// Per-particle renormalisation of the kernel gradient (run.kernel_gradient = "particle"):
//   s_a = D / tr(L_a),   L_a = sum_b V_b (x_b - x_a) (x) grad_a W_ab   (water and wall neighbours),
// the scalar (trace) form of the correction matrix of Bonet & Lok (1999), Comput. Methods Appl.
// Mech. Engrg. 180, 97-115, eq. 27; the kernel already carries the lattice factor
// (sph/lattice_gradient.h), so s_a = 1 on the initial square lattice. A pair uses
// (s_a + s_b) / 2 (a wall pair s_a) in the pressure and continuity terms: still antisymmetric, so
// momentum and mass stay exact. Why: a flowing lattice rearranges. Under the seepage weir of
// docs/verification.md the square lattice in the sand collapsed towards a hexagonal packing, where
// tr(L) / D is 1.028-1.035 (1.036 for a perfect hexagonal packing): every pressure gradient ~3 %
// too strong. The layer's bottom then lost
// 12-15 % of the head difference and the discharge rose by 8 %. With s_a the heads stayed within
// 1.7 % of it (dp 10 mm, 2 s).
// Where the support is incomplete (a free surface: tr(L) / D well below 1) the gradient is left
// as it is: s_a blends from 1 at tr(L) / D <= kFrom to D / tr(L) at tr(L) / D >= kFull, linearly
// in between, and is capped at kFull above (tr / D > 1.1: a clump; left to the lattice factor).
//
// The matrix form (run.kernel_gradient = "particle_matrix"): C_a = (1 - w_a) I + w_a L_a^-1, w_a
// the same blend of t = tr(L_a) / D, and a pair uses (C_a + C_b) / 2 grad_a W_ab (a wall pair
// C_a grad_a W_ab): antisymmetric as the scalar form. Why: a lattice that a shear flow strains
// has an off-diagonal L_xz, which the trace leaves alone, and through it the vertical hydrostatic
// gradient rho g leaks into the horizontal pressure force: equilibrium then needs a horizontal
// head gradient of -L_xz / L_xx. In the seepage weir's pools (flow 5-8 mm/s) L_xz was -0.0013 to
// -0.0021 at dp 10 and 5 mm alike, and the pools' heads fell by 0.3-0.6 mm (0.6-1.2 % of the
// head difference) along the flow over 0.36 m, as that predicts, at every resolution and with any
// artificial viscosity (docs/verification.md, seepage under a weir).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "sph/neighbour_list.h"
#include "sph/vector.h"

namespace porosph::water {

struct ParticleGradient {
  static constexpr double kFrom = 0.90;  ///< tr(L) / D at and below which s_a = 1
  static constexpr double kFull = 0.97;  ///< from which s_a = D / tr(L)
  static constexpr double kMax = 1.10;   ///< above which s_a = 1 again
  /// The matrix form keeps C_a = I where an eigenvalue of L_a lies below this (a support
  /// missing on one side that the trace does not show).
  static constexpr double kMinEigenvalue = 0.5;

  /// The blend weight w in [0, 1] of t = tr(L_a) / D (above): 0 at t <= kFrom, above kMax and
  /// for NaN.
  static double weight(double t) {
    if (!(t > kFrom) || t > kMax) return 0.0;
    return std::min(1.0, (t - kFrom) / (kFull - kFrom));
  }

  /// s_a from t = tr(L_a) / D.
  static double scale(double t) {
    if (!(t > kFrom) || t > kMax) return 1.0;
    const double w = weight(t);
    return 1.0 + w * (1.0 / t - 1.0);
  }

  /// C_a = (1 - w) I + w L^-1 of L = L_a (the matrix form, above).
  template <int D>
  static Eigen::Matrix<double, D, D> correction(const Eigen::Matrix<double, D, D>& L) {
    using Mat = Eigen::Matrix<double, D, D>;
    const double w = weight(L.trace() / D);
    if (w == 0.0) return Mat::Identity();
    Eigen::SelfAdjointEigenSolver<Mat> eigen;
    eigen.computeDirect(L, Eigen::EigenvaluesOnly);
    if (!(eigen.eigenvalues().minCoeff() > kMinEigenvalue)) return Mat::Identity();
    return (1.0 - w) * Mat::Identity() + w * L.inverse();
  }

  /// A pair's corrected kernel gradient and its factor along x_ab (grad_w . x_ab / r^2, what the
  /// trace of L sums; for the scalar forms grad_w = factor x_ab).
  template <int D>
  struct Pair {
    sph::Vec<D> grad_w;
    double factor;
  };

  /// Water pair a, b of `grad_factor` = dW/dr / r and x_ab: (s_a + s_b) / 2 grad W, or with the
  /// matrix form (`matrix` not null) (C_a + C_b) / 2 grad W.
  template <int D>
  static Pair<D> water_pair(const double* scale, const Eigen::Matrix<double, D, D>* matrix,
                            std::size_t a, std::size_t b, double grad_factor,
                            const sph::Vec<D>& x_ab, double r) {
    if (matrix == nullptr) {
      const double factor = grad_factor * (0.5 * (scale[a] + scale[b]));
      return {factor * x_ab, factor};
    }
    const sph::Vec<D> grad_w = grad_factor * (0.5 * (matrix[a] + matrix[b]) * x_ab);
    return {grad_w, grad_w.dot(x_ab) / (r * r)};
  }

  /// Water particle a and wall particle b: s_a grad W, or C_a grad W (above).
  template <int D>
  static Pair<D> wall_pair(const double* scale, const Eigen::Matrix<double, D, D>* matrix,
                           std::size_t a, double grad_factor, const sph::Vec<D>& x_ab, double r) {
    if (matrix == nullptr) {
      const double factor = grad_factor * scale[a];
      return {factor * x_ab, factor};
    }
    const sph::Vec<D> grad_w = grad_factor * (matrix[a] * x_ab);
    return {grad_w, grad_w.dot(x_ab) / (r * r)};
  }

  /// s_a of the water particles (the first n_free of the list) into `out` (resized); `volume`
  /// the V = m / rho of every particle of the list.
  template <int D, class Kernel>
  static void compute(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                      std::size_t n_free, const std::vector<double>& volume,
                      std::vector<double>& out) {
    out.resize(n_free);
    const std::int64_t n = static_cast<std::int64_t>(n_free);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t a = 0; a < n; ++a) {
      double trace = 0.0;  // sum_b V_b (x_b - x_a) . grad_a W_ab = -sum_b V_b grad_factor r^2
      for (auto it = neighbours.begin(a); it != neighbours.end(a); ++it)
        trace -= volume[it->b] * kernel.grad_factor(it->r) * it->r * it->r;
      out[a] = scale(trace / D);
    }
  }

  /// C_a (the matrix form, above) of the water particles (the first n_free of the list) into
  /// `out` (resized); `volume` the V = m / rho of every particle of the list.
  template <int D, class Kernel>
  static void compute_matrix(const sph::NeighbourList<D>& neighbours, const Kernel& kernel,
                             std::size_t n_free, const std::vector<double>& volume,
                             std::vector<Eigen::Matrix<double, D, D>>& out) {
    using Mat = Eigen::Matrix<double, D, D>;
    out.resize(n_free);
    const std::int64_t n = static_cast<std::int64_t>(n_free);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t a = 0; a < n; ++a) {
      Mat L = Mat::Zero();  // sum_b V_b (x_b - x_a) (x) grad_a W_ab = -sum_b V_b F x_ab x_ab^T
      for (auto it = neighbours.begin(a); it != neighbours.end(a); ++it)
        L.noalias() -=
            (volume[it->b] * kernel.grad_factor(it->r)) * it->x_ab * it->x_ab.transpose();
      out[a] = correction<D>(L);
    }
  }
};

}  // namespace porosph::water
