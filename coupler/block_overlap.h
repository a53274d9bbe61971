// Bodies of one phase that overlap (issue 24, hardening): two [[water.blocks]] entries, or two
// [[soil.blocks]] entries, whose particle lattices share a point would put particles there twice
// (water) or silently keep only the first block's (soil). `coupler check` and `coupler run`
// refuse such a scene with exit 2, naming both blocks and their lines; blocks that touch (a box
// ending where the next begins) share no lattice point and pass.
#pragma once

#include <string>

#include "scene/scene.h"

namespace porosph::coupler {

/// "" when no two blocks of a phase overlap, else
/// "FILE:LINE: key 'water.blocks[j]': overlaps water.blocks[i] (line L) at N lattice points ...".
std::string block_overlap_problem(const scene::Scene& scene);

}  // namespace porosph::coupler
