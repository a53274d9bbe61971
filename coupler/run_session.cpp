#include "coupler/run_session.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>

#include "coupler/checkpoint.h"
#include "coupler/coupled_step.h"
#include "coupler/coupled_step_clock.h"
#include "coupler/progress_line.h"
#include "coupler/resume_point.h"
#include "coupler/run_directory.h"
#include "coupler/run_errors.h"
#include "coupler/run_record.h"
#include "coupler/scene_check.h"
#include "coupler/solver_hub.h"
#include "coupler/solver_launch.h"
#include "coupler/solver_process.h"
#include "coupler/thin_walls.h"
#include "proto/checkpoint_names.h"
#include "scene/scene_loader.h"

namespace porosph::coupler {

namespace {

namespace fs = std::filesystem;

/// Set by SIGINT/SIGTERM; the only process-wide state, as a signal handler can reach nothing else.
/// The step loop takes (and clears) it, so that a second signal is seen as such.
std::atomic<int> interrupt_signal{0};
extern "C" void on_interrupt(int signal) { interrupt_signal.store(signal); }

class RunSession {
 public:
  explicit RunSession(const RunOptions& options) : options_(options) {}

  int run();

 private:
  void prepare_output_dir();
  /// --resume: the run directory, the record and loop state of its latest checkpoint, the scene.
  void load_resume_point();
  /// The scene from the file and --set, and a fresh run directory.
  void load_fresh_run();
  void start_solvers();
  void handshake();
  void check_interrupt() const;
  void check_solvers_alive();
  /// The run's failure message for `e`: a solver found dead after a lost connection is named.
  std::string failure_reason(const std::exception& e);
  void shut_down_after_failure(const std::string& reason);
  void write_outputs();
  /// Rewrites run.json (its heartbeat with it).
  void write_record();

  /// run.json is rewritten at least this often while a run goes on (its heartbeat).
  static constexpr double kHeartbeatSeconds = 30.0;

