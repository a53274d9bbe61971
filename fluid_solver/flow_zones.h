// Water inflow and outflow zones (scene [[water.inflow]], [[water.outflow]]; docs/design.md section
// 3, "Boundaries").
//
// Inflow zone: a box whose water particles ("zone particles", WaterParticles::zone = the zone's
// index) follow the prescribed velocity u(t) = speed(t) e instead of their equation of motion
// (e: the unit direction, along one axis). They stay in the free range, so they interact with
// everything, and their density follows the continuity equation as usual: the zone pushes the
// water downstream through the pressure. Their accelerations (internal and interaction) are not
// used, nor counted in the eq. 21 limit (water_rates.cpp). Over a step [t, t + dt] a zone particle
// does
//   x += dt u(t + dt/2)                    (the exact integral of u for the linear ramp)
//   v^{n-1} = u(t),  v^{n+1} = u(t + dt)   (the two Verlet levels a free particle needs)
// A zone particle past the downstream face (the face along e; or, where the zone's rows reach
// past it, the lattice's end L from the upstream face, L below) becomes a free particle with these
// velocities, and a new zone particle is born at x - L e with the crossing particle's density,
// pressure, mass m = rho dp^D and a fresh id. L = N dp, N the number of lattice rows of the zone
// along e (the zone's length when that is a multiple of dp), so the zone keeps its lattice and
// emits one row of mass rho dp^D per column every dp / speed: a mass flux rho speed A, A the
// zone's cross-section (columns x dp^(D-1)). Requires speed dt < L (always true under the CFL
// limit). Zones must not straddle a periodic face.
//
// Outflow zone: free water particles inside the box [min, max] are removed (zone particles never
// are). With water.outflow[].stagger = S > 0, particle id k is removed only once its centre is
// frac(k / golden ratio) S dp above the box's lower face along gravity, so that a water surface
// rising into the box as one lattice row leaves one particle at a time: removing a whole row at
// once drops the head of the water below by rho g dp in one step, a pressure pulse. Inflow speeds
// are 0 during the damping stage (t < hold_until, sph/damping_stage.h), whatever the ramp says.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid_solver/water_particles.h"
#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
class FlowZones {
 public:
  using Vec = sph::Vec<D>;

  FlowZones() = default;
  /// From water.inflows / water.outflows; dp is the lattice spacing, h the smoothing length;
  /// hold_until the end of the damping stage (0: none). Throws std::invalid_argument on vectors of
  /// the wrong length, an empty box, a direction that is not a unit vector along one axis, or an
  /// inflow zone shorter along it than the kernel support 2h: the water just downstream must see
  /// a full kernel of zone particles behind it (a 1.3 dp zone let the fluidised bed drain).
  /// gravity: the outflows' stagger acts along its axis (needed only where a stagger is set).
  FlowZones(const scene::WaterPhase& water, double dp, double h, const Vec& gravity,
            double hold_until);

  std::size_t inflow_count() const { return inflows_.size(); }
  bool has_outflows() const { return !outflows_.empty(); }

  /// The box of inflow zone z as a shape, to fill with the water lattice at t = 0.
  scene::Shape inflow_box(int z) const;
  /// Index of the inflow zone whose closed box holds x, or -1.
  int inflow_at(const Vec& x) const {
    for (std::size_t z = 0; z < inflows_.size(); ++z)
      if (inside(inflows_[z].box, x)) return static_cast<int>(z);
    return -1;
  }
  /// True when x lies in the closed box of an outflow zone that is active at `time` (its
  /// start_time reached) and, where the zone has a stagger, the particle `id` is past its own
  /// threshold above the box's lower face.
  bool in_outflow(const Vec& x, std::int64_t id, double time) const {
    for (std::size_t z = 0; z < outflows_.size(); ++z)
      if (time >= outflow_start_[z] && inside(outflows_[z], x) && outflow_stagger_[z].past(x, id))
        return true;
    return false;
  }

  /// Prescribed speed of zone z at `time`: 0 before hold_until, else the scene's ramp.
  double speed(int z, double time) const;
  /// Prescribed velocity speed(z, time) e of zone z.
  Vec velocity(int z, double time) const { return speed(z, time) * inflows_[z].direction; }

  /// Prepares the velocities of every zone for the step [time, time + dt] (no allocation).
  void begin_step(double time, double dt);
  /// The velocity u(time + dt) zone z's particles have after the prepared step.
  const Vec& end_velocity(int z) const { return step_[z].end; }
  /// Moves a particle of zone z over the prepared step (see above); returns 1 if it is now past
  /// the zone's downstream face, else 0.
  int move(int z, Vec& x, Vec& v, Vec& v_previous, double dt) const {
    x += dt * step_[z].middle;
    v_previous = step_[z].start;
    v = step_[z].end;
    return past_downstream(z, x) ? 1 : 0;
  }
  /// Turns every zone particle past its downstream face into a free particle and inserts its
  /// replacement (fresh ids from next_id, which advances) into the free range. volume = dp^D.
  /// Returns the number of particles born and adds their mass to `born_mass`. Allocates only when
  /// P must grow beyond its capacity (it then reserves one zone-load ahead).
  std::size_t renew(WaterParticles<D>& P, double volume, std::int64_t& next_id, double& born_mass);

 private:
  struct Box {
    Vec min, max;
  };
  struct Inflow {
    Box box;
    Vec direction;              ///< unit, along `axis`
    int axis = 0;               ///< the flow axis
    double downstream = 0.0;    ///< coordinate of the downstream face along `axis`
    double lattice_length = 0;  ///< L = N dp
    scene::InflowZone ramp;     ///< speed_at(t)
  };
  struct StepVelocities {
    Vec start, middle, end;  ///< u(t), u(t + dt/2), u(t + dt)
  };

  static bool inside(const Box& b, const Vec& x) {
    return (x.array() >= b.min.array()).all() && (x.array() <= b.max.array()).all();
  }
  bool past_downstream(int z, const Vec& x) const {
    const Inflow& f = inflows_[z];
    return f.direction[f.axis] * (x[f.axis] - f.downstream) > 0.0;
  }

  std::vector<Inflow> inflows_;
  std::vector<Box> outflows_;
  std::vector<double> outflow_start_;  ///< per outflow zone: start_time [s]
  /// water.outflow[].stagger: particle `id` leaves once it is s(id) depth above the lower face.
  struct Stagger {
    int axis = 0;
    double up = 1.0;     ///< +1: gravity along -axis
    double face = 0.0;   ///< up x[axis] of the lower face
    double depth = 0.0;  ///< stagger dp [m]; 0: none
    bool past(const Vec& x, std::int64_t id) const {
      if (depth == 0.0) return true;
      // s(id) = frac(id / golden ratio): evenly spread over [0, 1) for any run of ids.
      const double s = std::fmod(static_cast<double>(id) * 0.6180339887498949, 1.0);
      return up * x[axis] - face >= s * depth;
    }
  };
  std::vector<Stagger> outflow_stagger_;
  double hold_until_ = 0.0;
  std::vector<StepVelocities> step_;
  WaterParticles<D> born_;  ///< staging of the particles born in renew()
};

extern template class FlowZones<2>;
extern template class FlowZones<3>;

}  // namespace porosph::water
