// What every particle solver holds besides its physics (issue 24, the shared phase core): its
// particles, their neighbour list, the scalars of its state that survive a step
// (solver_scalars.h) and the terms the registry switches on; and the read access that the coupling
// loop (proto/solver_runtime.h), the tools and the tests use. A solver derives from it and adds
// its physics and the rest of the interface of proto/solver_runtime.h (compute_rates, fill_state,
// add_interaction, advance, find_non_finite, snapshot_fields, write_checkpoint,
// restore_checkpoint; documented there).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/checkpoint_file.h"
#include "sph/checkpoint_arrays.h"
#include "sph/neighbour_list.h"
#include "sph/occluder_crossing.h"
#include "sph/particle_removal.h"
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

  /// The common part of add_interaction(): every particle's interaction to zero, then the
  /// coupler's accelerations (n*D values, row-major, in the order of the overlap set the last
  /// fill_state() reported) onto the overlap particles with index < movable; on_fixed(index, a)
  /// gets those of the others. Throws std::invalid_argument on a size mismatch.
  template <class OnFixed>
  void scatter_interaction(const std::vector<double>& acceleration, std::size_t movable,
                           OnFixed&& on_fixed) {
    if (acceleration.size() != overlap_index_.size() * D) {
      throw std::invalid_argument("add_interaction: expected " +
                                  std::to_string(overlap_index_.size() * D) + " values, got " +
                                  std::to_string(acceleration.size()));
    }
    std::fill(particles_.interaction.begin(), particles_.interaction.end(), Vec<D>::Zero());
    for (std::size_t i = 0; i < overlap_index_.size(); ++i) {
      const std::size_t index = static_cast<std::size_t>(overlap_index_[i]);
      Vec<D> a;
      for (int k = 0; k < D; ++k) a[k] = acceleration[i * D + k];
      if (index < movable) {
        particles_.interaction[index] = a;
      } else {
        on_fixed(overlap_index_[i], a);
      }
    }
    interaction_fresh_ = true;
    scalars_.interaction_nonzero = true;
  }

  /// The start of advance(): when no add_interaction() came since the last advance, the
  /// interaction of an earlier step is zeroed (it acts neither in this step nor in the next
  /// step's eq. 21) and true is returned, so the solver can drop what it kept of it too.
  bool drop_stale_interaction() {
    const bool stale = !interaction_fresh_ && scalars_.interaction_nonzero;
    if (stale) {
      std::fill(particles_.interaction.begin(), particles_.interaction.end(), Vec<D>::Zero());
      scalars_.interaction_nonzero = false;
    }
    interaction_fresh_ = false;
    return stale;
  }

  /// Removes the free particles for which leaves(i) holds (particle_removal.h), counting them in
  /// removed_count and their mass in outflow_mass; removing(i) sees each before it goes.
  template <class Leaves, class Removing>
  void remove_free_particles_where(const Leaves& leaves, const Removing& removing) {
    scalars_.removed_count +=
        remove_free_particles(particles_, leaves, keep_scratch_, scalars_.outflow_mass, removing);
  }

  /// The occluder (thin wall) free particle a's move from `before` to its position now crossed,
  /// or -1 (always -1 without occluders). Called in the drift loops before the periodic wrap.
  int crossed_occluder_by(std::size_t a, const Vec<D>& before) const {
    const WallOccluders<D>& occluders = neighbours_.occluders();
    if (occluders.empty()) return -1;
    return sph::crossed_occluder<D>(occluders, before, particles_.position[a]);
  }
  /// Keeps the first crossing of a run (occluder_crossing.h) for crossing_problem().
  void record_crossing(const char* kind, const FirstCrossing<D>& c) {
    if (crossing_problem_ || c.index < 0) return;
    crossing_particle_ = particles_.id[c.index];
    crossing_problem_ =
        occluder_crossing_message<D>(kind, crossing_particle_, neighbours_.occluders()[c.wall],
                                     c.before, c.after, scalars_.step, scalars_.time);
  }
  /// The crossing recorded, if any, with its particle's id: find_non_finite() reports it first.
  std::optional<std::string> crossing_problem(std::int64_t* particle_id) const {
    if (crossing_problem_ && particle_id) *particle_id = crossing_particle_;
    return crossing_problem_;
  }

  /// Removes the fixed particles whose time has come (a wall's remove_at; particle_removal.h).
  void remove_expired_walls() {
    if (scalars_.next_wall_removal < 0.0 || scalars_.time < scalars_.next_wall_removal) return;
    scalars_.next_wall_removal =
        remove_expired_fixed_particles(particles_, scalars_.time, keep_scratch_);
  }

  /// The core's part of write_checkpoint(): every particle array (checkpoint_arrays.h), then the
  /// step scalars. The solver adds its own scalars after it.
  void write_core_checkpoint(io::CheckpointWriter& out) {
    write_particle_arrays(out, particles_);
    scalars_.write(out, D);
  }
  /// The core's part of restore_checkpoint(): the step scalars first (they throw for another
  /// dimension before anything else changes), then the particle arrays; the neighbour list is
  /// rebuilt by the next compute_rates(), and no interaction is pending (a checkpoint is taken
  /// after advance()). A checkpoint written before thin walls were filled on both sides has no
  /// tagged wall particle (its wall_side zero-filled, checkpoint_arrays.h): the run keeps its thin
  /// walls shared, as it ran so far, and says so.
  void read_core_checkpoint(const io::CheckpointReader& in) {
    neighbours_.invalidate();
    scalars_.read(in, D);
    read_particle_arrays(in, particles_);
    interaction_fresh_ = false;
    const auto& tags = particles_.wall_side;
    if (!neighbours_.occluders().empty() &&
        std::none_of(tags.begin(), tags.end(), [](std::int32_t tag) { return tag != 0; })) {
      std::fprintf(stderr,
                   "%s: the checkpoint's thin walls are one-sided (written before "
                   "water.thin_walls / soil.thin_walls); they stay shared as in the run so far\n",
                   in.path().c_str());
      neighbours_.set_occluders({});
    }
  }

  Particles particles_;
  NeighbourList<D> neighbours_;
  SolverScalars scalars_;  ///< time, step, dt limits, removal and interaction bookkeeping
  std::vector<std::string> terms_;
  /// The particles of the overlap set the last fill_state() reported, in its order.
  std::vector<std::int32_t> overlap_index_;
  bool interaction_fresh_ = false;               ///< add_interaction called since the last advance
  std::optional<std::string> crossing_problem_;  ///< a free particle crossed a thin wall
  std::int64_t crossing_particle_ = -1;
  std::vector<std::uint8_t> keep_scratch_;
};

}  // namespace porosph::sph
