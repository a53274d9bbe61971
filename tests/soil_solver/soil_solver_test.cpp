// The soil solver class on small scenes built in code: particle set-up from blocks and walls,
// geostatic initial stress, momentum conservation of the pair terms, equilibrium of a geostatic
// column against its walls, a gate removed on time, the damping stage, non-finite detection and
// the snapshot fields.
#include "soil_solver/soil_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

namespace porosph::soil {
namespace {

scene::Shape box(std::vector<double> lo, std::vector<double> hi, std::string material = "") {
  scene::Shape s;
  s.kind = scene::Shape::Kind::Box;
  s.min = std::move(lo);
  s.max = std::move(hi);
  s.material = std::move(material);
  return s;
}

scene::Shape container(std::vector<double> lo, std::vector<double> hi, int layers) {
  scene::Shape s = box(std::move(lo), std::move(hi));
  s.kind = scene::Shape::Kind::Container;
  s.layers = layers;
  s.open_faces = {"y+"};
  return s;
}

scene::SoilMaterial material(const std::string& name, double rho, double phi, bool fixed = false) {
  scene::SoilMaterial m;
  m.name = name;
  m.density = rho;
  m.young_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.bulk_modulus = 1e7 / (3 * 0.4);
  m.shear_modulus = 1e7 / 2.6;
  m.friction_angle_deg = phi;
  m.fixed = fixed;
  return m;
}

/// 2D soil scene, g = -9.81 y, dp 0.01, h 1.2 dp, one material "sand" (rho 1800, phi 30).
scene::Scene soil_scene(std::vector<double> domain_min, std::vector<double> domain_max) {
  scene::Scene s;
  s.run.dimension = 2;
  s.run.dp = 0.01;
  s.run.h_factor = 1.2;
  s.run.gravity = {0.0, -9.81};
  s.run.periodic = {false, false};
  s.domain.min = std::move(domain_min);
  s.domain.max = std::move(domain_max);
  s.soil = scene::SoilPhase{};
  s.soil->materials.push_back(material("sand", 1800.0, 30.0));
  return s;
}

TEST(SoilSolver, ParticlesFromBlocksWallsAndFixedMaterial) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->materials.push_back(material("bed", 2000.0, 35.0, /*fixed=*/true));
  s.soil->blocks = {box({0.0, 0.05}, {0.2, 0.15}, "sand"), box({0.0, 0.0}, {0.2, 0.1}, "bed")};
  s.walls = {container({0.0, 0.0}, {0.2, 0.3}, 2)};
  scene::Shape water_only = box({0.3, 0.0}, {0.4, 0.1});
  water_only.phases = {"water"};  // does not exist for the soil
  s.walls.push_back(water_only);
  SoilSolver<2> solver(s);
  const auto& P = solver.particles();
  // Sand: 20 x 10 lattice points; the bed block loses its upper half (0.05-0.1) to the earlier
  // sand block: 20 x 5 fixed points. Container: 2 layers around 0.2 x 0.3 open at the top:
  // bottom 2 x (20 + 4), sides 2 x 2 x 30.
  EXPECT_EQ(solver.free_count(), 200u);
  EXPECT_EQ(solver.particle_count(), 200u + 100u + 48u + 120u);
  std::size_t bed = 0;
  for (std::size_t i = P.n_free; i < P.size(); ++i) bed += P.material[i] == 1;
  EXPECT_EQ(bed, 100u);
  for (std::size_t i = 0; i < P.n_free; ++i) {
    EXPECT_EQ(P.material[i], 0);
    EXPECT_EQ(P.mass[i], 1800.0 * 1e-4);
    EXPECT_EQ(P.porosity[i], 0.4);  // the scene default n0
  }
}

TEST(SoilSolver, GeostaticInitialStressFollowsTheWeightOfTheLayersAbove) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->materials.push_back(material("clay", 1500.0, 20.0));
  s.soil->initial_stress = "geostatic";  // k0 = "jaky"
  s.soil->blocks = {box({0.0, 0.1}, {0.1, 0.2}, "clay"), box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  SoilSolver<2> solver(s);
  const auto& P = solver.particles();
  for (std::size_t i = 0; i < P.n_free; ++i) {
    const double y = P.position[i].y();
    // Depth below the top (0.2): the clay above weighs 1500 g per metre, the sand 1800 g.
    const double expected =
        y > 0.1 ? -9.81 * 1500.0 * (0.2 - y) : -9.81 * (1500.0 * 0.1 + 1800.0 * (0.1 - y));
    EXPECT_NEAR(P.stress[i](1, 1), expected, 1e-9 * std::abs(expected)) << "y = " << y;
    const double k0 = 1.0 - std::sin((y > 0.1 ? 20.0 : 30.0) * M_PI / 180.0);
    EXPECT_NEAR(P.stress[i](0, 0), k0 * expected, 1e-9 * std::abs(expected));
    EXPECT_NEAR(P.stress[i](2, 2), k0 * expected, 1e-9 * std::abs(expected));  // plane strain
    EXPECT_EQ(P.stress[i](0, 1), 0.0);
  }
}

TEST(SoilSolver, PairTermsConserveMomentumOfAFreeBlock) {
  // No gravity, no walls: every pair term (stress divergence, artificial viscosity, artificial
  // stress) is antisymmetric, so the total momentum keeps its initial value to round-off while
  // the particles exchange momentum (~ the random initial momentum scale).
  scene::Scene s = soil_scene({-1, -1}, {1, 1});
  s.run.gravity = {0.0, 0.0};
  s.soil->materials[0].artificial_stress = true;
  s.soil->materials[0].cohesion = 1e4;
  s.soil->blocks = {box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  SoilSolver<2> solver(s);
  auto& P = solver.mutable_particles();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  double scale = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    P.velocity[i] = sph::Vec<2>(u(rng), u(rng));
    scale += P.mass[i] * P.velocity[i].norm();
  }
  auto momentum = [&] {
    sph::Vec<2> m = sph::Vec<2>::Zero();
    for (std::size_t i = 0; i < P.n_free; ++i) m += P.mass[i] * P.velocity[i];
    return m;
  };
  const sph::Vec<2> initial = momentum();
  double max_change = 0.0;
  for (int step = 0; step < 50; ++step) {
    solver.compute_rates();
    solver.advance(std::min(1e-5, solver.dt_limits().min()));
    max_change = std::max(max_change, (momentum() - initial).norm());
  }
  EXPECT_LT(max_change, 1e-12 * scale);
  // The particles did interact: the momentum of individual particles changed.
  EXPECT_GT(P.stress[P.n_free / 2].norm(), 0.0);
}

TEST(SoilSolver, GeostaticColumnInAContainerIsInEquilibrium) {
  // A geostatic column (K0 = nu / (1 - nu), the elastic at-rest state) between free-slip walls:
  // the stress divergence balances gravity. Away from the free surface (the top two rows, where
  // the kernel is truncated) the net acceleration is a small fraction of g; 5 % allows for the
  // discrete kernel sums on the lattice (the consistency error of sum_j V_j grad W).
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.3, 0.6});
  s.soil->initial_stress = "geostatic";
  s.soil->k0 = "elastic";
  s.soil->wall_condition = "free_slip";
  s.soil->blocks = {box({0.0, 0.0}, {0.2, 0.4}, "sand")};
  s.walls = {container({0.0, 0.0}, {0.2, 0.5}, 3)};
  SoilSolver<2> solver(s);
  solver.compute_rates();
  const auto& P = solver.particles();
  double worst = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    if (P.position[i].y() > 0.38) continue;
    worst = std::max(worst, P.acceleration[i].norm() / 9.81);
    if (P.acceleration[i].norm() > 0.04 * 9.81)
      std::printf("x %g %g a %g %g\n", P.position[i].x(), P.position[i].y(), P.acceleration[i].x(),
                  P.acceleration[i].y());
  }
  EXPECT_LT(worst, 0.05);
}

