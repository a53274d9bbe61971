// Solver side of the PoroSPH coupling, in the spirit of preCICE's Participant:
//   CouplingClient client(endpoint, identity);   // connect, handshake, receive the set-up
//   loop { command = client.exchange(state); if (command.stop) break; ... advance(command.dt) }
//   client.finalize(timing);
// This library is the only solver-side code that sees ZeroMQ or Protobuf; its API is plain C++.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::coupling {

inline constexpr std::uint32_t kProtocolVersion = 1;

struct SolverIdentity {
  std::string phase;  ///< "water" | "soil"
  std::string name;   ///< e.g. "porosph-water"
  std::string version;
  /// Announced in Hello. Leave it at kProtocolVersion; the test dummies override it to exercise the
  /// coupler's version check.
  std::uint32_t protocol_version = kProtocolVersion;
  /// The run's secret, sent with every message (docs/protocol.md, "Who can connect"). Empty: the
  /// value of POROSPH_RUN_TOKEN, which the coupler sets for the solvers it starts.
  std::string run_token;
};

/// What the coupler tells a solver before the first step.
struct SetupData {
  std::string phase;
  std::string scene_toml;  ///< resolved scene; parse with scene::load_scene_text
  std::string scene_name;
  std::string output_dir;
  int dimension = 2;
  double dp = 0, h = 0, dt0 = 0, end_time = 0;
  std::vector<double> gravity;
  double timeout_seconds = 60;
  /// Resume: the checkpoint file to restore before the first step (empty: start from the scene).
  std::string restore_checkpoint;
  /// Resume: snapshots with this index or higher are dropped from the phase's HDF5 file.
  std::uint32_t resume_output_index = 0;
};

/// One per-particle field of a solver's snapshot file (porosph.proto, OutputField).
struct OutputField {
  std::string name;
  std::uint32_t components = 1;       ///< 1, D or 9
  std::string number_type = "Float";  ///< "Float" | "Int" | "UChar"
  std::string unit;                   ///< SI; empty: none
};

struct Diagnostics {
  std::uint64_t particle_count = 0, free_count = 0, removed_count = 0;
  double mass = 0, kinetic_energy = 0, max_speed = 0;
  std::vector<double> momentum;
  std::map<std::string, double> observables;
  double physics_seconds = 0;  ///< since the last report, as the two below
  double wall_seconds = 0, communication_seconds = 0;
  double inflow_mass = 0, outflow_mass = 0;  ///< since t = 0: born in inflow zones, removed
  double neighbours_per_particle = 0;        ///< mean neighbour count of a free particle
  /// The physics terms the solver evaluates (first state only; empty afterwards).
  std::vector<std::string> terms;
  /// Optional external-impulse books (docs/coupling.md, "The external-impulse ledger"): the
  /// sources' names (first state only, like terms), and per source the impulse [N s] by which the
  /// last advance changed balance_momentum (sources x D, row-major; empty: no books).
  std::vector<std::string> impulse_sources;
  std::vector<double> external_impulse;
  /// The momentum the books balance where it is not `momentum` (the soil: sum m^s v, m^s the
  /// effective mass of its equation of motion); empty: `momentum`.
  std::vector<double> balance_momentum;
  /// The fields of the solver's snapshot file besides position (first state only, like terms).
  std::vector<OutputField> output_fields;
};

/// What a received state message left out (proto/state_delta.h). Solvers leave it at its
/// default: the client computes it when it sends; the coupler's hub fills it when it receives.
struct StateDelta {
  bool same_set = false;             ///< ids, masses, materials as in the previous state
  std::uint32_t unchanged_tail = 0;  ///< last K particles' per-step values as before
};

/// One solver's report after computing its accelerations for the current state.
/// Overlap arrays are flattened row-major (n*D for vectors).
struct StepState {
  std::uint64_t step = 0;
  double time = 0;
  double dt_limit = 0, dt_cfl = 0, dt_viscous = 0, dt_force = 0;
  std::vector<std::int64_t> overlap_id;
  std::vector<double> overlap_position, overlap_velocity, overlap_density, overlap_mass;
  std::vector<double> overlap_porosity;        ///< soil only
  std::vector<std::int32_t> overlap_material;  ///< soil only
  /// Optional (n*D or empty), for the pairwise implicit drag: the velocity without interaction at
  /// the end of the step is predicted as update_base + dt * update_rate (porosph.proto).
  std::vector<double> overlap_update_base, overlap_update_rate;
  std::vector<double> region_min, region_max;
  Diagnostics diagnostics;
  /// Index of the checkpoint written after the last advance (asked by the last command); 0: none.
  std::uint32_t checkpoint_written = 0;
  StateDelta delta;  ///< wire level: what the message left out (see StateDelta)

