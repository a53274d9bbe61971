// The step loop every built-in solver runs against the coupler (docs/design.md section 1):
//   report state + dt limit -> compute own rates (while the coupler computes the interaction from
//   the same state) -> receive the shared dt, interaction, flags -> write output if asked ->
//   add interaction -> advance.
// The state sent carries the dt limits of the latest rates (eq. 21 with the total acceleration of
// the previous step, docs/design.md section 1) and the CFL limit of the current speeds; the rates
// of the initial state are computed before the first report. A solver type plugs in by providing:
// compute_rates(), fill_state(StepState&, min, max), find_non_finite(std::int64_t*),
// add_interaction(const std::vector<double>&), advance(double), snapshot_fields(), time(), step(),
// write_checkpoint(io::CheckpointWriter&), restore_checkpoint(const io::CheckpointReader&); a soil
// solver also set_saturation(const std::vector<double>&); a solver with set_porosity(const
// std::vector<double>&) (the water solver) gets StepCommand.porosity before each snapshot, and one
// with set_drag_rate(const std::vector<double>&) StepCommand.interaction_rate every step. A solver
// with impulse_sources() reports those names with its first state (its fill_state() then fills
// Diagnostics.external_impulse; docs/coupling.md, "The external-impulse ledger").
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
#include <stdexcept>
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

