// The step loop every built-in solver runs against the coupler (DESIGN.md section 1):
//   compute own rates -> report state + dt limit -> receive the shared dt, interaction, flags ->
//   write output if asked -> add interaction -> advance.
// A solver type plugs in by providing: compute_rates(), fill_state(StepState&, min, max),
// find_non_finite(std::int64_t*), add_interaction(const std::vector<double>&), advance(double),
// snapshot_fields(), time(), step(), write_checkpoint(io::CheckpointWriter&),
// restore_checkpoint(const io::CheckpointReader&); a soil solver also
// set_saturation(const std::vector<double>&).
// Checkpoints (docs/checkpoints.md): a command with write_checkpoint makes the loop advance, then
// write OUT/checkpoint/<phase>_NNNN.h5 (the solver's state plus the overlap zone of that command)
// and confirm it in the next state; Setup.restore_checkpoint makes it restore one before the first
// step.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/checkpoint_file.h"
#include "io/snapshot_writer.h"
#include "proto/checkpoint_names.h"
#include "proto/coupling_client.h"

namespace porosph::coupling {

/// True for a solver with set_saturation(const std::vector<double>&) (the soil solvers).
template <class Solver, class = void>
struct has_set_saturation : std::false_type {};
template <class Solver>
struct has_set_saturation<Solver, std::void_t<decltype(std::declval<Solver&>().set_saturation(
                                      std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

/// The phase's snapshot file OUT/<file_name>: created afresh, or on resume reopened without the
/// snapshots written after the checkpoint (index >= Setup.resume_output_index).
inline std::unique_ptr<io::SnapshotWriter> open_snapshot_writer(const SetupData& setup,
                                                                const std::string& file_name) {
  const std::string path = setup.output_dir + "/" + file_name;
  if (setup.restore_checkpoint.empty()) return std::make_unique<io::SnapshotWriter>(path);
  return std::make_unique<io::SnapshotWriter>(path, setup.resume_output_index);
}

/// Writes checkpoint `index` of `solver` (atomically: temp file + rename) with the overlap zone
/// the solver must report next.
template <class Solver>
void write_solver_checkpoint(const SetupData& setup, std::uint32_t index, Solver& solver,
                             const std::vector<double>& overlap_min,
                             const std::vector<double>& overlap_max) {
  std::filesystem::create_directories(checkpoint_dir(setup.output_dir));
  io::CheckpointWriter out(solver_checkpoint_path(setup.output_dir, setup.phase, index));
  solver.write_checkpoint(out);
  out.write("overlap_min", overlap_min.data(), overlap_min.size());
  out.write("overlap_max", overlap_max.data(), overlap_max.size());
  out.commit();
}

/// Restores Setup.restore_checkpoint into `solver` and the overlap zone it must report first.
template <class Solver>
void restore_solver_checkpoint(const SetupData& setup, Solver& solver,
                               std::vector<double>& overlap_min, std::vector<double>& overlap_max) {
  const io::CheckpointReader in(setup.restore_checkpoint);
  solver.restore_checkpoint(in);
  overlap_min.resize(in.rows("overlap_min"));
  overlap_max.resize(in.rows("overlap_max"));
  in.read("overlap_min", overlap_min.data());
  in.read("overlap_max", overlap_max.data());
}

/// Runs the coupled step loop until the coupler says stop. Returns the process exit code (0 when
/// the coupler stopped the run normally, 1 when this solver failed - it has then told the coupler
/// why).
template <class Solver>
int run_solver_loop(CouplingClient& client, Solver& solver, io::SnapshotWriter& writer) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double physics_seconds = 0.0;
  StepState state;
  std::vector<double> overlap_min, overlap_max;
  const SetupData& setup = client.setup();
  if (!setup.restore_checkpoint.empty()) {
    restore_solver_checkpoint(setup, solver, overlap_min, overlap_max);
  }
  std::uint32_t checkpoint_written = 0;  // confirmed with the next state
  for (;;) {
    const auto physics_start = Clock::now();
    solver.compute_rates();
    std::int64_t bad_particle = -1;
    if (auto problem = solver.find_non_finite(&bad_particle)) {
      client.report_error(*problem, solver.step(), solver.time(), bad_particle);
      return 1;
    }
    solver.fill_state(state, overlap_min, overlap_max);
    const double physics_now = std::chrono::duration<double>(Clock::now() - physics_start).count();
    physics_seconds += physics_now;
    state.diagnostics.physics_seconds = physics_now;
    state.checkpoint_written = checkpoint_written;
    checkpoint_written = 0;

    const StepCommand& command = client.exchange(state);

    const auto output_start = Clock::now();
    if (command.write_output)
      writer.write(command.output_index, solver.time(), solver.snapshot_fields());
    if (command.stop) break;
    overlap_min = command.other_region_min;
    overlap_max = command.other_region_max;
    if (!command.interaction_acceleration.empty()) {
      solver.add_interaction(command.interaction_acceleration);
    }
    if constexpr (has_set_saturation<Solver>::value) solver.set_saturation(command.saturation);
    solver.advance(command.dt);
    if (command.write_checkpoint) {
      write_solver_checkpoint(setup, command.checkpoint_index, solver, overlap_min, overlap_max);
      checkpoint_written = command.checkpoint_index;
    }
    physics_seconds += std::chrono::duration<double>(Clock::now() - output_start).count();
  }
  Timing timing;
  timing.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  timing.physics_seconds = physics_seconds;
  timing.communication_seconds = client.communication_seconds();
  client.finalize(timing);
  return 0;
}

}  // namespace porosph::coupling
