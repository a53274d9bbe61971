// The step loop every built-in solver runs against the coupler (DESIGN.md section 1):
//   report state + dt limit -> compute own rates (while the coupler computes the interaction from
//   the same state) -> receive the shared dt, interaction, flags -> write output if asked ->
//   add interaction -> advance.
// The state sent carries the dt limits of the latest rates (eq. 21 with the total acceleration of
// the previous step, DESIGN.md section 1) and the CFL limit of the current speeds; the rates of the
// initial state are computed before the first report.
// A solver type plugs in by providing: compute_rates(), fill_state(StepState&, min, max),
// find_non_finite(std::int64_t*), add_interaction(const std::vector<double>&), advance(double),
// snapshot_fields(), time(), step(); a soil solver also set_saturation(const std::vector<double>&).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/snapshot_writer.h"
#include "proto/coupling_client.h"

namespace porosph::coupling {

/// True for a solver with set_saturation(const std::vector<double>&) (the soil solvers).
template <class Solver, class = void>
struct has_set_saturation : std::false_type {};
template <class Solver>
struct has_set_saturation<Solver, std::void_t<decltype(std::declval<Solver&>().set_saturation(
                                      std::declval<const std::vector<double>&>()))>>
    : std::true_type {};

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
  // Physics wall time since the last report (reported with each state) and in all.
  double physics_since_report = 0.0;
  const auto timed = [&](auto&& work) {
    const auto t0 = Clock::now();
    const bool ok = work();
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    physics_since_report += seconds;
    physics_seconds += seconds;
    return ok;
  };
  if (!timed(rates_are_finite)) return 1;
  bool rates_pending = false;  // the rates of the current state are still to be computed
  for (;;) {
    if (rates_pending && !timed(state_is_finite)) return 1;
    timed([&] {
      solver.fill_state(state, overlap_min, overlap_max);
      return true;
    });
    state.diagnostics.physics_seconds = physics_since_report;
    physics_since_report = 0.0;
    client.send_state(state);
    // Overlaps with the coupler's interaction and the other solver's work.
    if (rates_pending && !timed(rates_are_finite)) return 1;

    const StepCommand& command = client.receive_command();
    if (command.stop) {
      if (command.write_output)
        writer.write(command.output_index, solver.time(), solver.snapshot_fields());
      break;
    }
    timed([&] {
      if (command.write_output)
        writer.write(command.output_index, solver.time(), solver.snapshot_fields());
      overlap_min = command.other_region_min;
      overlap_max = command.other_region_max;
      if (!command.interaction_acceleration.empty()) {
        solver.add_interaction(command.interaction_acceleration);
      }
      if constexpr (has_set_saturation<Solver>::value) solver.set_saturation(command.saturation);
      solver.advance(command.dt);
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