TEST(SoilSolver, GateIsRemovedAtItsTime) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->blocks = {box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  scene::Shape gate = box({0.1, 0.0}, {0.13, 0.12});
  gate.remove_at = 0.002;
  s.walls = {box({-0.03, -0.03}, {0.4, 0.0}), gate};
  SoilSolver<2> solver(s);
  const std::size_t with_gate = solver.particle_count();
  while (solver.time() < 0.0019) {
    solver.compute_rates();
    solver.advance(1e-4);
  }
  EXPECT_EQ(solver.particle_count(), with_gate);
  while (solver.time() < 0.0021) {
    solver.compute_rates();
    solver.advance(1e-4);
  }
  EXPECT_EQ(solver.particle_count(), with_gate - 3u * 12u);  // 3 x 12 gate particles
}

TEST(SoilSolver, DampingStageEndsWithVelocitiesZeroed) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->damping_duration = 0.001;
  s.soil->blocks = {box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  s.walls = {box({-0.03, -0.03}, {0.4, 0.0})};
  SoilSolver<2> solver(s);
  double speed_during = 0.0;
  while (solver.time() < 0.001 - 1e-12) {
    solver.compute_rates();
    solver.advance(1e-4);
    for (std::size_t i = 0; i < solver.free_count(); ++i)
      speed_during = std::max(speed_during, solver.particles().velocity[i].norm());
  }
  EXPECT_GT(speed_during, 0.0);  // the stress-free column was settling
  for (std::size_t i = 0; i < solver.free_count(); ++i)
    EXPECT_EQ(solver.particles().velocity[i].norm(), 0.0);
}

