// The scalars of a particle solver's state that survive a step and that every particle solver has
// (time, step, the dt limits of its latest rates, removal counters, the interaction and wall
// bookkeeping), with their checkpoint names (docs/checkpoints.md). A solver keeps its own further
// scalars (the water's inflow counters, the soil's saturation flag) next to them.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "io/checkpoint_file.h"
#include "sph/time_step_limits.h"

namespace porosph::sph {

struct SolverScalars {
  double time = 0.0;       ///< simulated time [s]
  std::uint64_t step = 0;  ///< steps taken
  /// Of the latest rates: the state after a checkpoint is reported before its own rates are
  /// computed (proto/solver_runtime.h), with these limits.
  DtLimits limits;
  double neighbours_per_particle = 0.0;  ///< of the latest neighbour list (free particles)
  std::uint64_t removed_count = 0;       ///< particles removed so far
  double outflow_mass = 0.0;             ///< their mass [kg]
  bool interaction_nonzero = false;      ///< the particles' interaction may hold non-zero values
  double next_wall_removal = -1.0;       ///< earliest pending wall removal time (< 0: none)

  /// Stores them (and the dimension D) in a solver checkpoint.
  void write(io::CheckpointWriter& out, int dimension) const {
    out.set("dimension", static_cast<std::int64_t>(dimension));
    out.set("time", time);
    out.set("dt_cfl", limits.cfl);
    out.set("dt_viscous", limits.viscous);
    out.set("dt_force", limits.force);
    out.set("neighbours_per_particle", neighbours_per_particle);
    out.set("step", static_cast<std::int64_t>(step));
    out.set("removed_count", static_cast<std::int64_t>(removed_count));
    out.set("outflow_mass", outflow_mass);
    out.set("interaction_nonzero", static_cast<std::int64_t>(interaction_nonzero));
    out.set("next_wall_removal", next_wall_removal);
  }

  /// Reads them back; throws std::runtime_error for a checkpoint of another dimension.
  void read(const io::CheckpointReader& in, int dimension) {
    if (in.get_i64("dimension") != dimension)
      throw std::runtime_error(in.path() + ": a checkpoint of a run in another dimension");
    time = in.get_f64("time");
    limits.cfl = in.get_f64("dt_cfl");
    limits.viscous = in.get_f64("dt_viscous");
    limits.force = in.get_f64("dt_force");
    neighbours_per_particle = in.get_f64("neighbours_per_particle");
    step = static_cast<std::uint64_t>(in.get_i64("step"));
    removed_count = static_cast<std::uint64_t>(in.get_i64("removed_count"));
    outflow_mass = in.get_f64("outflow_mass");
    interaction_nonzero = in.get_i64("interaction_nonzero") != 0;
    next_wall_removal = in.get_f64("next_wall_removal");
  }
};

}  // namespace porosph::sph