  RunOptions options_;
  std::unique_ptr<RunDirectoryLock> lock_;  ///< held for the session's life
  Clock::time_point last_record_write_ = Clock::now();
  scene::Scene scene_;
  RunRecord record_;  ///< its wall clock starts with the session
  std::string out_dir_;
  std::unique_ptr<PrivateSocketDir> socket_dir_;  ///< the default socket's; outlives hub_
  std::unique_ptr<SolverHub> hub_;
  SolverProcesses processes_;
  std::optional<LoopState> resumed_;         ///< set when resuming
  std::set<std::string> phases_without_h5_;  ///< phases whose solver wrote no snapshot file
};

void RunSession::prepare_output_dir() {
  out_dir_ = options_.out_dir.empty() ? "runs/" + scene_.name : options_.out_dir;
  out_dir_ = fs::absolute(out_dir_).lexically_normal().string();
  if (out_dir_.size() > 1 && out_dir_.back() == '/') out_dir_.pop_back();
  try {
    lock_ = claim_run_directory(out_dir_, options_.overwrite);
  } catch (const RunDirectoryError& e) {
    throw BadInput(e.what());
  }
}

void RunSession::load_fresh_run() {
  try {
    scene_ = scene::load_scene_file(options_.scene_path, options_.overrides);
  } catch (const scene::SceneError& e) {
    throw BadInput(std::string("bad scene: ") + e.what());
  }
  record_.scene_name = scene_.name;
  record_.scene_path = options_.scene_path;
  record_.resolved_toml = scene_.resolved_toml;
  record_.dimension = scene_.run.dimension;
  record_.end_time = scene_.run.end_time;
  record_.ledger = ConservationLedger(scene_.run.dimension);
  const std::string refused = run_gate(scene_, options_.out_dir, options_.force_size);
  if (!refused.empty()) throw BadInput(refused);
  for (const std::string& warning : thin_wall_warnings(scene_))
    std::fprintf(stderr, "coupler: warning: %s\n", warning.c_str());
  prepare_output_dir();
}

void RunSession::load_resume_point() {
  ResumePoint point = coupler::load_resume_point(options_.resume_dir, record_);
  lock_ = std::move(point.lock);
  out_dir_ = point.out_dir;
  scene_ = std::move(point.scene);
  resumed_ = point.loop;
  std::fprintf(stderr, "coupler: resuming %s from checkpoint %u at t = %.9g s (step %llu)\n",
               out_dir_.c_str(), point.checkpoint_index, point.time,
               static_cast<unsigned long long>(point.step));
  for (const std::string& notice : point.newer_key_notices)
    std::fprintf(stderr, "coupler: %s\n", notice.c_str());
}

void RunSession::start_solvers() {
  try {
    hub_ = open_solver_hub(options_.endpoint, scene_, socket_dir_);
  } catch (const BadEndpoint& e) {
    if (options_.endpoint.empty()) throw RunFailure(e.what());
    throw BadInput(e.what());  // the user's --endpoint
  }
  const std::string connect = hub_->connect_endpoint();
  if (options_.attach) {
    std::fputs(
        attach_instructions(scene_.phases(), connect, hub_->run_token(), hub_->listens_everywhere())
            .c_str(),
        stderr);
    return;
  }
  for (const std::string& phase : scene_.phases()) {
    SolverCommand command;
    try {
      command = resolve_solver_command(phase, options_.solver_override(phase), scene_);
    } catch (const std::invalid_argument& e) {
      throw BadInput(e.what());
    }
    const std::string& requested = command.requested;
    const bool user_named = command.user_named;
    std::vector<std::string>& args = command.args;
    const std::string executable = find_solver_executable(args.front());
    args.erase(args.begin());
    args.insert(args.end(), {"--endpoint", connect});
    if (executable.empty()) {
      const std::string message =
          "cannot find the " + phase + " solver executable '" + requested + "'";
      if (user_named) throw BadInput(message);
      throw RunFailure(message);
    }
    try {
      processes_[phase] = std::make_unique<SolverProcess>(
          executable, args,
          solver_environment(connect, hub_->run_token(),
                             static_cast<unsigned>(scene_.phases().size())));
    } catch (const std::exception& e) {
      if (user_named) throw BadInput(e.what());
      throw RunFailure(e.what());
    }
    PhaseRecord& phase_record = record_.phases[phase];
    phase_record.phase = phase;
    phase_record.executable = executable;
    phase_record.pid = processes_[phase]->pid();
    phase_record.h5_file = h5_file_of_phase(phase);
  }
}

void RunSession::check_interrupt() const {
  if (const int signal = interrupt_signal.load()) {
    throw RunFailure(std::string("interrupted by signal ") + std::to_string(signal));
  }
}

void RunSession::check_solvers_alive() {
  std::string phase;
  if (SolverProcess* dead = exited_solver(processes_, &phase, 0.0))
    throw RunFailure(dead_solver_message(phase, *dead, record_.steps, record_.time));
}

std::string RunSession::failure_reason(const std::exception& e) {
  // A solver that died is the reason, not the lost connection the coupler met first.
  if (dynamic_cast<const SolverUnreachable*>(&e) == nullptr) return e.what();
  std::string phase;
  SolverProcess* dead = exited_solver(processes_, &phase, 2.0);
  if (dead == nullptr) return e.what();
  return dead_solver_message(phase, *dead, record_.steps, record_.time) + " (" + e.what() + ")";
}

void RunSession::handshake() {
  const auto expected = scene_.phases();
  std::map<std::string, bool> greeted;
  const double timeout = scene_.run.solver_timeout;
  const auto start = Clock::now();
  Incoming in;
  while (greeted.size() < expected.size()) {
    check_interrupt();
    check_solvers_alive();
    if (seconds_since(start) > timeout) {
      throw RunFailure("no solver said hello within " + std::to_string(timeout) +
                       " s (run.solver_timeout)");
    }
    if (!hub_->receive(in, 0.1)) continue;
    if (in.kind == Incoming::Kind::Error) {
      throw RunFailure("the " + in.phase + " solver failed during start-up: " + in.error_message);
    }
    if (in.kind != Incoming::Kind::Hello) continue;
    if (in.protocol_version != coupling::kProtocolVersion) {
      const std::string message = "protocol version mismatch: the " + in.phase + " solver '" +
                                  in.solver_name + "' speaks version " +
                                  std::to_string(in.protocol_version) + ", the coupler " +
                                  std::to_string(coupling::kProtocolVersion);
      hub_->send_error(in.phase, message);
      throw RunFailure(message);
    }
    if (std::find(expected.begin(), expected.end(), in.phase) == expected.end()) {
      hub_->send_error(in.phase, "this scene has no " + in.phase + " phase");
      continue;
    }
    PhaseRecord& phase_record = record_.phases[in.phase];
    phase_record.phase = in.phase;
    phase_record.solver_name = in.solver_name;
    phase_record.solver_version = in.solver_version;
    if (!processes_.count(in.phase)) phase_record.pid = in.pid;  // else the pid it was started as
    phase_record.h5_file = h5_file_of_phase(in.phase);
    greeted[in.phase] = true;
  }
  for (const std::string& phase : expected) {
    coupling::SetupData setup;
    setup.phase = phase;
    setup.scene_toml = scene_.resolved_toml;
    setup.scene_name = scene_.name;
    setup.output_dir = out_dir_;
    setup.dimension = scene_.run.dimension;
    setup.dp = scene_.run.dp;
    setup.h = scene_.h();
    setup.dt0 = scene_.run.dt0;
    setup.end_time = scene_.run.end_time;
    setup.gravity = scene_.run.gravity;
    setup.timeout_seconds = solver_side_timeout(timeout);  // longer: a stalled solver is named
    if (resumed_) {
      setup.restore_checkpoint =
          coupling::solver_checkpoint_path(out_dir_, phase, record_.checkpoint_index);
      setup.resume_output_index = resumed_->output_index;
    }
    hub_->send_setup(phase, setup);
  }
}

void RunSession::shut_down_after_failure(const std::string& reason) {
  if (hub_) {
    for (const auto& [phase, unused] : record_.phases) {
      try {
        hub_->send_shutdown(phase, reason);
      } catch (const std::exception&) {
        // The peer is gone already; terminating below covers it.
      }
    }
  }
  stop_solvers(processes_, 2.0);
}

void RunSession::write_outputs() {
  if (hub_) record_.dropped_messages = hub_->dropped_messages();
  const std::vector<io::XdmfPhaseSeries> series =
      xdmf_series(record_, out_dir_, phases_without_h5_);
  if (!series.empty()) io::write_xdmf(out_dir_ + "/run.xdmf", series);
  write_record();
}

void RunSession::write_record() {
  record_.update_wall_seconds();
  write_run_json(out_dir_ + "/run.json", record_);
  last_record_write_ = Clock::now();
}

int RunSession::run() {
  try {
    if (options_.resume_dir.empty()) {
      load_fresh_run();
    } else {
      load_resume_point();
    }
  } catch (const BadInput& e) {
    std::fprintf(stderr, "coupler: %s\n", e.what());
    return kBadInput;
  }
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  record_.coupler_pid = getpid();
  record_.coupler_host = host_name();
  int exit_code = kCompleted;
  try {
    start_solvers();
    write_record();  // status "running" with the coupler's pid and host from the start
    handshake();
    if (resumed_) write_outputs();  // run.xdmf lists the snapshots the checkpoint keeps
    CoupledStepLoop loop(
        scene_, *hub_, record_, out_dir_, [this] { check_solvers_alive(); },
        [] { return interrupt_signal.exchange(0); }, [this] { write_outputs(); },
        resumed_ ? &*resumed_ : nullptr);
    loop.set_heartbeat([this] {
      if (seconds_since(last_record_write_) >= kHeartbeatSeconds) write_record();
    });
    ProgressLine progress(scene_.run.end_time, options_.progress);
    loop.run(progress);
    record_.status = "completed";
    stop_solvers(processes_, 10.0);
  } catch (const BadInput& e) {
    record_.status = "failed";
    record_.message = e.what();
    shut_down_after_failure(e.what());
    exit_code = kBadInput;
  } catch (const std::exception& e) {
    record_.status = "failed";
    record_.message = failure_reason(e);
    shut_down_after_failure(record_.message);
    exit_code = kRunFailed;
  }
  processes_.clear();  // terminates and reaps anything still running
  try {
    write_outputs();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coupler: cannot write the run record: %s\n", e.what());
    if (exit_code == kCompleted) exit_code = kRunFailed;
  }
  if (exit_code == kCompleted) {
    std::fprintf(stderr,
                 "coupler: completed %llu steps to t = %.6g s in %.1f s wall time\n"
                 "coupler: results in %s (open run.xdmf in ParaView; run.json, timeseries.csv)\n",
                 static_cast<unsigned long long>(record_.steps), record_.time, record_.wall_seconds,
                 out_dir_.c_str());
  } else {
    std::fprintf(stderr, "coupler: run failed: %s\ncoupler: partial results in %s\n",
                 record_.message.c_str(), out_dir_.c_str());
  }
  return exit_code;
}

}  // namespace

int run_scene(const RunOptions& options) {
  RunSession session(options);
  return session.run();
}

}  // namespace porosph::coupler
