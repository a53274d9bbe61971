// The soil phase solver (elastic-perfectly-plastic Drucker-Prager SPH, seed paper eq. 5-12 and
// 18-21; Bui et al. 2008): owns the soil and its fixed particles, computes the internal
// accelerations, strain rates and stress rates, reports its state to the coupler and integrates
// with the shared dt. The coupling loop (soil_solver/main.cpp, proto/solver_runtime.h) drives it:
//   fill_state(state, ...); <send>; compute_rates(); <receive>; add_interaction(a); advance(dt);
//
// Time integration (symplectic Euler): kick v += dt a(sigma^n) (minus the damping stage's D v);
// strain rate, spin and drho/dt from the NEW velocities at the old positions (a second neighbour
// pass on the same list); the stress update of stress_update.h (Jaumann rate + Drucker-Prager, then
// tension cracking and scaling back); drift x += dt v, rho += dt drho/dt, porosity from rho
// (eq. 20). Updating the stress from the new velocities is what keeps the explicit velocity-stress
// system stable up to the CFL limit: with velocity and stress both advanced from the old state
// (forward Euler) every elastic wave is amplified each step, and a column at rest blows up within
// a few hundred steps (measured on cases/soil_column).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/checkpoint_file.h"
#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"
#include "scene/scene.h"
#include "soil_solver/soil_impulse_book.h"
#include "soil_solver/soil_params.h"
#include "soil_solver/soil_particles.h"
#include "soil_solver/surface_loads.h"
#include "soil_solver/wall_stress_continuation.h"
#include "sph/cell_order.h"
#include "sph/damping_stage.h"
#include "sph/domain_box.h"
#include "sph/kernel_choice.h"
#include "sph/kernels.h"
#include "sph/neighbour_list.h"
#include "sph/observables.h"
#include "sph/particle_solver_core.h"
#include "sph/time_step_limits.h"
#include "sph/wall_occluders.h"

namespace porosph::soil {

template <int D>
class SoilSolver : public sph::ParticleSolverCore<D, SoilParticles<D>> {
  using Core = sph::ParticleSolverCore<D, SoilParticles<D>>;

 public:
  /// Particles from scene.soil.blocks (lattice points inside the soil's walls or an earlier block
  /// skipped, points outside the domain dropped; blocks of a fixed material become fixed
  /// particles) and from the walls acting on soil. Masses m = rho dp^D. Stress: geostatic or zero
  /// per soil.initial_stress. Throws std::invalid_argument on a bad scene.
  explicit SoilSolver(const scene::Scene& scene);

  /// Neighbour search + fixed-particle state + artificial stress + all rates.
  void compute_rates();

  /// Diagnostics and the overlap set (free soil particles inside [overlap_min, overlap_max]; with
  /// porosity and material). Reuses out's vectors.
  void fill_state(coupling::StepState& out, const std::vector<double>& overlap_min,
                  const std::vector<double>& overlap_max);
  /// Adds accelerations (n*D, row-major) to the overlap particles of the last fill_state (fixed
  /// soil among them ignores its share).
  void add_interaction(const std::vector<double>& acceleration);
  /// The water volume fraction around each overlap particle of the last fill_state (empty: none
  /// near water). A particle at or above coupling.submerged_saturation carries its submerged weight
  /// (stress divergence over rho^s = rho (rho_sat - rho_w) / rho_dry, seed eq. 16); at or above
  /// coupling.wet_saturation it is wet for good (wet_cohesion_loss: cohesion 0 from then on, its
  /// stress scaled back onto the cohesionless surface at the next update). Particles outside the
  /// overlap set are dry.
  void set_saturation(const std::vector<double>& saturation);
  /// The forces added to the surface loads for the next rates (StepCommand.load_force; empty:
  /// none; surface_loads.h). Throws std::invalid_argument on a size mismatch.
  void set_load_forces(const std::vector<double>& forces) { loads_.set_extra_forces(forces); }
  /// One step (see above), periodic wrap, removal of particles leaving the domain and of walls
  /// whose time has come; time += dt; ++step.
  void advance(double dt);

  std::optional<std::string> find_non_finite(std::int64_t* particle_id) const;
  /// position, velocity, density, stress (N x 9, row-major 3x3, tension positive), porosity,
  /// plastic_strain, displacement, saturation, id, material, fixed; valid until the next
  /// compute_rates/advance.
  std::vector<io::FieldView> snapshot_fields() const;
  /// The sources of the external impulses reported with each state (soil_impulse_book.h).
  std::vector<std::string> impulse_sources() const { return soil_impulse_sources(); }
  /// The external impulses of the last advance() (zero before the first), by source.
  const SoilImpulseBook<D>& impulse_book() const { return book_; }

  /// Stores the whole state the integrator carries from step to step (every particle array incl.
  /// stress, porosity, plastic strain, displacement, saturation and wet flags; the counters, time,
  /// step, damping release, pending wall removal; soil_checkpoint.cpp). Call between advance() and
  /// the next compute_rates().
  void write_checkpoint(io::CheckpointWriter& out);
  /// Replaces the state with a checkpoint's (the solver must be built from the same scene); the
  /// run then continues exactly as the one that wrote it. Throws std::runtime_error on a mismatch.
  void restore_checkpoint(const io::CheckpointReader& in);

  SoilParticles<D>& mutable_particles() { return particles_; }  ///< for tests
  const SoilParams<D>& params() const { return params_; }

 private:
  using Core::neighbours_;
  using Core::overlap_index_;
  using Core::particles_;
  using Core::scalars_;

  /// Every free particle's stress over dt from its velocity gradient (seed eq. 6, 12a/12b;
  /// stress_update.h).
  void update_stresses(double dt);
  template <class Kernel>
  void compute_rates_with(const Kernel& kernel);
  void remove_particles_outside();
  double evaluate(const sph::PreparedObservable<D>& o, const sph::ParticleView<D>& view) const;

  SoilParams<D> params_;
  sph::DampingStage damping_;  ///< soil.damping_duration (0 with the term off)
  sph::DomainBox<D> box_;
  sph::KernelChoice<D> kernel_;  ///< run.kernel: the one dispatch to the compiled loops
  SurfaceLoads<D> loads_;        ///< [[soil.loads]]: tractions on tagged particles
  std::vector<sph::PreparedObservable<D>> observables_;

  sph::CellOrder<D> cell_order_{neighbours_, params_.h};  ///< search, re-sort by cell
  bool saturation_set_ = false;                   ///< some particle has a non-zero saturation
  SoilImpulseBook<D> book_;                       ///< of the last advance() (checkpointed)
  sph::Vec<D> load_force_ = sph::Vec<D>::Zero();  ///< the surface loads' total, latest rates
  std::vector<double> rates_weight_ratio_;  ///< weight_ratio of the free soil at the latest rates
  /// The interaction the coupler sent to fixed soil (index, acceleration): never applied, booked.
  std::vector<std::pair<std::int32_t, sph::Vec<D>>> fixed_interaction_;

  std::vector<Eigen::Matrix3d> filter_scratch_;
  std::vector<StressGradient<D>> wall_gradient_scratch_;  ///< soil_walls.h, linear continuation
};

extern template class SoilSolver<2>;
extern template class SoilSolver<3>;

}  // namespace porosph::soil
