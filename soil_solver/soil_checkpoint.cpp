// SoilSolver's checkpoint (docs/checkpoints.md): the particle arrays (stress, porosity, plastic
// strain, displacement, saturation, wet flags, ...) and every scalar of the state that survives a
// step. Scratch buffers and the neighbour list are rebuilt by the next compute_rates().
#include <stdexcept>

#include "soil_solver/soil_solver.h"

namespace porosph::soil {

template <int D>
void SoilSolver<D>::write_checkpoint(io::CheckpointWriter& out) {
  this->write_core_checkpoint(out);
  out.set("damping_released", static_cast<std::int64_t>(damping_.released()));
  out.set("saturation_set", static_cast<std::int64_t>(saturation_set_));
  book_.write(out);  // the next state reports the step before the checkpoint
}

template <int D>
void SoilSolver<D>::restore_checkpoint(const io::CheckpointReader& in) {
  this->read_core_checkpoint(in);
  damping_.set_released(in.get_i64("damping_released") != 0);
  saturation_set_ = in.get_i64("saturation_set") != 0;
  book_.read(in);
}

template void SoilSolver<2>::write_checkpoint(io::CheckpointWriter&);
template void SoilSolver<3>::write_checkpoint(io::CheckpointWriter&);
template void SoilSolver<2>::restore_checkpoint(const io::CheckpointReader&);
template void SoilSolver<3>::restore_checkpoint(const io::CheckpointReader&);

}  // namespace porosph::soil
