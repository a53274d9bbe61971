// The coupler's part of a checkpoint (docs/checkpoints.md): the step loop's own state and the run
// record (counters, dt statistics, conservation ledger, interaction statistics, per-phase initial
// diagnostics and mass ledgers, snapshot lists, observables, the resolved scene), as JSON text.
// Doubles are written so that they read back bit for bit (shortest round-trip form; non-finite
// values as the strings "inf", "-inf", "nan").
#pragma once

#include <cstdint>
#include <string>

#include "coupler/run_record.h"

namespace porosph::coupler {

/// What CoupledStepLoop carries from one step to the next besides the run record.
struct LoopState {
  std::uint32_t output_index = 0;  ///< index of the next snapshot
  double next_output_time = 0.0;
  double last_output_time = -1.0;
  std::uint64_t row_index = 0;  ///< rows written to timeseries.csv (run.timeseries_interval)
  double next_row_time = 0.0;
  double last_row_time = -1.0;
  bool outputs_pending = false;  ///< run.json / run.xdmf to refresh after the next states
  double controller_dt = 0.0;    ///< TimeStepController::current()
};

/// The coupler state as JSON text.
std::string coupler_state_json(const RunRecord& record, const LoopState& loop);

/// Restores a coupler_state_json() text into `record` and `loop` (the fields it holds; process
/// ids, timing of the solver processes and the status stay as they are). Throws
/// std::runtime_error naming `source` if the text is not such a state.
void restore_coupler_state(const std::string& text, const std::string& source, RunRecord& record,
                           LoopState& loop);

}  // namespace porosph::coupler
