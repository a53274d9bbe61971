// The blocks of a scene on the particle lattice of run.dp (issue 24, hardening), which `coupler
// check` and `coupler run` refuse with exit 2, naming the block and its line:
// - a block that holds no lattice point (thinner than dp along an axis): a body that would
//   silently not exist;
// - two [[water.blocks]] entries, or two [[soil.blocks]] entries, whose lattices share a point:
//   water would be placed there twice, soil silently only from the first block. Blocks that
//   touch (a box ending where the next begins) share no lattice point and pass.
#pragma once

#include <string>

#include "scene/scene.h"

namespace porosph::coupler {

/// Skipped ("") for scenes whose blocks hold more than 2e7 lattice points (the size gate refuses
/// them unless forced). "" when every block holds a lattice point and no two blocks of a phase
/// overlap, else "FILE:LINE: key 'water.blocks[j]': ..." for the first that does not.
std::string block_lattice_problem(const scene::Scene& scene);

}  // namespace porosph::coupler
