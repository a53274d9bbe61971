// The lock-step loop of a coupled run (docs/design.md section 1, one round trip per step):
// collect every solver's state -> soil-water interaction (when both phases exist; its eq. 21
// limit joins the solvers' dt limits) -> the one shared dt (TimeStepController) -> output / stop
// flags -> conservation ledger -> send every solver its command (dt, interaction accelerations,
// saturation, and the overlap zone it must report next step). Checkpoints (coupler/checkpoint.h):
// the command advancing to a checkpoint's step boundary carries write_checkpoint; the states that
// follow confirm it and the coupler writes its part. A SIGINT/SIGTERM past t = 0 forces one and
// then stops the solvers.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "coupler/checkpoint.h"
#include "coupler/checkpoint_state.h"
#include "coupler/interaction/soil_water_interaction.h"
#include "coupler/progress_line.h"
#include "coupler/run_record.h"
#include "coupler/solver_hub.h"
#include "coupler/time_step_controller.h"
#include "io/timeseries_csv.h"
#include "scene/scene.h"

namespace porosph::coupler {

class CoupledStepLoop {
 public:
  /// `check_alive` throws when a solver process died; `interrupt_signal` returns the SIGINT /
  /// SIGTERM received since its last call (0: none; a second one stops the run at once);
  /// `write_outputs` refreshes run.json and run.xdmf (called after each output once the solvers
  /// have written it). `resumed`: the loop state of the checkpoint the run resumes from (record
  /// already restored, record.checkpoint_index its index), or null.
  CoupledStepLoop(const scene::Scene& scene, SolverHub& hub, RunRecord& record,
                  const std::string& out_dir, std::function<void()> check_alive,
                  std::function<int()> interrupt_signal, std::function<void()> write_outputs,
                  const LoopState* resumed = nullptr);

  /// Called once per step (the caller rewrites run.json when its heartbeat is due).
  void set_heartbeat(std::function<void()> heartbeat) { heartbeat_ = std::move(heartbeat); }

  /// Runs to end_time and the solvers' Goodbye. Throws std::runtime_error on any failure.
  void run(ProgressLine& progress);

 private:
  void collect_states();
  /// Evaluates the interaction for the collected states (scenes with both phases) and books its
  /// statistics; returns its dt limit (infinity without interaction).
  double compute_interaction();
  /// Checks `state` and keeps it as the phase's current state, completed from the previous one
  /// where the message left parts out (proto/state_delta.h). Arrays sent whole are swapped in:
  /// `state` keeps storage the next receive reuses.
  void absorb_state(const std::string& phase, coupling::StepState& state);
  void append_timeseries_row(double dt);
  void send_commands(double dt, bool write_output, std::uint32_t output_index, bool stop,
                     std::uint32_t checkpoint_index = 0);
  void wait_for_goodbyes();
  /// Completes the pending checkpoint with the states just collected; on a signal, stops the run
  /// (throws) once it is written. Returns whether a checkpoint must be forced on this step.
  bool handle_checkpoint_and_signal();
  [[noreturn]] void stop_after_signal();
  /// Takes a new signal from interrupt_signal_; throws if one was already being handled.
  void poll_signal();
  std::vector<std::string> timeseries_columns() const;

  const scene::Scene& scene_;
  SolverHub& hub_;
  RunRecord& record_;
  std::function<void()> check_alive_;
  std::function<int()> interrupt_signal_;
  std::function<void()> write_outputs_;
  std::function<void()> heartbeat_;
  int pending_signal_ = 0;   ///< a signal arrived, not yet acted upon
  int stopping_signal_ = 0;  ///< the checkpoint of that signal is under way; then stop
  std::chrono::steady_clock::time_point signal_seen_;
  LoopState loop_;
  CheckpointKeeper checkpoints_;
  std::vector<std::string> phases_;
  TimeStepController controller_;
  std::unique_ptr<io::TimeSeriesCsv> timeseries_;
  std::unique_ptr<SoilWaterInteraction> interaction_;  ///< null unless both phases exist
  InteractionSummary interaction_summary_;
  std::map<std::string, coupling::StepState> states_;
  std::map<std::string, coupling::StepCommand> commands_;
  std::map<std::string, bool> received_;  ///< which phases reported this step
  Incoming incoming_;  ///< the message being received (its arrays keep their capacity)
  /// The hub's byte counts and the record's when the loop started (the record adds the loop's).
  std::uint64_t hub_bytes_received_start_ = 0, hub_bytes_sent_start_ = 0;
  std::uint64_t record_bytes_received_start_ = 0, record_bytes_sent_start_ = 0;
  std::vector<double> row_;
};

}  // namespace porosph::coupler
