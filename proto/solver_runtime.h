// The step loop every built-in solver runs against the coupler (DESIGN.md section 1):
//   compute own rates -> report state + dt limit -> receive the shared dt, interaction, flags ->
//   write output if asked -> add interaction -> advance.
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
