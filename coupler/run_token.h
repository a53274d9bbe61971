// The secret of one run (docs/protocol.md, "Who can connect"): drawn by the coupler's SolverHub,
// handed to the solvers the coupler starts in POROSPH_RUN_TOKEN (printed with --attach), carried
// by every message a solver sends.
#pragma once

#include <string>
#include <string_view>

namespace porosph::coupler {

/// 32 bytes from the kernel's random source (getrandom) as 64 hex digits. Throws
/// std::runtime_error when there is no random source.
std::string fresh_run_token();

/// What a stranger claims about itself, fit for the log: printable ASCII, at most 64 characters.
std::string printable(std::string_view claimed);

}  // namespace porosph::coupler
