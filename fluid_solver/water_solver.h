// The water phase solver (weakly compressible SPH, seed paper eq. 2-4 and 21): owns the water and
// wall particles, computes the internal accelerations, reports its state to the coupler and
// integrates with the shared dt. The coupling loop (proto/solver_runtime.h) drives it:
//   fill_state(state, ...); <send>; compute_rates(); <receive>; add_interaction(a); advance(dt);
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fluid_solver/flow_zones.h"
#include "fluid_solver/moving_walls.h"
#include "fluid_solver/open_reservoirs.h"
#include "fluid_solver/particle_shifting.h"
#include "fluid_solver/pore_fields.h"
#include "fluid_solver/reservoirs.h"
#include "fluid_solver/water_impulse_book.h"
#include "fluid_solver/water_params.h"
#include "fluid_solver/water_particles.h"
#include "io/checkpoint_file.h"
#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"
#include "scene/scene.h"
#include "sph/cell_order.h"
#include "sph/damping_stage.h"
#include "sph/domain_box.h"
#include "sph/kernel_choice.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "sph/observables.h"
#include "sph/particle_solver_core.h"
#include "sph/time_step_limits.h"

namespace porosph::water {

template <int D>
class WaterSolver : public sph::ParticleSolverCore<D, WaterParticles<D>> {
  using Core = sph::ParticleSolverCore<D, WaterParticles<D>>;

 public:
  /// Particles from scene.water.blocks, the inflow zones and the walls acting on water
  /// (initial_particles.h); masses m = rho(t=0) dp^D. Throws std::invalid_argument on a bad scene.
  explicit WaterSolver(const scene::Scene& scene);

  /// Neighbour search + wall state + all internal accelerations and drho/dt (+ density filter on
  /// its steps).
  void compute_rates();

  /// Diagnostics of the water particles and the overlap set: the water particles inside
  /// [overlap_min, overlap_max] (empty vectors: no overlap particles). Reuses out's vectors.
  /// region_min/max is the bounding box of the water (min = +inf, max = -inf when there is none).
  void fill_state(coupling::StepState& out, const std::vector<double>& overlap_min,
                  const std::vector<double>& overlap_max);
  /// Adds accelerations (n*D, row-major) to the overlap particles of the last fill_state, same
  /// order. Throws std::invalid_argument on a size mismatch.
  void add_interaction(const std::vector<double>& acceleration);
  /// The seepage drag rates lambda [1/s] of the overlap particles of the last fill_state
  /// (StepCommand.interaction_rate; empty: no drag): they set how much of the artificial
  /// viscosity the drag replaces in the next compute_rates() (artificial_viscosity.h) and the
  /// weight of the hydrostatic difference form (hydrostatic_difference.h). Throws
  /// std::invalid_argument on a size mismatch.
  void set_drag_rate(const std::vector<double>& rate);
  /// The soil porosity around the overlap particles of the last fill_state (StepCommand.porosity,
  /// sent before a snapshot; empty: no soil near), for the snapshot's `porosity` and
  /// `pore_velocity` fields (scenes with soil; pore_fields.h). Throws on a size mismatch.
  void set_porosity(const std::vector<double>& porosity);
  /// The speeds of the scene's walls for the next advance (StepCommand.wall_speed, one per
  /// [[walls]] entry; empty: all at rest): the moving ones move by dt times theirs
  /// (moving_walls.h).
  void set_wall_speeds(const std::vector<double>& speeds) { moving_walls_.set_speeds(speeds); }
  /// Modified Verlet step of the free water; prescribed motion of the inflow zones' particles and
  /// renewal of the zones (flow_zones.h); periodic wrap; removal of the water that left the domain,
  /// entered an outflow zone or rose above a reservoir's level (counted in removed_count); refill
  /// of the reservoirs (reservoirs.h); none of this while the damping stage
  /// freezes the water (sph/damping_stage.h). Then time += dt, ++step, and removal of the walls
  /// whose time has come.
  void advance(double dt);