TEST(SoilSolver, NonFiniteStressIsReportedWithTheParticleId) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->blocks = {box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  SoilSolver<2> solver(s);
  EXPECT_FALSE(solver.find_non_finite(nullptr).has_value());
  auto& P = solver.mutable_particles();
  P.stress[17](0, 1) = std::nan("");
  std::int64_t id = -1;
  const auto message = solver.find_non_finite(&id);
  ASSERT_TRUE(message.has_value());
  EXPECT_EQ(id, P.id[17]);
  EXPECT_NE(message->find("non-finite stress of soil particle"), std::string::npos) << *message;
}

TEST(SoilSolver, SnapshotFieldsHaveThePinnedNamesAndShapes) {
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->blocks = {box({0.0, 0.0}, {0.1, 0.1}, "sand")};
  s.walls = {box({-0.03, -0.03}, {0.4, 0.0})};
  SoilSolver<2> solver(s);
  std::set<std::string> names;
  for (const auto& f : solver.snapshot_fields()) {
    names.insert(f.name);
    EXPECT_EQ(f.rows, solver.particle_count()) << f.name;
    if (f.name == "stress") {
      EXPECT_EQ(f.cols, 9u);
    }
    if (f.name == "position" || f.name == "velocity" || f.name == "displacement") {
      EXPECT_EQ(f.cols, 2u);
    }
  }
  EXPECT_EQ(names, (std::set<std::string>{"position", "velocity", "density", "stress", "porosity",
                                          "plastic_strain", "displacement", "saturation", "id",
                                          "material", "fixed"}));
}

