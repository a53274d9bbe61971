// Lattice normalisation of the kernel gradient.
//
// An SPH gradient is exact for a linear field u = g . x only when the particles around a satisfy
//   sum_b V_b (x_b - x_a) (x) grad_a W_ab = I                                          (1)
// (the first-order consistency condition; Bonet & Lok 1999, Comput. Methods Appl. Mech. Engrg.
// 180, 97-115, eq. 27). The continuum integral of a normalised kernel satisfies (1), but the sum
// over the particle lattice does not: for the cubic spline at h = 1.2 dp on a square lattice the
// sum is 0.9908 I (Wendland C2: 0.9639 I). Every gradient and divergence of the solver - the
// pressure force, the continuity equation, the strain rate and the stress divergence - is then too
// small by that factor: still water needs a pressure 1 / 0.9908 too high to carry its weight (+0.93
// % at every depth), an elastic column is 0.9908^2 too soft (+1.9 % settlement). Refining at fixed
// h / dp leaves that error unchanged.
//
// The lattice normalisation divides dW/dr by the lattice sum S of (1) for the scene's h / dp, so
// that (1) holds exactly on the initial lattice. It is the constant, lattice limit of Bonet & Lok's
// correction matrix L_a = (sum_b V_b x_ba (x) grad W_ab)^-1, which equals I / S there; unlike a
// per-particle L_a it keeps every pair force antisymmetric, so momentum stays conserved to
// round-off. Away from the lattice (free surfaces, disordered flow) it is a constant rescaling, as
// good as the lattice is representative; it changes nothing that uses W itself (density sums, drag,
// probes).
#pragma once

#include <cmath>
#include <stdexcept>

#include "sph/vector.h"

namespace porosph::sph {

/// Calls visit(index) for every site of a square (cubic) lattice within `reach` sites of the
/// origin along each axis, index[k] in [-reach, reach] for k < D (the lattice sums below).
template <int D, class Visit>
void for_each_lattice_site(int reach, const Visit& visit) {
  int index[3] = {-reach, -reach, -reach};
  for (;;) {
    visit(static_cast<const int*>(index));
    int k = 0;
    while (k < D && ++index[k] > reach) index[k++] = -reach;
    if (k == D) break;
  }
}

/// S = sum_b V_b (x_b - x_a)_x (grad_a W_ab)_x over a square (cubic) lattice of spacing dp around a
/// particle at the origin, V_b = dp^D: the factor by which kernel gradients on the lattice fall
/// short of the identity (1). Depends only on the kernel's shape and h / dp.
template <class Kernel>
double lattice_gradient_sum(const Kernel& kernel, double dp) {
  constexpr int D = Kernel::kDim;
  if (!(dp > 0.0)) throw std::invalid_argument("lattice_gradient_sum: dp must be > 0");
  const int reach = static_cast<int>(std::ceil(kernel.support() / dp));
  const double volume = std::pow(dp, D);
  double sum = 0.0;
  for_each_lattice_site<D>(reach, [&](const int* index) {
    double r2 = 0.0;
    for (int k = 0; k < D; ++k) r2 += index[k] * index[k] * dp * dp;
    const double r = std::sqrt(r2);
    if (r > 0.0 && r < kernel.support()) {
      // x_ab = x_a - x_b = -x_b; d W / d x_a,x = grad_factor * x_ab,x; (x_b - x_a)_x = x_b,x
      const double xb = index[0] * dp;
      sum += volume * xb * (kernel.grad_factor(r) * (-xb));
    }
  });
  return sum;
}

/// The kernel of the scene: plain (gradient_scale 1) or lattice-normalised (1 / S).
template <class Kernel>
Kernel make_kernel(double h, double dp, bool lattice_normalised) {
  if (!lattice_normalised) return Kernel(h);
  const double s = lattice_gradient_sum(Kernel(h), dp);
  return Kernel(h, 1.0 / s);
}

}  // namespace porosph::sph
