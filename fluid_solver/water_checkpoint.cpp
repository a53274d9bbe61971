// WaterSolver's checkpoint (docs/checkpoints.md): the particle arrays and every scalar of the
// state that survives a step. Scratch buffers and the neighbour list are rebuilt by the next
// compute_rates().
#include <algorithm>
#include <stdexcept>

#include "fluid_solver/water_solver.h"

namespace porosph::water {

template <int D>
void WaterSolver<D>::write_checkpoint(io::CheckpointWriter& out) {
  this->write_core_checkpoint(out);
  out.set("born_count", static_cast<std::int64_t>(born_count_));
  out.set("inflow_mass", inflow_mass_);
  out.set("next_id", next_id_);
  out.set("damping_released", static_cast<std::int64_t>(damping_.released()));
  out.set("physics_seconds", physics_seconds_);
  out.set("dt_previous", dt_previous_);
  book_.write(out);  // the next state reports the step before the checkpoint
}

template <int D>
void WaterSolver<D>::restore_checkpoint(const io::CheckpointReader& in) {
  this->read_core_checkpoint(in);
  born_count_ = static_cast<std::uint64_t>(in.get_i64("born_count"));
  inflow_mass_ = in.get_f64("inflow_mass");
  next_id_ = in.get_i64("next_id");
  viscosity_cut_nonzero_ =
      std::any_of(particles_.viscosity_cut.begin(), particles_.viscosity_cut.end(),
                  [](double cut) { return cut > 0.0; });
  dt_previous_ = in.get_f64("dt_previous");
  damping_.set_released(in.get_i64("damping_released") != 0);
  physics_seconds_ = in.get_f64("physics_seconds");
  book_.read(in);
}

template void WaterSolver<2>::write_checkpoint(io::CheckpointWriter&);
template void WaterSolver<3>::write_checkpoint(io::CheckpointWriter&);
template void WaterSolver<2>::restore_checkpoint(const io::CheckpointReader&);
template void WaterSolver<3>::restore_checkpoint(const io::CheckpointReader&);

}  // namespace porosph::water