  /// "non-finite velocity of particle 123 (x = ...)" and *particle_id = 123, or std::nullopt when
  /// every position, velocity and density is finite.
  std::optional<std::string> find_non_finite(std::int64_t* particle_id) const;
  /// position, velocity, density, pressure, mass, id (i64), fixed (u8) of every particle incl.
  /// walls, and in scenes with soil porosity and pore_velocity (set_porosity); the views stay
  /// valid until the next compute_rates/advance.
  std::vector<io::FieldView> snapshot_fields() const;
  /// The sources of the external impulses reported with each state (water_impulse_book.h).
  std::vector<std::string> impulse_sources() const { return water_impulse_sources(); }
  /// The external impulses of the last advance() (zero before the first), by source.
  const WaterImpulseBook<D>& impulse_book() const { return book_; }

  /// Stores the whole state the integrator carries from step to step (every particle array, the
  /// counters, time, step, next id, damping release, pending wall removal; water_checkpoint.cpp).
  /// Call between advance() and the next compute_rates().
  void write_checkpoint(io::CheckpointWriter& out);
  /// Replaces the state with a checkpoint's (the solver must be built from the same scene); the
  /// run then continues exactly as the one that wrote it. Throws std::runtime_error on a mismatch.
  void restore_checkpoint(const io::CheckpointReader& in);

  /// Water particles created by the inflow zones and the reservoirs so far.
  std::uint64_t born_count() const { return born_count_; }

  // Read access for tests and tools.
  const WaterParams<D>& params() const { return params_; }
  const FlowZones<D>& flow_zones() const { return zones_; }
  const Reservoirs<D>& reservoirs() const { return reservoirs_; }
  const OpenReservoirs<D>& open_reservoirs() const { return open_; }
  const sph::DampingStage& damping_stage() const { return damping_; }

 private:
  using Core::neighbours_;
  using Core::overlap_index_;
  using Core::particles_;
  using Core::scalars_;

  template <class Kernel>
  void compute_rates_with(const Kernel& kernel);
  void integrate(double dt);
  /// Whether the next advance() takes an Euler step of the modified Verlet scheme (the first
  /// step, every euler_every, density-filter steps, the end of the damping stage).
  bool next_step_is_euler() const;
  /// Whether this step re-initialises the density (water.density_filter_every).
  bool density_filter_due() const;
  /// True if water particle a left the domain or is a free particle in an outflow zone or above
  /// a reservoir's level.
  bool leaves(std::size_t a) const;
  void remove_leaving_particles();
  double evaluate(const sph::PreparedObservable<D>& o, const sph::ParticleView<D>& view) const;

  WaterParams<D> params_;
  sph::DomainBox<D> box_;
  sph::KernelChoice<D> kernel_;  ///< run.kernel: the one dispatch to the compiled loops
  sph::DampingStage damping_;
  FlowZones<D> zones_;
  Reservoirs<D> reservoirs_;
  OpenReservoirs<D> open_;       ///< zone codes after the inflow zones'
  MovingWalls<D> moving_walls_;  ///< [[walls]] with moves_with
  std::vector<sph::PreparedObservable<D>> observables_;

  sph::CellOrder<D> cell_order_{neighbours_, params_.h};  ///< search, re-sort by cell
  std::uint64_t born_count_ = 0;
  double inflow_mass_ = 0.0;  ///< mass of the particles born in inflow zones / reservoirs [kg]
  std::int64_t next_id_ = 0;  ///< id of the next particle born in an inflow zone
  double dt_previous_ = 0.0;  ///< the last step's dt: the Verlet span is dt_previous + dt
  bool viscosity_cut_nonzero_ = false;  ///< particles_.viscosity_cut may hold non-zero values
  double physics_seconds_ = 0.0;
  WaterImpulseBook<D> book_;  ///< of the last advance() (checkpointed)

  std::vector<double> filter_scratch_;
  ParticleShiftingGradients<D> shifting_;  ///< of the latest rates (water.particle_shifting > 0)
  mutable PoreFields<D> pore_fields_;      ///< porosity, pore velocity of the next snapshot
};

extern template class WaterSolver<2>;
extern template class WaterSolver<3>;

}  // namespace porosph::water
