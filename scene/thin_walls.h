// Walls too thin to part the particles of one phase on their two sides (docs/water-in-soil.md,
// section 2): a wall of L particle layers keeps two bodies of water (or soil) apart by itself
// only for L >= 2m, m = ceil(2h / dp) - 1 (4 layers at h = 1.2 dp). The solvers fill such walls on
// both sides (sph/wall_occluders.h) where water.thin_walls / soil.thin_walls = "separating"; the
// term registry and `coupler check` ask here which walls those are.
#pragma once

#include <string>

#include "scene/scene.h"

namespace porosph::scene {

/// Number of lattice centres min + (i + 1/2) dp that lie below max (round-off tolerant): the
/// particle layers a box fills along one axis.
long lattice_count(double min, double max, double dp);

/// The fewest particle layers a wall between two bodies of one phase needs at this h and dp: 2m.
int separating_wall_layers(double h, double dp);

/// For a box wall of `scene` acting on `phase` ("water" or "soil"): the axis along which it is
/// thinner than separating_wall_layers() with blocks of that phase within 2h of both its faces
/// (over its span across the axis), or -1 (a thick wall, a wall with the phase on one side only,
/// a polygon or container).
int thin_wall_axis(const Scene& scene, const Shape& wall, const std::string& phase);

/// True if a wall acting on `phase` that does not move is thin (thin_wall_axis >= 0): the walls
/// that "separating" fills on both sides.
bool has_thin_walls(const Scene& scene, const std::string& phase);

}  // namespace porosph::scene
