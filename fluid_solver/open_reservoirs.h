// Constant-head reservoirs as open boundaries (scene [[water.reservoir]] with boundary = "open"):
// the pool ends in a buffer of water particles beyond the domain's open side, at the hydrostatic
// pressure of the level, through which the water enters and leaves. Unlike the surface
// reservoirs (reservoirs.h), nothing is added or removed at the pool's surface, so the pool is
// not stirred where the flow goes.
//
// Reference: the buffer-zone open boundary of Tafuni, Dominguez, Vacondio & Crespo (2018), "A
// versatile algorithm for the treatment of open boundary conditions in Smoothed particle
// hydrodynamics GPU models", CMAME 342, 604-624: buffer particles with a prescribed pressure and a
// velocity extrapolated from the fluid (zero gradient along the normal), a fluid particle crossing
// into the buffer becomes a buffer particle, a buffer particle crossing into the fluid becomes a
// fluid particle and is replaced one buffer length behind.
//
// Here, with n the unit inward normal (`direction`, along one axis across gravity), face the box's
// face along n (the open side of the domain), s = x . up the height and s_L the level:
//  - pressure: every buffer particle below the level has p = still_water_pressure(s_L - s)
//    (equation_of_state.h), its density the inverse of eq. 4 at p (set after every step, with
//    density_previous; density_rate 0);
//  - velocity: u n with u the mean of v . n over the free water particles within 2h of the face
//    inside the domain, per face cell (rows of height dp from the box's bottom to the level, times
//    dp-wide columns across the other axes); 0 in a cell without such particles and before
//    hold_until (the damping stage). The buffer particles move by dt u n, with v = v^{n-1} = u n
//    (no acceleration);
//  - a buffer particle past the face becomes free; a cell whose hindmost buffer particle lies a
//    whole spacing or more ahead of the far face (L = N dp behind the face, N the buffer's rows
//    along n) gets one new buffer particle dp behind it, on the cell's row (an empty cell: dp/2
//    behind the face), with the hydrostatic density, mass rho dp^D, velocity u n and a fresh id
//    (booked as inflow). Refilling from the back by the cell's own content, rather than
//    replacing each particle that crosses (Tafuni et al.), keeps a particle that crosses the face
//    back and forth from multiplying: a copy per crossing filled the buffer of a pool whose
//    surface particles oscillated about the face;
//  - absorbing = true (a radiation condition of Flather 1976 type: R. A. Flather, "A tidal model of
//    the north-west European continental shelf", Mem. Soc. R. Sci. Liege 6(10), 141-164): the
//    pressure above uses the level s_L - (H / c) u_m instead of s_L, H = s_L - s_B the level's
//    depth, c = sqrt(g H) the long-wave speed and u_m the mean of u over the zone's sampled cells
//    (the depth-mean inward velocity). A long wave leaving through the face carries
//    eta = -(H / c) u . n, so the face then matches it and it does not reflect; with a fixed level
//    (eta = 0 there) it reflects whole, and a pool between a wall and the reservoir rings as a
//    quarter-wave seiche (the seepage weir's, period ~1.5 s, docs/verification.md). A steady
//    inflow u holds the pool (H / c) u below s_L, as the velocity head across a channel of that
//    impedance would; the geometry (rows, capture, removal above the level) keeps s_L;
//  - a free particle inside the box below the level becomes a buffer particle (no exchange of
//    momentum); one above the level is removed, and so is a buffer particle past the box's far
//    face (booked as outflow).
// A buffer holds lattice rows at s_B + (j + 1/2) dp (s_B the box's bottom, j = 0, 1, ...) below
// the level (the bottom on the water's lattice, the buffer's rows continue the pool's), and
// N >= 2h / dp columns along n (refused otherwise: the water next to the face needs a full kernel
// support). The zone particles carry P.zone = first_zone + r (after the inflow zones). No state
// between steps beyond the particles (nothing to checkpoint); no allocation in a step unless P
// must grow beyond its capacity.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/water_particles.h"
#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::water {

/// What an open reservoir needs beyond the scene: the solver's gravity, smoothing length and EOS.
template <int D>
struct OpenBoundaryPhysics {
  sph::Vec<D> gravity = sph::Vec<D>::Zero();
  double h = 0.0;
  TaitEos eos;
};

template <int D>
class OpenReservoirs {
 public:
  using Vec = sph::Vec<D>;

  OpenReservoirs() = default;
  /// The reservoirs of `water` with boundary "open"; their zone codes start at first_zone. Throws
  /// std::invalid_argument (naming water.reservoir[i]) on gravity not along one axis, a direction
  /// that is not a unit vector along one axis across gravity, a level outside the box, or a box
  /// thinner than 2h along the direction.
  OpenReservoirs(const scene::WaterPhase& water, const OpenBoundaryPhysics<D>& physics, double dp,
                 double hold_until, int first_zone);