TEST(SoilSolver, SaturationSetsTheSubmergedWeightAndTheStickyWetFlag) {
  // Water rho 1000; sand rho_dry 1800, n0 0.4 -> rho_sat = 1800 + 0.4 * 1000 = 2200 when not given:
  // submerged ratio (2200 - 1000) / 1800. A fixed-soil bed is part of the overlap set (it exchanges
  // drag) but ignores accelerations.
  scene::Scene s = soil_scene({-1, -1}, {1, 1});
  s.water = scene::WaterPhase{};
  s.soil->materials[0].cohesion = 2e3;
  s.soil->materials[0].wet_cohesion_loss = true;
  s.soil->materials.push_back(material("bed", 2000.0, 35.0, /*fixed=*/true));
  s.soil->materials.back().saturated_density = 2100.0;
  s.soil->blocks = {box({0.0, 0.1}, {0.1, 0.2}, "sand"), box({0.0, 0.0}, {0.1, 0.1}, "bed")};
  SoilSolver<2> solver(s);
  coupling::StepState state;
  solver.fill_state(state, {-1.0, -1.0}, {1.0, 1.0});
  ASSERT_EQ(state.overlap_id.size(), 200u);  // 100 free sand + 100 fixed bed
  std::vector<double> saturation(200, 0.0);
  for (std::size_t k = 0; k < 200; ++k) saturation[k] = k % 3 == 0 ? 0.9 : (k % 3 == 1 ? 0.5 : 0.0);
  solver.set_saturation(saturation);
  const auto& P = solver.particles();
  std::size_t submerged = 0, wet = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.material[i] < 0) continue;
    const double ratio = P.material[i] == 0 ? 1200.0 / 1800.0 : 1100.0 / 2000.0;
    if (P.saturation[i] >= 0.8) {
      EXPECT_NEAR(P.weight_ratio[i], ratio, 1e-15);
      ++submerged;
    } else {
      EXPECT_EQ(P.weight_ratio[i], 1.0);
    }
    wet += P.wet[i];
  }
  EXPECT_EQ(submerged, 67u);  // k = 0, 3, ..., 198
  EXPECT_EQ(wet, 134u);       // saturation >= 0.1
  // Away from the water again: dry weight, but wet stays wet.
  solver.fill_state(state, {-1.0, -1.0}, {1.0, 1.0});
  solver.set_saturation({});
  std::size_t still_wet = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_EQ(P.weight_ratio[i], 1.0);
    still_wet += P.wet[i];
  }
  EXPECT_EQ(still_wet, 134u);
  // The bed's share of an interaction is ignored.
  std::vector<double> acceleration(400, 1.0);
  solver.add_interaction(acceleration);
  for (std::size_t i = P.n_free; i < P.size(); ++i) EXPECT_EQ(P.interaction[i].norm(), 0.0);
  for (std::size_t i = 0; i < P.n_free; ++i) EXPECT_EQ(P.interaction[i], sph::Vec<2>(1.0, 1.0));
}

TEST(SoilSolver, AThinWallPartsTheSoilOnItsTwoSides) {
  // A one-layer wall x in [0.2, 0.21] through a sand bed in a container (soil.thin_walls =
  // "separating", sph/wall_occluders.h): each side gets two tagged layers whose normal points
  // into it, and after a search no pair of the lists crosses the wall's mid-plane x = 0.205
  // (the wall's foot on the floor included). With "shared" pairs cross it.
  for (const std::string mode : {"separating", "shared"}) {
    scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
    s.soil->thin_walls = mode;
    s.soil->blocks = {box({0.0, 0.0}, {0.4, 0.1}, "sand")};
    s.walls = {box({0.2, 0.0}, {0.21, 0.3}), container({0.0, 0.0}, {0.4, 0.3}, 3)};
    SoilSolver<2> solver(s);
    solver.compute_rates();
    const auto& P = solver.particles();
    const auto& list = solver.neighbours();
    std::size_t tagged = 0, crossing = 0;
    for (std::size_t a = 0; a < P.size(); ++a) {
      if (P.wall_side[a] != 0) {
        ++tagged;
        EXPECT_EQ(P.wall_normal[a], sph::Vec<2>(P.wall_side[a] > 0 ? 1.0 : -1.0, 0.0));
      }
      const double xa = P.position[a][0];
      for (auto it = list.begin(a); it != list.end(a); ++it) {
        const double xb = xa - it->x_ab[0];  // a tagged particle on the plane counts as its side
        const double side_a = P.wall_side[a] != 0 ? P.wall_side[a] : xa - 0.205;
        const double side_b = P.wall_side[it->b] != 0 ? P.wall_side[it->b] : xb - 0.205;
        crossing += (side_a >= 0) != (side_b >= 0);
      }
    }
    if (mode == "separating") {
      EXPECT_EQ(tagged, 2u * 2u * 30u);  // 2 sides x 2 layers x 30 rows
      EXPECT_EQ(crossing, 0u);
    } else {
      EXPECT_EQ(tagged, 0u);
      EXPECT_GT(crossing, 100u);
    }
  }
}

