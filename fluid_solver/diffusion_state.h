// What the density diffusion needs of one water particle (density_diffusion.h), computed once per
// particle and rate evaluation so that the pair loops only read it.
#pragma once

namespace porosph::water {

/// s = rho / rho0: s^(2 - gamma) (kappa over rho0 / c0^2) and s^(gamma - 1) ((gamma - 1) Phi / c0^2
/// + 1).
struct DiffusionState {
  double inv_s_gamma_2 = 1.0;
  double s_gamma_1 = 1.0;
};

}  // namespace porosph::water
