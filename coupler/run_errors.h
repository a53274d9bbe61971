// The two ways a coupled run fails, as `coupler run` tells them apart (docs/design.md section 6):
// a failure of the run itself (exit code 1) and one caused by what the user gave (exit code 2).
#pragma once

#include <stdexcept>

namespace porosph::coupler {

/// A failure of the run (not of the input): status "failed", exit code 1.
struct RunFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A failure caused by what the user gave us (scene, options, run directory): exit code 2.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace porosph::coupler
