// A second soil solver: the soil as a rigid porous skeleton (a fixed bed of the seed paper's
// Darcy and Forchheimer tests). Its particles never move; each step it reports the ones inside the
// overlap zone with zero velocity, its material's density and porosity, and no time-step limit of
// its own (a skeleton that does not move has none). The interaction accelerations the coupler
// returns are not applied: they are only booked, as the impulse each particle absorbed,
// sum m^s a dt with the submerged mass of the coupler's own rule (so the skeleton's total equals
// the coupler's ledger impulse_to_soil). Writes OUT/soil.h5 in the layout of the built-in
// soil_solver (soil_solver/soil_output.h) plus one field, absorbed_impulse.
//
// It plugs into proto/solver_runtime.h's run_solver_loop like the built-in solvers, and so never
// sees ZeroMQ or Protobuf (docs/solver-protocol.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/checkpoint_file.h"
#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"
#include "rigid_soil_solver/rigid_skeleton.h"
#include "scene/scene.h"
#include "sph/kernels.h"
#include "sph/observables.h"

namespace porosph::rigid_soil {

template <int D>
class RigidSoilSolver {
 public:
  /// The skeleton of the scene's soil blocks (build_rigid_skeleton) and the scene's soil
  /// observables. Throws std::invalid_argument on a scene without soil or with a bad observable.
  explicit RigidSoilSolver(const scene::Scene& scene);

  /// Nothing to compute: a rigid skeleton has no internal forces.
  void compute_rates() {}

  /// Step and time, no dt limit (+infinity), the particles inside [overlap_min, overlap_max]
  /// (empty bounds: none) with zero velocity, the bounding box of the skeleton, and diagnostics of
  /// the free particles (there are none: zero mass, momentum and energy; soil observables take
  /// their empty-set values, sph/observables.h). Reuses out's vectors.
  void fill_state(coupling::StepState& out, const std::vector<double>& overlap_min,
                  const std::vector<double>& overlap_max);
  /// Keeps the interaction accelerations (n*D, one row per overlap particle of the last
  /// fill_state) for the bookkeeping of the next advance(). Throws std::invalid_argument on a
  /// wrong size.
  void add_interaction(const std::vector<double>& acceleration);
  /// The water volume fraction around each overlap particle of the last fill_state (empty: no
  /// water near); the others get 0. It decides the submerged mass of the bookkeeping and is
  /// written as the snapshot field `saturation`. Throws std::invalid_argument on a wrong size.
  void set_saturation(const std::vector<double>& saturation);
  /// Books the impulse of the accelerations received since the last advance over dt (none
  /// received: none booked); time += dt; ++step. Nothing moves.
  void advance(double dt);

  /// The first particle whose absorbed impulse is not finite (a non-finite acceleration from the
  /// coupler), as a message naming it; std::nullopt if there is none.
  std::optional<std::string> find_non_finite(std::int64_t* particle_id) const;
  /// position, velocity (0), density, stress (0, N x 9), porosity, plastic_strain (0),
  /// displacement (0), id, material, fixed (1), all marked unchanging (stored once in soil.h5's
  /// /static group, linked from every snapshot); saturation and absorbed_impulse (N x D).
  std::vector<io::FieldView> snapshot_fields() const;

  /// Stores the skeleton's arrays (saturation and absorbed impulse are its only changing state),
  /// time and step.
  void write_checkpoint(io::CheckpointWriter& out);
  /// Replaces the state with a checkpoint's. Throws std::runtime_error on a checkpoint of another
  /// dimension or particle layout.
  void restore_checkpoint(const io::CheckpointReader& in);

  double time() const { return time_; }
  std::uint64_t step() const { return step_; }
  const RigidSkeleton<D>& skeleton() const { return skeleton_; }
  /// Sum of absorbed_impulse over the skeleton [N s].
  sph::Vec<D> total_absorbed_impulse() const;

 private:
  RigidSkeleton<D> skeleton_;
  std::vector<double> zeros_;            ///< backs every field of the skeleton that is always 0
  std::vector<double> submerged_ratio_;  ///< rho^s / rho per material when submerged
  double submerged_saturation_ = 0.8;
  sph::CubicSpline<D> kernel_;  ///< what evaluate_observable asks for (pressure_at only)
  std::vector<sph::PreparedObservable<D>> observables_;
  std::vector<std::int32_t> overlap_index_;  ///< skeleton index of each overlap particle
  std::vector<double> interaction_;          ///< accelerations not yet booked (n_overlap * D)
  double time_ = 0.0;
  std::uint64_t step_ = 0;
};

extern template class RigidSoilSolver<2>;
extern template class RigidSoilSolver<3>;

}  // namespace porosph::rigid_soil
