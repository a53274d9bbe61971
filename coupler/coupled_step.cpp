#include "coupler/coupled_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "coupler/coupled_step_clock.h"
#include "coupler/interaction/overlap_region.h"
#include "coupler/observable_feedback.h"
#include "proto/state_delta.h"
#include "scene/timeseries_columns.h"

namespace porosph::coupler {

CoupledStepLoop::CoupledStepLoop(const scene::Scene& scene, SolverHub& hub, RunRecord& record,
                                 const std::string& out_dir, std::function<void()> check_alive,
                                 std::function<int()> interrupt_signal,
                                 std::function<void()> write_outputs, const LoopState* resumed)
    : scene_(scene),
      hub_(hub),
      record_(record),
      check_alive_(std::move(check_alive)),
      interrupt_signal_(std::move(interrupt_signal)),
      write_outputs_(std::move(write_outputs)),
      checkpoints_(scene, out_dir, scene.phases(), resumed ? record.checkpoint_index : 0,
                   record.time),
      phases_(scene.phases()),
      controller_(scene.run.dt0, scene.run.dt_smoothing),
      hub_bytes_received_start_(hub.bytes_received()),
      hub_bytes_sent_start_(hub.bytes_sent()),
      record_bytes_received_start_(record.transport_bytes_received),
      record_bytes_sent_start_(record.transport_bytes_sent) {
  if (scene.has_water() && scene.has_soil()) {
    // The solvers compute their own rates while the coupler sums the interaction
    // (proto/solver_runtime.h): leave them their cores. Threads beyond the cores only wait.
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int solvers = static_cast<int>(phases_.size());
    interaction_ = std::make_unique<SoilWaterInteraction>(scene, std::max(1, cores - solvers));
    record_.interaction.active = true;
    record_.interaction.terms = interaction_->terms();
  }
  const std::string csv = out_dir + "/timeseries.csv";
  if (resumed) {  // rows after the checkpoint (a killed run wrote them) go
    loop_ = *resumed;
    controller_.restore(resumed->controller_dt);
    timeseries_ =
        std::make_unique<io::TimeSeriesCsv>(csv, timeseries_columns(), resumed->row_index);
  } else {
    timeseries_ = std::make_unique<io::TimeSeriesCsv>(csv, timeseries_columns());
  }
}

std::vector<std::string> CoupledStepLoop::timeseries_columns() const {
  std::vector<std::string> columns = scene::builtin_timeseries_columns(
      phases_, scene_.run.dimension, scene_.has_water() && scene_.has_soil());
  for (const auto& observable : scene_.observables) columns.push_back(observable.name);
  return columns;
}

void CoupledStepLoop::collect_states() {
  // Signals are polled once per step after the states are in (handle_checkpoint_and_signal), so
  // they stop a run whose solvers answer every step too. A dead solver never answers: the receive
  // below times out and check_alive_ names it - after any Error it queued before exiting, which is
  // the reason the user needs (checking it first here raced with that message).
  // received_ keeps its nodes between steps: resetting the flags allocates nothing.
  for (auto& [phase, flag] : received_) flag = false;
  std::size_t received_count = 0;
  const double timeout = scene_.run.solver_timeout;
  auto last_heard = Clock::now();
  Incoming& in = incoming_;
  while (received_count < phases_.size()) {
    // Receive first: a solver that reported an error and exited has its message queued, and
    // that message (not "exited with code N") is the reason the user needs.
    if (!hub_.receive(in, std::min(0.2, timeout))) {
      check_alive_();
      poll_signal();  // a second signal while waiting stops at once
      const int signal = pending_signal_ != 0 ? pending_signal_ : stopping_signal_;
      if (signal != 0 && seconds_since(signal_seen_) > kSignalGraceSeconds) {
        throw std::runtime_error("interrupted by signal " + std::to_string(signal) +
                                 "; no checkpoint: the solvers did not reach it within " +
                                 std::to_string(static_cast<int>(kSignalGraceSeconds)) + " s");
      }
      if (seconds_since(last_heard) > timeout) {
        std::string silent;
        for (const auto& phase : phases_) {
          if (!received_[phase]) silent += (silent.empty() ? "" : ", ") + phase;
        }
        std::ostringstream msg;
        msg << "the " << silent << " solver did not answer within " << timeout
            << " s (run.solver_timeout) at step " << record_.steps << ", t = " << record_.time
            << " s";
        throw std::runtime_error(msg.str());
      }
      continue;
    }
    last_heard = Clock::now();
    switch (in.kind) {
      case Incoming::Kind::State:
        absorb_state(in.phase, in.state);
        if (!received_[in.phase]) ++received_count;
        received_[in.phase] = true;
        break;
      case Incoming::Kind::Error: {
        std::ostringstream msg;
        msg << "the " << in.phase << " solver failed at step " << in.error_step
            << ", t = " << in.error_time << " s";
        if (in.error_particle_id >= 0) msg << ", particle " << in.error_particle_id;
        msg << ": " << in.error_message;
        throw std::runtime_error(msg.str());
      }
      case Incoming::Kind::Goodbye:
        throw std::runtime_error("the " + in.phase + " solver left before the end of the run");
      case Incoming::Kind::Hello:
        hub_.send_error(in.phase, "unexpected hello: a " + in.phase + " solver is already running");
        break;
    }
  }
  // A started solver that is gone fails the run even while messages keep coming (the wait above
  // looks only when the wire falls silent).
  check_alive_();
}

void CoupledStepLoop::absorb_state(const std::string& phase, coupling::StepState& state) {
  const double tolerance = 1e-9 * std::max(1.0, std::abs(record_.time));
  if (std::abs(state.time - record_.time) > tolerance) {
    std::ostringstream msg;
    msg << "the " << phase << " solver is at t = " << state.time
        << " s, the coupler at t = " << record_.time
        << " s: the solver did not advance by the shared dt";
    throw std::runtime_error(msg.str());
  }
  const auto& reported = state.diagnostics;
  if (!std::isfinite(reported.kinetic_energy) || !std::isfinite(reported.mass) ||
      !(state.dt_limit > 0)) {
    std::ostringstream msg;
    msg << "the " << phase << " solver reported a non-finite state at step " << record_.steps
        << ", t = " << record_.time << " s (kinetic energy " << reported.kinetic_energy << ", mass "
        << reported.mass << ", dt limit " << state.dt_limit << ")";
    throw std::runtime_error(msg.str());
  }
  for (const coupling::OutputField& field : reported.output_fields) {
    if (const std::string bad = output_field_problem(field, scene_.run.dimension); !bad.empty())
      throw std::runtime_error("the " + phase + " solver declared a bad output field: " + bad);
  }
  // Completes the state from the previous one where the message left parts out (a delta); arrays
  // sent whole are swapped in, not copied.
  coupling::apply_state_delta(states_[phase], state, scene_.run.dimension, phase);
  const auto& d = states_[phase].diagnostics;
  PhaseRecord& phase_record = record_.phases[phase];
  if (record_.steps == 0) phase_record.initial = d;
  phase_record.last = d;
  if (!d.terms.empty()) phase_record.terms = d.terms;  // sent with the first state only
  if (!d.output_fields.empty()) phase_record.output_fields = d.output_fields;  // and these
  phase_record.external.add(d, scene_.run.dimension, phase);  // the last advance's impulses
  phase_record.reported.wall_seconds += d.wall_seconds;
  phase_record.reported.physics_seconds += d.physics_seconds;
  phase_record.reported.communication_seconds += d.communication_seconds;
  if (phase == "water" && scene_.water) {  // coupler/run_watch.h; the limit: sph/mach_watch.h
    const std::string warning = note_mach(record_.mach, d.max_speed, scene_.water->sound_speed,
                                          record_.time, record_.steps);
    if (!warning.empty()) std::fprintf(stderr, "coupler: %s\n", warning.c_str());
  }
  for (const auto& observable : scene_.observables) {
    if (observable.phase != phase) continue;
    const auto it = d.observables.find(observable.name);
    record_.observables[observable.name] =
        it == d.observables.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
    const std::string problem =
        it == d.observables.end() ? "" : observable_problem(observable, it->second, d.free_count);
    if (!problem.empty()) {
      std::ostringstream msg;
      msg << "the " << phase << " solver reported " << problem << " at step " << record_.steps
          << ", t = " << record_.time << " s";
      throw std::runtime_error(msg.str());
    }
  }
}

void CoupledStepLoop::append_timeseries_row(double dt) {
  row_.assign({record_.time, dt});
  for (const std::string& phase : phases_) {
    const auto& state = states_.at(phase);
    const auto& d = state.diagnostics;
    row_.push_back(d.kinetic_energy);
    for (int k = 0; k < scene_.run.dimension; ++k) {
      row_.push_back(k < static_cast<int>(d.momentum.size()) ? d.momentum[k] : 0.0);
    }
    row_.push_back(d.mass);
    row_.push_back(static_cast<double>(d.particle_count));
    row_.push_back(static_cast<double>(d.removed_count));
    row_.push_back(static_cast<double>(state.overlap_id.size()));
    row_.push_back(d.inflow_mass);
    row_.push_back(d.outflow_mass);
    PhaseRecord& phase_record = record_.phases[phase];
    phase_record.note_mass_balance(d);
    // The momentum balance up to t: the books through this state, the interaction before this
    // step's (momentum_balance.h).
    const MomentumBalance balance = phase_momentum_balance(record_, phase);
    for (double impulse : balance.external) row_.push_back(impulse);
    ExternalImpulseRecord& books = phase_record.external;
    const double residual = books.booked() ? balance.relative : 0.0;
    books.relative_residual_max = std::max(books.relative_residual_max, residual);
    row_.push_back(residual);
  }
  if (interaction_) {
    for (double impulse : record_.ledger.impulse_to_soil) row_.push_back(impulse);
    for (double impulse : record_.ledger.impulse_to_water) row_.push_back(impulse);
    row_.push_back(static_cast<double>(interaction_summary_.pair_count));
  }
  for (const auto& observable : scene_.observables) {
    row_.push_back(record_.observables[observable.name]);
  }
  timeseries_->append(row_);
}

void CoupledStepLoop::send_commands(double dt, bool write_output, std::uint32_t output_index,
                                    bool stop, std::uint32_t checkpoint_index) {
  for (const std::string& phase : phases_) {
    coupling::StepCommand& command = commands_[phase];
    command.step = record_.steps;
    command.time = record_.time;
    command.dt = dt;
    command.write_output = write_output;
    command.output_index = output_index;
    command.stop = stop;
    command.write_checkpoint = checkpoint_index > 0;
    command.checkpoint_index = checkpoint_index;
    // A scene with a single phase exchanges no interaction (docs/design.md section 1). The vectors
    // are assigned in place: their storage is reused from step to step.
    command.interaction_acceleration.clear();
    command.interaction_rate.clear();
    command.saturation.clear();
    command.porosity.clear();
    wall_speeds_from(scene_, record_.observables, command.wall_speed);  // observable_feedback.h
    load_forces_from(scene_, record_.observables, command.load_force);
    command.other_region_min.clear();
    command.other_region_max.clear();
    if (interaction_) {
      const bool soil = phase == "soil";
      // The accelerations already hold the implicit drag over dt (finish_step): the solvers add
      // them explicitly.
      interaction_->hand_over(soil, command.interaction_acceleration, command.saturation);
      // The porosity the water sees is output only: sent with the snapshots it goes into.
      if (!soil && write_output) interaction_->hand_over_porosity(command.porosity);
      // The water's drag rates set how much artificial viscosity the drag replaces there.
      if (!soil) interaction_->hand_over_water_rate(command.interaction_rate);
      overlap_region_for(states_.at(soil ? "water" : "soil"), scene_, command.other_region_min,
                         command.other_region_max);
    }
    hub_.send_command(phase, command);
  }
}

double CoupledStepLoop::compute_interaction() {
  if (!interaction_) return std::numeric_limits<double>::infinity();
  const auto start = Clock::now();
  const coupling::StepState& water = states_.at("water");
  const coupling::StepState& soil = states_.at("soil");
  interaction_summary_ = interaction_->compute(water, soil, record_.time);
  record_.interaction.add_step(interaction_summary_.evaluated, interaction_summary_.pair_count,
                               water.overlap_id.size(), soil.overlap_id.size(),
                               interaction_summary_.dt_limit, seconds_since(start));
  return interaction_summary_.dt_limit;
}

void CoupledStepLoop::wait_for_goodbyes() {
  std::map<std::string, bool> said;
  const auto start = Clock::now();
  Incoming in;
  while (said.size() < phases_.size()) {
    if (seconds_since(start) > scene_.run.solver_timeout) {
      throw std::runtime_error("a solver did not finish within run.solver_timeout after the end");
    }
    if (!hub_.receive(in, 0.2)) {
      check_alive_();
      continue;
    }
    if (in.kind == Incoming::Kind::Error) {
      throw std::runtime_error("the " + in.phase +
                               " solver failed while finishing: " + in.error_message);
    }
    if (in.kind != Incoming::Kind::Goodbye) continue;
    PhaseRecord& phase_record = record_.phases[in.phase];
    phase_record.timing = in.timing;
    phase_record.finished = true;
    said[in.phase] = true;
  }
}

void CoupledStepLoop::run(ProgressLine& progress) {
  const double end_time = scene_.run.end_time;
  const double interval = scene_.run.output_interval;
  const double row_interval =
      scene_.run.timeseries_interval > 0.0 ? scene_.run.timeseries_interval : interval;
  const double end_tolerance = 1e-9 * end_time;
  const auto max_steps = static_cast<std::uint64_t>(std::max(0L, scene_.run.max_steps));
  for (;;) {
    collect_states();
    const auto work_start = Clock::now();
    if (loop_.outputs_pending) {
      write_outputs_();  // the solvers wrote their snapshot before sending this state
      loop_.outputs_pending = false;
    }
    const bool force_checkpoint = handle_checkpoint_and_signal();
    const bool step_limit_reached = max_steps > 0 && record_.steps >= max_steps;
    const bool stop = record_.time >= end_time - end_tolerance || step_limit_reached;
    bool write = record_.time >= loop_.next_output_time - 1e-9 * interval;
    if (stop && loop_.last_output_time != record_.time) write = true;  // always a final snapshot
    bool row = record_.time >= loop_.next_row_time - 1e-9 * row_interval;
    if (stop && loop_.last_row_time != record_.time) row = true;  // and a final row
    // Eq. 21 with the interaction of this step; the solvers' own dt_force already includes the
    // interaction of the previous step.
    const double dt_interaction = compute_interaction();
    double dt = 0.0, dt_min = dt_interaction;
    if (!stop) {
      for (const auto& [phase, state] : states_) dt_min = std::min(dt_min, state.dt_limit);
      dt = std::min(controller_.next(dt_min), end_time - record_.time);
    }
    if (write) {
      for (const std::string& phase : phases_) {
        record_.phases[phase].snapshots.push_back(
            {loop_.output_index, record_.time, states_.at(phase).diagnostics.particle_count});
      }
      loop_.last_output_time = record_.time;
    }
    if (row) {
      append_timeseries_row(dt);  // cumulative impulses up to t: before this step's
      loop_.last_row_time = record_.time;
      ++loop_.row_index;
      loop_.next_row_time = static_cast<double>(loop_.row_index) * row_interval;
    }
    if (interaction_ && interaction_summary_.forces) {
      interaction_->finish_step(states_.at("water"), states_.at("soil"), dt);
      const InteractionOutputs& o = interaction_->outputs();
      record_.ledger.add_step(dt, o.force_on_water, o.force_on_soil, o.force_magnitude_sum);
      record_.ledger.add_explicit_share(dt, o.explicit_force_on_water, o.explicit_force_on_soil);
    }
    const bool final_step = record_.time + dt >= end_time - end_tolerance ||
                            (max_steps > 0 && record_.steps + 1 >= max_steps);
    const bool checkpoint =
        !stop && checkpoints_.due(record_.time, dt, final_step, force_checkpoint);
    send_commands(dt, write, loop_.output_index, stop, checkpoint ? checkpoints_.begin() : 0);
    if (write) {
      ++loop_.output_index;
      loop_.next_output_time = loop_.output_index * interval;
      loop_.outputs_pending = true;
    }
    record_.coupler_seconds += seconds_since(work_start);
    record_.transport_bytes_received =
        record_bytes_received_start_ + (hub_.bytes_received() - hub_bytes_received_start_);
    record_.transport_bytes_sent =
        record_bytes_sent_start_ + (hub_.bytes_sent() - hub_bytes_sent_start_);
    if (stop) break;
    record_.time += dt;
    record_.steps += 1;
    record_.record_dt(dt, dt_min);
    if (checkpoint) {  // the state at the new step boundary, written once the solvers confirm
      loop_.controller_dt = controller_.current();
      record_.update_wall_seconds();
      checkpoints_.hold(coupler_state_json(record_, loop_), record_.time, record_.steps);
    }
    progress.update(record_.time, record_.steps, dt);
    if (heartbeat_) heartbeat_();
  }
  wait_for_goodbyes();
  progress.finish(record_.time, record_.steps);
}

}  // namespace porosph::coupler