  /// Empties every overlap array (keeping their capacity: no allocation in steady state).
  void clear_overlap() {
    overlap_id.clear();
    overlap_position.clear();
    overlap_velocity.clear();
    overlap_density.clear();
    overlap_mass.clear();
    overlap_porosity.clear();
    overlap_material.clear();
    overlap_update_base.clear();
    overlap_update_rate.clear();
  }
};

/// The coupler's answer: the one shared dt and what else to do this step.
struct StepCommand {
  std::uint64_t step = 0;
  double time = 0;
  double dt = 0;
  bool write_output = false;
  std::uint32_t output_index = 0;
  bool stop = false;
  std::vector<double> interaction_acceleration;  ///< per overlap particle, n*D (may be empty)
  /// Water only, per overlap particle: the seepage drag rate lambda = -d(interaction
  /// acceleration)/d(own velocity) [1/s] (empty: no drag, or the explicit drag).
  std::vector<double> interaction_rate;
  std::vector<double> saturation;  ///< soil only
  /// Water only, with write_output: the soil porosity around each overlap particle (1 in free
  /// water; empty: no soil near). Output only (docs/water-in-soil.md).
  std::vector<double> porosity;
  /// Per [[walls]] entry of the scene (empty: none moves): its speed along its move_direction
  /// for this step [m/s] (docs/scene.md, walls[].moves_with).
  std::vector<double> wall_speed;
  /// Per [[soil.loads]] entry (empty: none takes one): the force added to it along the positive
  /// direction of its traction's axis [N/m^(3-D)] (docs/scene.md, soil.loads[].plus_force_from).
  std::vector<double> load_force;
  std::vector<double> other_region_min, other_region_max;
  /// After advancing, write checkpoint `checkpoint_index` (>= 1) and confirm it in the next state.
  bool write_checkpoint = false;
  std::uint32_t checkpoint_index = 0;
};

struct Timing {
  double wall_seconds = 0, physics_seconds = 0, communication_seconds = 0;
};

/// The coupler reported an error, asked to shut down, or fell silent past the timeout.
class CouplingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CouplingClient {
 public:
  /// Connects to `endpoint` (e.g. ipc:///tmp/x or tcp://host:port), sends Hello and blocks until
  /// Setup arrives (at most `connect_timeout_seconds`). Throws CouplingError.
  CouplingClient(const std::string& endpoint, const SolverIdentity& identity,
                 double connect_timeout_seconds = 60.0);
  ~CouplingClient();
  CouplingClient(const CouplingClient&) = delete;
  CouplingClient& operator=(const CouplingClient&) = delete;

  const SetupData& setup() const;

  /// Sends the state, waits for the coupler's command: send_state() then receive_command().
  const StepCommand& exchange(const StepState& state);

  /// Sends the state without waiting: the solver may work (e.g. compute its own rates) while the
  /// coupler computes the interaction; then receive_command(). Allocates nothing in steady state.
  void send_state(const StepState& state);

  /// Waits for the coupler's answer to the last state sent. The returned reference stays valid
  /// until the next call (its vectors are reused). Throws CouplingError on Shutdown/Error from the
  /// coupler or on timeout.
  const StepCommand& receive_command();

  /// Tells the coupler this solver failed (NaN, bad input...). Does not throw.
  void report_error(const std::string& message, std::uint64_t step, double time,
                    std::int64_t particle_id = -1) noexcept;

  /// Sends Goodbye with the timing figures; call after a command with stop = true. A zero
  /// `timing.communication_seconds` is replaced by communication_seconds().
  void finalize(const Timing& timing);

  /// Seconds spent inside exchange() (serialising, ZeroMQ, waiting for the coupler).
  double communication_seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Endpoint a solver should use when started by the coupler: the value of the environment variable
/// POROSPH_ENDPOINT, or the --endpoint argument when given (non-empty `cli_value` wins).
std::string resolve_endpoint(const std::string& cli_value);

/// The environment variable that carries the run token to a solver.
inline constexpr const char* kRunTokenVariable = "POROSPH_RUN_TOKEN";

/// The run token a solver sends: the value of POROSPH_RUN_TOKEN ("" when unset; the coupler then
/// refuses the solver's Hello and says why).
std::string resolve_run_token();

}  // namespace porosph::coupling
