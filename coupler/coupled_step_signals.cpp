// The coupled step loop's handling of interrupting signals and checkpoints: a first SIGINT or
// SIGTERM asks the next step for a checkpoint and stops after it; a second one stops at once.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>

#include "coupler/coupled_step.h"
#include "coupler/coupled_step_clock.h"

namespace porosph::coupler {

void CoupledStepLoop::poll_signal() {
  const int signal = interrupt_signal_();
  if (signal == 0) return;
  if (pending_signal_ != 0 || stopping_signal_ != 0) {
    throw std::runtime_error("interrupted by signal " + std::to_string(signal) +
                             " a second time; stopped without waiting for a checkpoint");
  }
  pending_signal_ = signal;
  signal_seen_ = Clock::now();
}

bool CoupledStepLoop::handle_checkpoint_and_signal() {
  poll_signal();
  if (checkpoints_.pending()) {
    const std::string problem = checkpoints_.complete(states_);
    if (!problem.empty()) {
      checkpoints_.disable();
      if (stopping_signal_ != 0) {
        throw std::runtime_error("interrupted by signal " + std::to_string(stopping_signal_) +
                                 "; no checkpoint written: " + problem);
      }
      std::fprintf(stderr, "coupler: checkpoints disabled: %s\n", problem.c_str());
    } else {
      record_.checkpoint_index = checkpoints_.last_index();
      record_.checkpoint_time = checkpoints_.last_time();
      record_.checkpoint_step = checkpoints_.last_step();
      if (stopping_signal_ == 0 && pending_signal_ != 0) stopping_signal_ = pending_signal_;
      if (stopping_signal_ != 0) stop_after_signal();  // a fresh checkpoint: no need for another
    }
  }
  if (pending_signal_ == 0 || stopping_signal_ != 0) return false;
  const int signal = pending_signal_;
  if (record_.time > 0.0 && checkpoints_.enabled()) {
    stopping_signal_ = signal;
    return true;  // this step's command asks for the checkpoint
  }
  throw std::runtime_error("interrupted by signal " + std::to_string(signal) +
                           (record_.time > 0.0 ? "; no checkpoint (checkpoints are disabled)"
                                               : "; no checkpoint at t = 0"));
}

void CoupledStepLoop::stop_after_signal() {
  send_commands(0.0, false, loop_.output_index, true);
  wait_for_goodbyes();
  std::ostringstream msg;
  const std::string out_dir =
      std::filesystem::path(checkpoints_.directory()).parent_path().string();
  msg << "interrupted by signal " << stopping_signal_
      << "; checkpoint at t = " << checkpoints_.last_time() << " s in " << checkpoints_.directory()
      << " (resume with coupler run --resume " << out_dir << ")";
  throw std::runtime_error(msg.str());
}

}  // namespace porosph::coupler
