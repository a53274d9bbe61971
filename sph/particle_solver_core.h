// What every particle solver holds besides its physics (issue 24, the shared phase core): its
// particles, their neighbour list, the scalars of its state that survive a step
// (solver_scalars.h) and the terms the registry switches on; and the read access that the coupling
// loop (proto/solver_runtime.h), the tools and the tests use. A solver derives from it and adds
// its physics and the rest of the interface of proto/solver_runtime.h (compute_rates, fill_state,
// add_interaction, advance, find_non_finite, snapshot_fields, write_checkpoint,
// restore_checkpoint; documented there).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sph/neighbour_list.h"
#include "sph/solver_scalars.h"
#include "sph/time_step_limits.h"

namespace porosph::sph {

template <int D, class Particles>
class ParticleSolverCore {
 public:
  /// The time-step limits of the latest compute_rates() (seed eq. 21).
  DtLimits dt_limits() const { return scalars_.limits; }
  /// The physics terms the registry switches on for the scene (scene/term_registry.h), as
  /// run.json lists them under phases.<phase>.terms.
  const std::vector<std::string>& active_terms() const { return terms_; }
  double time() const { return scalars_.time; }
  std::uint64_t step() const { return scalars_.step; }
  std::size_t particle_count() const { return particles_.size(); }
  std::size_t free_count() const { return particles_.n_free; }
  /// Particles removed so far (left the domain, or an outflow of the phase).
  std::uint64_t removed_count() const { return scalars_.removed_count; }
  const Particles& particles() const { return particles_; }
  const NeighbourList<D>& neighbours() const { return neighbours_; }

 protected:
  explicit ParticleSolverCore(std::vector<std::string> terms) : terms_(std::move(terms)) {}

  Particles particles_;
  NeighbourList<D> neighbours_;
  SolverScalars scalars_;  ///< time, step, dt limits, removal and interaction bookkeeping
  std::vector<std::string> terms_;
};

}  // namespace porosph::sph
