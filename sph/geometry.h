// Geometry -> particles: lattice fill of the scene's shapes (scene::Shape) at spacing dp.
//
//  Box:       centres at min + (i + 1/2) dp along each axis, as long as the centre lies below max.
//  Polygon:   (2D) lattice anchored at the bounding-box min + dp/2, points inside the polygon
//             (even-odd rule).
//  Container: `layers` layers of wall particles outside the inner box [min, max], at distances
//             (k + 1/2) dp outside each closed face, corners filled; faces in open_faces ("x-",
//             "y+",
//             ...) are left open. Inside the inner box the lattice is that of a Box fill.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "scene/thin_walls.h"
#include "sph/vector.h"

namespace porosph::sph {

/// Lattice points filling `shape` (see above). Throws std::invalid_argument on a malformed shape
/// (wrong vector lengths, polygon in 3D or with fewer than 3 vertices, unknown face name).
template <int D>
std::vector<Vec<D>> fill_shape(const scene::Shape& shape, double dp);

/// True if x lies inside `shape`: the box, the polygon, or a container's wall layers (the region
/// between the inner box and the inner box grown by layers x dp across each closed face).
template <int D>
bool inside_shape(const scene::Shape& shape, const Vec<D>& x, double dp);

/// Water (or soil) block fill: the lattice of `block` without the points inside any of `walls`.
template <int D>
std::vector<Vec<D>> fill_block_outside_walls(const scene::Shape& block,
                                             const std::vector<scene::Shape>& walls, double dp);

/// Even-odd point-in-polygon test (2D).
bool point_in_polygon(const std::vector<std::vector<double>>& vertices, double x, double y);

/// Number of lattice centres min + (i + 1/2) dp that lie below max (round-off tolerant;
/// scene/thin_walls.h).
using scene::lattice_count;

}  // namespace porosph::sph
