// The overlap zone the coupler sends each solver (docs/design.md section 1): a solver reports only
// its particles inside the box it was sent, so each solver gets the OTHER phase's region (the
// bounding box of its interacting particles) inflated by the kernel support 2h, which holds every
// particle that can pair with the other phase. Along a periodic axis a pair can reach across the
// faces, so the box spans the whole domain there.
#pragma once

#include <vector>

#include "proto/coupling_client.h"
#include "scene/scene.h"

namespace porosph::coupler {

/// Fills [min, max] with the other phase's region [other.region_min, other.region_max] inflated by
/// 2 scene.h(), the domain extent on periodic axes. An empty or missing region (no particle:
/// min > max, wrong length or NaN) gives empty vectors: the solver then sends no particle.
void overlap_region_for(const coupling::StepState& other, const scene::Scene& scene,
                        std::vector<double>& min, std::vector<double>& max);

}  // namespace porosph::coupler
