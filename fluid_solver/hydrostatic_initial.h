// Hydrostatic initial state of the water (so that still water starts in equilibrium):
//   p_a = p(s_level(a) - s_a),   rho_a = inverse of eq. 4 at p_a,
// p(d) the pressure of still weakly compressible water d below its surface
// (TaitEos::still_water_pressure; rho0 |g| d to first order),
// with s = x . (-g/|g|) the height along -g. The level is found per connected water body
// (water_bodies.h: particles linked through neighbours at most 1.5 dp apart, so a wall separates
// bodies and a gap under it joins them), each from its own free surface:
//  - the particles of one body are binned into columns perpendicular to g (bins of width dp, so no
//    "up" axis is assumed), and each column is split into runs where two consecutive particles
//    are more than 1.5 dp apart along g (a wall or an air gap between them);
//  - a run that nothing covers takes its own top: s_level = (highest centre of the run) + dp/2,
//    the free surface lying half a spacing above the top particle centres;
//  - a run covered by a wall (a wall particle in its column less than 2 dp above its top centre:
//    water under a wall's tip, under a plate or a lid) takes the body's top instead: s_level =
//    (highest centre of the whole body) + dp/2.
// So two pools that a wall separates each start from their own surface, one pool in two columns
// stacked one above the other (a shelf) too, and the water under a wall's tip has the pressure of
// its body's surface, not of its own column's (the wall's). A body whose columns have different
// free-surface levels (not at rest) keeps them column by column.
#pragma once

#include <cstddef>

#include "fluid_solver/equation_of_state.h"
#include "sph/vector.h"

namespace porosph::water {

/// Writes pressure[i] and density[i] for the n water particles at x; the n_walls wall particles
/// at walls cover the water beneath them (see above). Zero gravity: p = 0, rho = rho0.
template <int D>
void hydrostatic_state(const sph::Vec<D>* x, std::size_t n, const sph::Vec<D>* walls,
                       std::size_t n_walls, const sph::Vec<D>& gravity, double dp,
                       const TaitEos& eos, double* pressure, double* density);

/// The same without walls.
template <int D>
void hydrostatic_state(const sph::Vec<D>* x, std::size_t n, const sph::Vec<D>& gravity, double dp,
                       const TaitEos& eos, double* pressure, double* density) {
  hydrostatic_state<D>(x, n, nullptr, 0, gravity, dp, eos, pressure, density);
}

}  // namespace porosph::water
