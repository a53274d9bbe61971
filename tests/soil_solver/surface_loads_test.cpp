// Surface loads (soil_solver/surface_loads.h): a rigid plate moves as one along its traction and
// freely across it, changes no momentum beyond the load's own impulse, and a load's material
// replaces the loaded particles' own (refused when density or porosity differ).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "soil_solver/soil_solver.h"

namespace porosph::soil {
namespace {

scene::SoilMaterial elastic(const std::string& name, double density) {
  scene::SoilMaterial m;
  m.name = name;
  m.density = density;
  m.porosity = 0.4;
  m.bulk_modulus = 1e5;
  m.shear_modulus = 1e5;
  m.young_modulus = 2.25e5;  // 9 K G / (3 K + G)
  m.poisson_ratio = 0.125;   // (3 K - 2 G) / (2 (3 K + G))
  m.friction_angle_deg = 30.0;
  m.cohesion = 1e5;  // never yields
  return m;
}

/// A free 0.1 m x 0.05 m elastic block without gravity or walls, its top row pushed down by
/// `traction` and, below it, a bottom row pushed up by the same (the plates of Mandel's problem).
scene::Scene squeezed_block(bool rigid, const std::string& plate_material) {
  scene::Scene s;
  s.run.dimension = 2;
  s.run.dp = 0.01;
  s.run.h_factor = 1.2;
  s.run.gravity = {0.0, 0.0};
  s.run.periodic = {false, false};
  s.domain.min = {-0.2, -0.2};
  s.domain.max = {0.3, 0.25};
  s.soil = scene::SoilPhase{};
  s.soil->materials = {elastic("sand", 1600.0), elastic("seal", 1600.0), elastic("heavy", 2000.0)};
  scene::Shape block;
  block.kind = scene::Shape::Kind::Box;
  block.min = {0.0, 0.0};
  block.max = {0.1, 0.05};
  block.material = "sand";
  s.soil->blocks = {block};
  for (double sign : {-1.0, 1.0}) {
    scene::SoilLoad load;
    load.min = {0.0, sign < 0 ? 0.04 : 0.0};
    load.max = {0.1, sign < 0 ? 0.05 : 0.01};
    load.traction = {0.0, sign * 2000.0};
    load.ramp_time = 2e-3;
    load.rigid = rigid;
    load.material = plate_material;
    s.soil->loads.push_back(load);
  }
  return s;
}

TEST(SurfaceLoads, ARigidPlateMovesAsOneAlongItsAxisAndFreelyAcrossIt) {
  for (bool rigid : {false, true}) {
    SoilSolver<2> solver(squeezed_block(rigid, ""));
    const SoilParticles<2>& P = solver.particles();
    for (int n = 0; n < 300; ++n) {
      solver.compute_rates();
      solver.advance(std::min(2e-5, solver.dt_limits().min()));
    }
    double top_min = 1e9, top_max = -1e9, across_min = 1e9, across_max = -1e9;
    double momentum_y = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < P.n_free; ++i) {
      momentum_y += P.mass[i] * P.velocity[i][1];
      scale += P.mass[i] * std::abs(P.velocity[i][1]);
      if (P.load[i] != 0) continue;  // the top plate
      top_min = std::min(top_min, P.velocity[i][1]);
      top_max = std::max(top_max, P.velocity[i][1]);
      across_min = std::min(across_min, P.velocity[i][0]);
      across_max = std::max(across_max, P.velocity[i][0]);
    }
    std::printf("rigid %d: top v_y %.6g .. %.6g, v_x %.6g .. %.6g, momentum %.3g of %.3g\n", rigid,
                top_min, top_max, across_min, across_max, momentum_y, scale);
    ASSERT_GT(std::abs(top_min), 1e-3);  // it moves (the block rings under the ramped load)
    if (rigid) {
      // One velocity along the axis, to round-off.
      EXPECT_LE(top_max - top_min, 1e-14 * std::abs(top_min));
    } else {
      // Without the constraint the loaded row bends (its ends, next to the free sides, move
      // faster): the test can tell the two apart.
      EXPECT_GT(top_max - top_min, 1e-3 * std::abs(top_min));
    }
    // Free across: the plate spreads with the block (Poisson), its ends in opposite directions.
    EXPECT_LT(across_min, 0.0);
    EXPECT_GT(across_max, 0.0);
    // Equal and opposite loads, internal constraint forces: no net momentum (round-off).
    EXPECT_LT(std::abs(momentum_y), 1e-12 * scale);
  }
}

TEST(SurfaceLoads, ALoadsMaterialReplacesTheLoadedParticlesOwn) {
  SoilSolver<2> solver(squeezed_block(true, "seal"));
  const SoilParticles<2>& P = solver.particles();
  int sealed = 0, plain = 0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    if (P.load[i] >= 0) {
      EXPECT_EQ(P.material[i], 1);
      ++sealed;
    } else {
      EXPECT_EQ(P.material[i], 0);
      ++plain;
    }
  }
  EXPECT_EQ(sealed, 20);  // the top and bottom rows, 10 particles each
  EXPECT_EQ(plain, 30);
  try {
    SoilSolver<2> heavy(squeezed_block(true, "heavy"));
    FAIL() << "a load material of another density was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("soil.loads[0].material 'heavy'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace porosph::soil