  std::size_t count() const { return zones_.size(); }
  bool owns(int zone) const {
    return zone >= first_zone_ && zone < first_zone_ + static_cast<int>(zones_.size());
  }

  /// The buffer lattice of reservoir r (its rows below the level), for the initial fill.
  std::vector<Vec> buffer_lattice(int r) const;
  /// The zone code of the box that holds x below its level, or -1.
  int zone_below_level(const Vec& x) const;
  /// True if x lies inside a box, above its level (a free particle there is removed).
  bool above_level(const Vec& x) const;
  /// The level whose still-water pressure zone `zone`'s buffer carries over the prepared step.
  double pressure_level(int zone) const { return zones_[zone - first_zone_].pressure_level; }
  /// True if x lies beyond the far face of zone `zone`'s box (a buffer particle there is removed).
  bool past_far_face(int zone, const Vec& x) const;

  /// The cell velocities for the step from `time` (free water next to each face; no allocation),
  /// and the level of the imposed pressure (the level, or with absorbing its Flather shift).
  void begin_step(const WaterParticles<D>& P, double time);
  /// The velocity u n a buffer particle of zone `zone` at x has over the prepared step.
  Vec velocity_at(int zone, const Vec& x) const;
  /// Moves a buffer particle over the prepared step; returns 1 if it is now past the face.
  int move(int zone, Vec& x, Vec& v, Vec& v_previous, double dt) const {
    v = v_previous = velocity_at(zone, x);
    x += dt * v;
    return along(zones_[zone - first_zone_], x) > 0.0 ? 1 : 0;
  }
  /// Turns the free particles inside a box below its level into buffer particles, and sets every
  /// buffer particle's density to the hydrostatic one of its height (above).
  void capture_and_impose(WaterParticles<D>& P) const;
  /// Hands the buffer particles past their face to the water, and adds (into the free range, fresh
  /// ids from next_id) one buffer particle per cell where a whole spacing is free behind the
  /// cell's hindmost particle up to the far face (in an empty cell: dp/2 behind the face); adds
  /// their mass to born_mass, returns their number. Call every step.
  std::size_t renew(WaterParticles<D>& P, double volume, std::int64_t& next_id, double& born_mass);

 private:
  struct Zone {
    Vec min, max;
    Vec normal;                   ///< unit inward normal
    int axis = 0;                 ///< the normal's axis
    double face = 0.0;            ///< coordinate of the open face along `axis`
    double length = 0.0;          ///< L = N dp along the normal
    double level = 0.0;           ///< s_L (height of the level)
    double bottom = 0.0;          ///< lowest height of the box
    double impedance = 0.0;       ///< absorbing: H / sqrt(g H) [s]; 0: the level is fixed
    double pressure_level = 0.0;  ///< the level of the imposed pressure over the prepared step
    std::array<long, D> cells{};  ///< per axis: rows along up, columns across, 1 along the normal
    std::size_t first_cell = 0;
  };

  static bool inside(const Zone& z, const Vec& x) {
    return (x.array() >= z.min.array()).all() && (x.array() <= z.max.array()).all();
  }
  /// Signed distance of x past the face into the domain.
  static double along(const Zone& z, const Vec& x) {
    return z.normal[z.axis] * (x[z.axis] - z.face);
  }
  double height(const Vec& x) const { return up_sign_ * x[up_axis_]; }
  /// Cell of zone z holding x (transverse position inside the box, any position along the
  /// normal), as an index into the cell arrays; -1 above the level or below the box.
  long cell_of(const Zone& z, const Vec& x) const;
  /// cell_centres_: per zone, the centre of every cell on its row (at the face along the normal).
  void find_cell_centres();

  std::vector<Zone> zones_;
  int first_zone_ = 0;
  int up_axis_ = D - 1;
  double up_sign_ = 1.0;
  double g_ = 0.0, dp_ = 0.0, h_ = 0.0, hold_until_ = 0.0;
  TaitEos eos_;
  bool held_ = true;                   ///< inside the damping stage: every buffer at rest
  std::vector<double> cell_sum_;       ///< per cell: sum of v . n of the sampled particles
  std::vector<std::uint32_t> cell_n_;  ///< per cell: their number (renew: buffer particles)
  std::vector<double> cell_speed_;     ///< per cell: u
  std::vector<double> cell_back_;      ///< per cell: the hindmost buffer particle's signed distance
  std::vector<std::vector<Vec>> cell_centres_;
  WaterParticles<D> born_;  ///< staging of the particles renew() adds
};

extern template class OpenReservoirs<2>;
extern template class OpenReservoirs<3>;

}  // namespace porosph::water
