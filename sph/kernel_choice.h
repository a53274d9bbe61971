// The kernel a scene picks (run.kernel, run.kernel_gradient) and the one dispatch from that
// runtime choice to the pair loops compiled for each kernel type: every particle solver and the
// soil-water interaction take their kernel from here (issue 24, the shared phase core).
#pragma once

#include <stdexcept>
#include <string>

#include "sph/kernels.h"
#include "sph/lattice_gradient.h"

namespace porosph::sph {

template <int D>
class KernelChoice {
 public:
  /// `name` "cubic_spline" or "wendland_c2" at smoothing length h; with `lattice_normalised`
  /// (run.kernel_gradient != "plain") dW/dr is normalised on the lattice of spacing dp
  /// (lattice_gradient.h). Throws std::invalid_argument naming run.kernel for another name.
  KernelChoice(const std::string& name, double h, double dp, bool lattice_normalised)
      : wendland_(name == "wendland_c2"),
        cubic_(make_kernel<CubicSpline<D>>(h, dp, lattice_normalised)),
        wendland_kernel_(make_kernel<WendlandC2<D>>(h, dp, lattice_normalised)) {
    if (name != "cubic_spline" && name != "wendland_c2")
      throw std::invalid_argument("run.kernel: unknown kernel '" + name + "'");
  }

  /// f(kernel) with the chosen kernel as its concrete type; returns what f returns.
  template <class F>
  decltype(auto) visit(F&& f) const {
    if (wendland_) return f(wendland_kernel_);
    return f(cubic_);
  }

 private:
  bool wendland_ = false;
  CubicSpline<D> cubic_;
  WendlandC2<D> wendland_kernel_;
};

}  // namespace porosph::sph