TEST(SoilSolver, EveryLayerOfAStraightWallKnowsItsAxis) {
  // A container of three layers around a sand bed (dp 10 mm). Each layer of its side wall, the
  // middle one too (open at the same distance on both faces), has its normal along x, and lies
  // inside a straight stretch at mid-height (straight_walls.h); a corner particle has none. Before
  // 2026-12-06 the middle layer counted as a corner: not mirrored, it passed the soil's shear to
  // the frictionless wall (docs/validation-studies.md, soil_column).
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->blocks = {box({0.0, 0.0}, {0.4, 0.1}, "sand")};
  s.walls = {container({0.0, 0.0}, {0.4, 0.3}, 3)};
  SoilSolver<2> solver(s);
  const auto& P = solver.particles();
  int side_layers = 0, corners = 0;
  for (std::size_t w = P.n_free; w < P.size(); ++w) {
    const sph::Vec<2>& x = P.position[w];
    if (x[0] < 0.0 && std::abs(x[1] - 0.155) < 1e-9) {
      ++side_layers;
      EXPECT_EQ(std::abs(P.wall_normal[w][0]), 1.0) << "layer at x = " << x[0];
      EXPECT_EQ(P.wall_normal[w][1], 0.0);
      EXPECT_EQ(P.straight_wall[w], 1) << "layer at x = " << x[0];
    }
    if (x[0] < 0.0 && x[1] < 0.0) {
      ++corners;
      EXPECT_EQ(P.straight_wall[w], 0);
    }
  }
  EXPECT_EQ(side_layers, 3);
  EXPECT_EQ(corners, 9);
}

TEST(SoilSolver, AParticleCarriedAcrossAThinWallStopsTheRunNamingIt) {
  // The thin wall of the test above; the free particle next to its left face, thrown at it at
  // 20 m/s for one 1 ms step, lands 2 cm on: past the mid-plane x = 0.205. The solver reports it
  // as a bad state (proto/solver_runtime.h stops the run with the message), naming the particle.
  scene::Scene s = soil_scene({-0.1, -0.1}, {0.5, 0.5});
  s.soil->blocks = {box({0.0, 0.0}, {0.4, 0.1}, "sand")};
  s.walls = {box({0.2, 0.0}, {0.21, 0.3}), container({0.0, 0.0}, {0.4, 0.3}, 3)};
  SoilSolver<2> solver(s);
  solver.compute_rates();
  EXPECT_FALSE(solver.find_non_finite(nullptr).has_value());
  auto& P = solver.mutable_particles();
  std::size_t thrown = P.n_free;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    if (std::abs(P.position[i][0] - 0.195) < 1e-9 && std::abs(P.position[i][1] - 0.055) < 1e-9)
      thrown = i;
  }
  ASSERT_LT(thrown, P.n_free);
  const std::int64_t thrown_id = P.id[thrown];
  P.velocity[thrown] = sph::Vec<2>(20.0, 0.0);
  solver.advance(1e-3);
  std::int64_t id = -1;
  const auto message = solver.find_non_finite(&id);
  ASSERT_TRUE(message.has_value());
  EXPECT_EQ(id, thrown_id);
  EXPECT_NE(message->find("soil particle " + std::to_string(thrown_id) +
                          " crossed the thin wall at x0 = 0.205"),
            std::string::npos)
      << *message;
}

}  // namespace
}  // namespace porosph::soil