/// True for a solver with set_porosity(const std::vector<double>&) (the water solver: the soil
/// porosity around its overlap particles, for the snapshot it is about to write).
template <class Solver, class = void>
struct has_set_porosity : std::false_type {};
template <class Solver>
struct has_set_porosity<Solver, std::void_t<decltype(std::declval<Solver&>().set_porosity(
                                    std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

/// True for a solver with set_drag_rate(const std::vector<double>&) (the water solver: the
/// seepage drag rates of its overlap particles, StepCommand.interaction_rate).
template <class Solver, class = void>
struct has_set_drag_rate : std::false_type {};
template <class Solver>
struct has_set_drag_rate<Solver, std::void_t<decltype(std::declval<Solver&>().set_drag_rate(
                                     std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

/// True for a solver with set_wall_speeds(const std::vector<double>&) (the water solver: the
/// speeds of the scene's moving walls, StepCommand.wall_speed).
template <class Solver, class = void>
struct has_set_wall_speeds : std::false_type {};
template <class Solver>
struct has_set_wall_speeds<Solver, std::void_t<decltype(std::declval<Solver&>().set_wall_speeds(
                                       std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

/// True for a solver with set_load_forces(const std::vector<double>&) (the soil solver: the forces
/// added to its surface loads, StepCommand.load_force).
template <class Solver, class = void>
struct has_set_load_forces : std::false_type {};
template <class Solver>
struct has_set_load_forces<Solver, std::void_t<decltype(std::declval<Solver&>().set_load_forces(
                                       std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

/// Writes the snapshot a command asks for, after handing a solver that takes it the command's
/// porosity.
template <class Solver>
void write_snapshot(io::SnapshotWriter& writer, Solver& solver, const StepCommand& command) {
  if constexpr (has_set_porosity<Solver>::value) solver.set_porosity(command.porosity);
  writer.write(command.output_index, solver.time(), solver.snapshot_fields());
}

/// The fields of a solver's snapshots besides position, as it declares them with its first state
/// (porosph.proto, OutputField): run.xdmf and run.json list them.
inline std::vector<coupling::OutputField> declared_output_fields(
    const std::vector<io::FieldView>& fields) {
  std::vector<coupling::OutputField> declared;
  for (const io::FieldView& f : fields) {
    if (f.name == "position") continue;  // the geometry of every snapshot
    const io::FieldType type = io::stored_type(f);
    declared.push_back({f.name, static_cast<std::uint32_t>(f.cols),
                        type == io::FieldType::I64  ? "Int"
                        : type == io::FieldType::U8 ? "UChar"
                                                    : "Float",
                        f.unit});
  }
  return declared;
}

/// True for a solver with active_terms() (the names reported with the first state).
template <class Solver, class = void>
struct has_active_terms : std::false_type {};
template <class Solver>
struct has_active_terms<Solver, std::void_t<decltype(std::declval<const Solver&>().active_terms())>>
    : std::true_type {};

/// True for a solver with impulse_sources() (the names of its external-impulse books, reported
/// with the first state; docs/coupling.md).
template <class Solver, class = void>
struct has_impulse_sources : std::false_type {};
template <class Solver>
struct has_impulse_sources<Solver,
                           std::void_t<decltype(std::declval<const Solver&>().impulse_sources())>>
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

/// A failure inside the step loop (a snapshot or checkpoint that cannot be written, ...), with the
/// solver's step and time when it happened: what solver_main.h reports to the coupler.
struct SolverFailure : std::runtime_error {
  SolverFailure(const std::string& what, std::uint64_t failed_step, double failed_time)
      : std::runtime_error(what), step(failed_step), time(failed_time) {}
  std::uint64_t step;
  double time;
};

template <class Solver>
int run_solver_loop_unguarded(CouplingClient& client, Solver& solver, io::SnapshotWriter& writer);

/// Runs the coupled step loop until the coupler says stop. Returns the process exit code (0 when
/// the coupler stopped the run normally, 1 when this solver failed - it has then told the coupler
/// why). Throws CouplingError when the coupler is gone, SolverFailure (the step and time of the
/// solver) on any other failure.
template <class Solver>
int run_solver_loop(CouplingClient& client, Solver& solver, io::SnapshotWriter& writer) {
  try {
    return run_solver_loop_unguarded(client, solver, writer);
  } catch (const CouplingError&) {
    throw;
  } catch (const std::exception& e) {
    throw SolverFailure(e.what(), solver.step(), solver.time());
  }
}

template <class Solver>
int run_solver_loop_unguarded(CouplingClient& client, Solver& solver, io::SnapshotWriter& writer) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double physics_seconds = 0.0;
  StepState state;
  std::vector<double> overlap_min, overlap_max;
  const SetupData& setup = client.setup();
  // A non-finite check; false (after telling the coupler, naming the particle) when the state
  // went bad. Run on each new state before it is sent, and again on its rates.
  const auto state_is_finite = [&]() {
    std::int64_t bad_particle = -1;
    if (auto problem = solver.find_non_finite(&bad_particle)) {
      client.report_error(*problem, solver.step(), solver.time(), bad_particle);
      return false;
    }
    return true;
  };
  const auto rates_are_finite = [&]() {
    solver.compute_rates();
    return state_is_finite();
  };
  // Physics wall time since the last report (reported with each state) and in all; the wall and
  // communication time of the process are reported the same way.
  double physics_since_report = 0.0;
  auto last_report = start;
  double communication_reported = 0.0;
  const auto timed = [&](auto&& work) {
    const auto t0 = Clock::now();
    const bool ok = work();
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    physics_since_report += seconds;
    physics_seconds += seconds;
    return ok;
  };
  // The rates of the current state are still to be computed. A checkpoint is taken after
  // advance(), before those rates: a restored solver continues from exactly there (its dt limits
  // of the previous rates are part of the checkpoint).
  bool rates_pending = false;
  if (!setup.restore_checkpoint.empty()) {
    restore_solver_checkpoint(setup, solver, overlap_min, overlap_max);
    rates_pending = true;
  } else if (!timed(rates_are_finite)) {
    return 1;
  }
  std::uint32_t checkpoint_written = 0;  // confirmed with the next state
  if constexpr (has_active_terms<Solver>::value) state.diagnostics.terms = solver.active_terms();
  if constexpr (has_impulse_sources<Solver>::value)
    state.diagnostics.impulse_sources = solver.impulse_sources();
  state.diagnostics.output_fields = declared_output_fields(solver.snapshot_fields());
  for (;;) {
    if (rates_pending && !timed(state_is_finite)) return 1;
    timed([&] {
      solver.fill_state(state, overlap_min, overlap_max);
      return true;
    });
    state.diagnostics.physics_seconds = physics_since_report;
    physics_since_report = 0.0;
    const auto now = Clock::now();
    state.diagnostics.wall_seconds = std::chrono::duration<double>(now - last_report).count();
    last_report = now;
    const double communication = client.communication_seconds();
    state.diagnostics.communication_seconds = communication - communication_reported;
    communication_reported = communication;
    state.checkpoint_written = checkpoint_written;
    checkpoint_written = 0;
    client.send_state(state);
    state.diagnostics.terms.clear();  // the first state carries them
    state.diagnostics.impulse_sources.clear();
    state.diagnostics.output_fields.clear();
    // Overlaps with the coupler's interaction and the other solver's work.
    if (rates_pending && !timed(rates_are_finite)) return 1;

    const StepCommand& command = client.receive_command();
    if (command.stop) {
      if (command.write_output) write_snapshot(writer, solver, command);
      break;
    }
    timed([&] {
      if (command.write_output) write_snapshot(writer, solver, command);
      overlap_min = command.other_region_min;
      overlap_max = command.other_region_max;
      if (!command.interaction_acceleration.empty()) {
        solver.add_interaction(command.interaction_acceleration);
      }
      if constexpr (has_set_saturation<Solver>::value) solver.set_saturation(command.saturation);
      if constexpr (has_set_drag_rate<Solver>::value)
        solver.set_drag_rate(command.interaction_rate);
      if constexpr (has_set_wall_speeds<Solver>::value) solver.set_wall_speeds(command.wall_speed);
      if constexpr (has_set_load_forces<Solver>::value) solver.set_load_forces(command.load_force);
      solver.advance(command.dt);
      if (command.write_checkpoint) {
        write_solver_checkpoint(setup, command.checkpoint_index, solver, overlap_min, overlap_max);
        checkpoint_written = command.checkpoint_index;
      }
      return true;
    });
    rates_pending = true;
  }
  Timing timing;
  timing.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  timing.physics_seconds = physics_seconds;
  timing.communication_seconds = client.communication_seconds();
  client.finalize(timing);
  return 0;
}

}  // namespace porosph::coupling
