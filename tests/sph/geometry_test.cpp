// Geometry -> particles: lattice counts and positions of boxes, containers and polygons.
#include "sph/geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace porosph::sph {
namespace {

scene::Shape make_box(std::vector<double> lo, std::vector<double> hi) {
  scene::Shape s;
  s.kind = scene::Shape::Kind::Box;
  s.min = std::move(lo);
  s.max = std::move(hi);
  return s;
}

scene::Shape make_container(std::vector<double> lo, std::vector<double> hi, int layers,
                            std::vector<std::string> open = {}) {
  scene::Shape s = make_box(std::move(lo), std::move(hi));
  s.kind = scene::Shape::Kind::Container;
  s.layers = layers;
  s.open_faces = std::move(open);
  return s;
}

TEST(SphGeometry, BoxTenByTwentyGivesTwoHundredCentredPoints) {
  const auto pts = fill_shape<2>(make_box({0.0, 0.0}, {0.1, 0.2}), 0.01);
  ASSERT_EQ(pts.size(), 200u);
  double min_x = 1, min_y = 1, max_x = 0, max_y = 0;
  for (const auto& p : pts) {
    min_x = std::min(min_x, p[0]), min_y = std::min(min_y, p[1]);
    max_x = std::max(max_x, p[0]), max_y = std::max(max_y, p[1]);
  }
  EXPECT_NEAR(min_x, 0.005, 1e-12);
  EXPECT_NEAR(min_y, 0.005, 1e-12);
  EXPECT_NEAR(max_x, 0.095, 1e-12);
  EXPECT_NEAR(max_y, 0.195, 1e-12);
}

TEST(SphGeometry, BoxIn3DAndNonMultipleLengths) {
  EXPECT_EQ(fill_shape<3>(make_box({0, 0, 0}, {0.1, 0.05, 0.03}), 0.01).size(), 10u * 5u * 3u);
  // 0.104 / 0.01 = 10.4: centres 0.005 ... 0.095 (10 points; 0.105 > 0.104).
  EXPECT_EQ(lattice_count(0.0, 0.104, 0.01), 10);
  // 0.106: the 11th centre 0.105 lies inside.
  EXPECT_EQ(lattice_count(0.0, 0.106, 0.01), 11);
}

TEST(SphGeometry, ContainerLayerCounts) {
  // Inner 10 x 10 cells, 3 layers: closed (16^2 - 10^2 = 156), open top (16 x 13 - 100 = 108).
  EXPECT_EQ(fill_shape<2>(make_container({0, 0}, {1, 1}, 3), 0.1).size(), 156u);
  const auto open = fill_shape<2>(make_container({0, 0}, {1, 1}, 3, {"y+"}), 0.1);
  EXPECT_EQ(open.size(), 108u);
  double max_y = -1, min_y = 1, min_x = 1;
  for (const auto& p : open) {
    max_y = std::max(max_y, p[1]), min_y = std::min(min_y, p[1]), min_x = std::min(min_x, p[0]);
  }
  EXPECT_NEAR(max_y, 0.95, 1e-12);   // side walls stop at the inner box top
  EXPECT_NEAR(min_y, -0.25, 1e-12);  // third layer at (2 + 0.5) dp below the floor
  EXPECT_NEAR(min_x, -0.25, 1e-12);
  // 3D, 4^3 inner, 2 layers, closed: 8^3 - 4^3 = 448; open z+: 8 x 8 x 6 - 64 = 320.
  EXPECT_EQ(fill_shape<3>(make_container({0, 0, 0}, {0.4, 0.4, 0.4}, 2), 0.1).size(), 448u);
  EXPECT_EQ(fill_shape<3>(make_container({0, 0, 0}, {0.4, 0.4, 0.4}, 2, {"z+"}), 0.1).size(), 320u);
  EXPECT_THROW(fill_shape<2>(make_container({0, 0}, {1, 1}, 3, {"z+"}), 0.1),
               std::invalid_argument);
}

TEST(SphGeometry, NoPointOfAContainerInsideItsInnerBox) {
  const auto pts = fill_shape<2>(make_container({0, 0}, {0.3, 0.2}, 4, {"x+"}), 0.01);
  for (const auto& p : pts) {
    const bool inner = p[0] > 0 && p[0] < 0.3 && p[1] > 0 && p[1] < 0.2;
    EXPECT_FALSE(inner) << p.transpose();
  }
}

TEST(SphGeometry, TriangleCountMatchesAreaWithinARow) {
  // Right triangle of area 0.5 m^2 at dp = 0.02: area / dp^2 = 1250 points, up to one row of
  // points (1 / dp = 50) more or less along the hypotenuse.
  scene::Shape tri;
  tri.kind = scene::Shape::Kind::Polygon;
  tri.vertices = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  const auto pts = fill_shape<2>(tri, 0.02);
  EXPECT_NEAR(static_cast<double>(pts.size()), 1250.0, 50.0);
  for (const auto& p : pts) EXPECT_LE(p[0] + p[1], 1.0 + 1e-12);
  EXPECT_NEAR(pts.front()[0], 0.01, 1e-12);  // anchored at the bounding box min + dp/2
}

TEST(SphGeometry, BlockSkipsPointsInsideWalls) {
  // Water box 0.2 x 0.1 with a wall box over its right half: 10 x 10 points remain.
  const auto water = make_box({0, 0}, {0.2, 0.1});
  const auto wall = make_box({0.1, -1}, {1, 1});
  EXPECT_EQ(fill_block_outside_walls<2>(water, {wall}, 0.01).size(), 100u);
  // A container around the water does not remove any water point.
  const auto tank = make_container({0, 0}, {0.2, 0.1}, 3);
  EXPECT_EQ(fill_block_outside_walls<2>(water, {tank}, 0.01).size(), 200u);
  // A water block overlapping the container's floor loses the points inside the wall layers.
  const auto deep = make_box({0, -0.03}, {0.2, 0.1});
  EXPECT_EQ(fill_block_outside_walls<2>(deep, {tank}, 0.01).size(), 200u);
}

}  // namespace
}  // namespace porosph::sph
