// Constant-head reservoirs (scene [[water.reservoir]]): boxes in which the water surface is held
// at a given level (a dam's reservoir, a river, a pit kept dry by pumping).
//
// Heights s = x . up, up = -g/|g| along one axis; the target is s_L, the level's height. Each step
// (after the move and the removal of the water that left):
//  - removal: a free water particle inside an active zone's box with s > s_L leaves the water
//    (WaterSolver::leaves, booked as outflow like an outflow zone's);
//  - refill (refill()): the box is split into lattice columns across up (spacing dp, anchored at
//    the box's min); in every column whose highest free particle inside the box lies below
//    s_L - dp, one particle is added dp above that particle (in an empty column at the box's
//    bottom + dp/2), with that particle's velocities (at rest in an empty column), the
//    hydrostatic pressure p = rho0 |g| (s_L - s) and density rho = inverse eq. 4 at p, mass
//    m = rho dp^D and a fresh id; booked as inflow. A candidate closer than kClearance dp to any
//    particle (water, wall, or a candidate accepted before it), or inside the water (kMaxFill),
//    waits for a later step.
// So the column tops stay within [s_L - dp, s_L]: the surface (tops + dp/2) within dp/2 of the
// level, and the water exchanged is in the mass ledger (inflow / outflow), so mass balances.
// A zone adds at most one particle per column per step (the CFL limit moves the water by well
// under dp per step). No allocation in a step unless the particle arrays must grow beyond their
// capacity. The zones hold no state between steps beyond the particles (nothing to checkpoint).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/water_particles.h"
#include "scene/scene.h"
#include "sph/kernels.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
class Reservoirs {
 public:
  using Vec = sph::Vec<D>;
  /// Smallest distance of an added particle to any other, in particle spacings.
  static constexpr double kClearance = 0.5;
  /// Largest volume fraction sum_b dp^D W(x - x_b) of the particles around an added particle: a
  /// point one row above a flat lattice surface has 0.22, a point of the surface row 0.47 and one
  /// inside the water 0.68 (cubic spline, h = 1.2 dp), so a candidate inside the water (where a
  /// column's top is low only because the particles above it drifted out of the box sideways) is
  /// not added.
  static constexpr double kMaxFill = 0.45;

  Reservoirs() = default;
  /// From water.reservoirs. Throws std::invalid_argument on vectors of the wrong length, an
  /// empty box, gravity not along one axis, or a level outside the box along it.
  Reservoirs(const scene::WaterPhase& water, const Vec& gravity, double dp, double h,
             const TaitEos& eos);

  std::size_t count() const { return zones_.size(); }
  /// The number of lattice columns of all zones (the most particles one refill() adds).
  std::size_t column_count() const { return top_index_.size(); }

  /// True if a free water particle at x is to be removed: inside the box of a zone active at
  /// `time`, above its level.
  bool above_level(const Vec& x, double time) const {
    for (const Zone& z : zones_)
      if (time >= z.start_time && inside(z, x) && height(x) > z.level) return true;
    return false;
  }

  /// Adds the particles described above to the free range of P (fresh ids from next_id, which
  /// advances); adds their mass to born_mass and returns how many were added.
  std::size_t refill(WaterParticles<D>& P, double time, std::int64_t& next_id, double& born_mass);

  /// Surface of each column of zone z (highest free particle in the box + dp/2; NaN for an empty
  /// column), as a coordinate along the gravity axis. For tests and tools (allocates).
  std::vector<double> column_surfaces(int z, const WaterParticles<D>& P) const;

 private:
  struct Zone {
    Vec min, max;
    double level = 0.0;   ///< s_L
    double bottom = 0.0;  ///< lowest height of the box
    double start_time = 0.0;
    std::array<long, D> columns{};  ///< per axis; 1 along `axis_`
    std::size_t first_column = 0;   ///< offset into the column arrays
    std::size_t column_total = 1;
  };
  struct Candidate {
    Vec x;
    std::int64_t source;  ///< particle whose velocities it takes; -1: at rest
    double level;         ///< s_L of its zone
  };

  static bool inside(const Zone& z, const Vec& x) {
    return (x.array() >= z.min.array()).all() && (x.array() <= z.max.array()).all();
  }
  double height(const Vec& x) const { return sign_ * x[axis_]; }
  /// Column of zone z holding x (inside the box), as an index into the column arrays.
  std::size_t column_of(const Zone& z, const Vec& x) const;
  /// Centre of column c of zone z across up, at height s.
  Vec column_point(const Zone& z, std::size_t c, double s) const;
  /// Highest free particle of every column of the active zones (top_index_, top_height_).
  void find_column_tops(const WaterParticles<D>& P, double time);
  /// Drops the candidates closer than kClearance dp to a particle of P or an earlier accepted
  /// candidate, or where those fill more than kMaxFill of the volume (cubic spline of support 2h).
  void keep_clear_candidates(const WaterParticles<D>& P);

  std::vector<Zone> zones_;
  int axis_ = D - 1;   ///< the gravity axis
  double sign_ = 1.0;  ///< up = sign_ e_axis
  double g_ = 0.0, dp_ = 0.0;
  TaitEos eos_;
  sph::CubicSpline<D> kernel_{1.0};
  std::vector<double> fill_;             ///< per candidate: sum_b dp^D W
  std::vector<std::int64_t> top_index_;  ///< per column: highest free particle, -1: none
  std::vector<double> top_height_;
  std::vector<Candidate> candidates_;
  std::vector<std::uint8_t> clear_;
  WaterParticles<D> born_;  ///< staging of the added particles
};

extern template class Reservoirs<2>;
extern template class Reservoirs<3>;

}  // namespace porosph::water
