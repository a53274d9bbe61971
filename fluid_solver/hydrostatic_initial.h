// Hydrostatic initial state of the water (so that a still tank starts in equilibrium):
//   p_a = rho0 |g| (s_top - s_a),   rho_a = inverse of eq. 4 at p_a,
// with s = x . (-g/|g|) the height along -g and s_top the top of the water column above particle a
// plus dp/2 (the free surface lies half a spacing above the top particle centres). Columns are
// found by binning the coordinates perpendicular to g at dp, so no "up" axis is assumed. A column
// holding two separate water bodies gets the top of the upper one (a limitation of the binning).
#pragma once

#include <cstddef>

#include "fluid_solver/equation_of_state.h"
#include "sph/vector.h"

namespace porosph::fluid {

/// Writes pressure[i] and density[i] for the n particles at x. Zero gravity: p = 0, rho = rho0.
template <int D>
void hydrostatic_state(const sph::Vec<D>* x, std::size_t n, const sph::Vec<D>& gravity, double dp,
                       const TaitEos& eos, double* pressure, double* density);

}  // namespace porosph::fluid
