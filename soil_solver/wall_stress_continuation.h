// Linear continuation of the soil's stress into its wall particles (soil.wall_stress_continuation
// = "linear", an option; "weight" is the default; used by update_soil_wall_state, soil_walls.h).
//
// A wall particle w takes the Shepard mean of its free soil neighbours f, each continued to x_w:
//   sigma_w = sum_f W_wf c_f(x_w) / sum_f W_wf
//   "weight": c_f = sigma_f - rho_f (g . x_wf) I   (Adami, Hu & Adams 2012 eq. 27, made isotropic)
//   "linear": c_f = sigma_f + limited(sum_k (d sigma / d x_k)_f x_wf,k, -rho_f (g . x_wf))
// x_wf = x_w - x_f; limited() keeps, per diagonal component, the first-order (Taylor) change
// where it has the sign of the weight's and is smaller, and the weight's change otherwise (a
// minmod limiter); the shear gets the weight form's, none. The weight form continues the normal
// stress that carries the weight onto a floor exactly, but its horizontal stress grows with depth
// as fast as the vertical one, where a geostatic state grows it K0 times as fast: the floor's and a
// corner's wall particles are too compressed sideways by (1 - K0) rho g dy. Along a floor that
// excess cancels left and right; at a corner it does not, and a settled column carried 0.09-0.14 %
// more weight in its wall columns over the lowest 0.1 m at dp 2.5 mm, an error that grew as dp fell
// (docs/validation-studies.md, soil_column, session 30). The limited linear form is exact for a
// geostatic state (its K0 included: K0 rho g dy has the sign of rho g dy and is smaller) and never
// continues a component further than the weight does. Why limited: the plain Taylor form
// extrapolates the row-to-row stress oscillation of the soil next to a floor (the second wall layer
// sees one soil row, the first two), and the wall feeds it back: a soil column without the stress
// filter went unstable in 0.05 s (max speed 0.6 m/s, vertical stress off by 100-380 % near its
// floor, dp 5 mm; docs/validation-studies.md, session 32). With the limiter the same column stays
// at rest (1.4e-8 m/s).
//
// The gradient is the first-order corrected SPH gradient over the free neighbours b of f
// (Bonet & Lok 1999, Comput. Methods Appl. Mech. Engrg. 180, 97-115; Randles & Libersky 1996):
//   A_f = sum_b V_b grad_f W_fb (x) x_bf,   s_f,k = sum_b V_b (sigma_b - sigma_f) (grad_f W_fb)_k,
//   (d sigma / d x_m)_f = sum_k (A_f^-1)_mk s_f,k,
// exact for a linear field whatever the neighbours' layout, as long as A_f can be inverted. Where
// the smallest eigenvalue of A_f (symmetric for a radial kernel) is below kMinimumGradientSupport
// (a particle with its neighbours on less than about a quarter of its support: a splash, a free
// corner) the gradient is not trusted and f falls back to the weight form, pair by pair.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "soil_solver/soil_particles.h"
#include "soil_solver/velocity_gradient.h"
#include "sph/vector.h"

namespace porosph::soil {

/// Smallest eigenvalue of A_f (1 with a full support on a lattice, about 1/2 next to a
/// straight wall, 1/4 in a corner) below which f's stress gradient is not used.
inline constexpr double kMinimumGradientSupport = 0.2;

/// Per component: the linear change where it has the sign of the weight form's and is smaller,
/// else the weight form's (a minmod limiter; Roe 1986, Annu. Rev. Fluid Mech. 18, 337-365). Only
/// the diagonal can differ from the weight form's, which has no shear.
inline Eigen::Matrix3d limited_change(const Eigen::Matrix3d& linear, double weight_change) {
  Eigen::Matrix3d out = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const double l = linear(k, k);
    out(k, k) =
        (l * weight_change > 0.0 && std::abs(l) < std::abs(weight_change)) ? l : weight_change;
  }
  return out;
}

/// d sigma / d x_k of one free particle (3x3 each, in-plane k < D) and whether it is trusted.
template <int D>
struct StressGradient {
  std::array<Eigen::Matrix3d, D> d{};
  bool trusted = false;

  /// sum_k (d sigma / d x_k) x_k: the change of the stress over x.
  Eigen::Matrix3d change_over(const sph::Vec<D>& x) const {
    Eigen::Matrix3d out = d[0] * x[0];
    for (int k = 1; k < D; ++k) out.noalias() += d[k] * x[k];
    return out;
  }
};

/// The corrected stress gradient of free particle a over its free neighbours [begin(a), mid(a)).
template <int D, class List, class Kernel>
StressGradient<D> corrected_stress_gradient(const List& neighbours, const Kernel& kernel,
                                            const SoilParticles<D>& P, std::int64_t a) {
  StressGradient<D> g;
  // A = sum_b V_b grad_a W_ab (x) x_ba = -sum_b V_b F_ab x_ab x_ab^T (grad_a W_ab = F_ab x_ab):
  // symmetric for a radial kernel.
  MatD<D> A = MatD<D>::Zero();
  std::array<Eigen::Matrix3d, D> s;
  for (auto& m : s) m.setZero();
  for (auto it = neighbours.begin(a); it != neighbours.mid(a); ++it) {
    const std::int32_t b = it->b;
    const double volume = P.mass[b] / P.density[b];
    const sph::Vec<D> grad = kernel.gradient(it->x_ab, it->r);  // grad_a W_ab
    A.noalias() -= volume * grad * it->x_ab.transpose();
    const Eigen::Matrix3d difference = P.stress[b] - P.stress[a];
    for (int k = 0; k < D; ++k) s[k].noalias() += (volume * grad[k]) * difference;
  }
  const Eigen::SelfAdjointEigenSolver<MatD<D>> eigen(A, Eigen::EigenvaluesOnly);
  if (!(eigen.eigenvalues()(0) >= kMinimumGradientSupport)) return g;
  const MatD<D> inverse = A.inverse();
  for (int m = 0; m < D; ++m) {
    g.d[m].setZero();
    for (int k = 0; k < D; ++k) g.d[m].noalias() += inverse(m, k) * s[k];
  }
  g.trusted = true;
  return g;
}

/// Fills gradients[f] for every free particle f with a fixed neighbour (the only ones a wall
/// particle reads); the others are left untrusted. `gradients` is resized to P.n_free (no
/// allocation once it has reached that size).
template <int D, class List, class Kernel>
void stress_gradients_next_to_walls(const List& neighbours, const Kernel& kernel,
                                    const SoilParticles<D>& P,
                                    std::vector<StressGradient<D>>& gradients) {
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  gradients.resize(P.n_free);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t f = 0; f < n; ++f) {
    if (neighbours.mid(f) == neighbours.end(f)) {
      gradients[f].trusted = false;
      continue;
    }
    gradients[f] = corrected_stress_gradient<D>(neighbours, kernel, P, f);
  }
}

}  // namespace porosph::soil
