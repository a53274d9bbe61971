// Everything the coupler learns during a run, and how it becomes run.json / run.xdmf.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "coupler/momentum_balance.h"
#include "coupler/run_watch.h"
#include "io/xdmf_writer.h"
#include "proto/coupling_client.h"

namespace porosph::coupler {

/// Impulse given to each phase by the interaction (docs/design.md section 1). The pair force is
/// antisymmetric, so the two totals cancel to round-off; relative_imbalance() is what tests assert.
struct ConservationLedger {
  std::vector<double> impulse_to_water;  ///< sum over steps of dt * sum_a m_a a_a^interaction
  std::vector<double> impulse_to_soil;   ///< sum over steps of dt * sum_i m_i^s a_i^interaction
  /// sum over steps of dt * (sum_i |m_i^s a_i| + sum_a |m_a a_a|): the scale of the round-off
  /// against which the imbalance is measured.
  double impulse_magnitude_sum = 0;
  /// The explicit share: dt * the explicit drag at the states' velocities (the paper's scheme);
  /// impulse_to_* minus these is the implicit share (soil_water_interaction.h).
  std::vector<double> explicit_impulse_to_water, explicit_impulse_to_soil;

  explicit ConservationLedger(int dimension = 2)
      : impulse_to_water(dimension, 0.0),
        impulse_to_soil(dimension, 0.0),
        explicit_impulse_to_water(dimension, 0.0),
        explicit_impulse_to_soil(dimension, 0.0) {}
  /// Books one step of length dt with the interaction forces sum_a m_a a_a (`force_on_water`),
  /// sum_i m_i^s a_i (`force_on_soil`) and the sum of the per-particle force magnitudes.
  void add_step(double dt, const std::vector<double>& force_on_water,
                const std::vector<double>& force_on_soil, double force_magnitude_sum);
  /// Books the explicit share of one step (forces as in add_step).
  void add_explicit_share(double dt, const std::vector<double>& force_on_water,
                          const std::vector<double>& force_on_soil);
  /// |sum of both impulses| / impulse_magnitude_sum; 0 when nothing was exchanged.
  double relative_imbalance() const;
};

/// The coupler's soil-water interaction over the run (scenes with both phases).
struct InteractionRecord {
  bool active = false;            ///< the scene has both phases (run.json then has "interaction")
  std::uint64_t evaluations = 0;  ///< steps on which both overlap sets were non-empty
  std::uint64_t pairs_min = 0, pairs_max = 0, pairs_last = 0;
  double pairs_sum = 0;  ///< over the evaluations (mean = pairs_sum / evaluations)
  std::uint64_t water_overlap_max = 0, soil_overlap_max = 0;  ///< largest overlap sets
  double seconds = 0;  ///< coupler wall time in the interaction (part of coupler_seconds)
  double dt_limit_min = std::numeric_limits<double>::infinity();  ///< smallest eq. 21 limit [s]
  std::vector<std::string> terms;  ///< the interaction terms of the scene (run.json)

  /// Books one step: `evaluated` false when an overlap set was empty (pairs = 0).
  void add_step(bool evaluated, std::uint64_t pairs, std::uint64_t water_overlap,
                std::uint64_t soil_overlap, double dt_limit, double seconds);
};

struct PhaseRecord {
  std::string phase;
  std::string executable;  ///< empty in attach mode
  std::string solver_name, solver_version;
  std::int64_t pid = 0;
  std::string h5_file;  ///< relative to the run directory
  coupling::Diagnostics initial;
  coupling::Diagnostics last;
  std::vector<io::XdmfSnapshot> snapshots;
  coupling::Timing timing;  ///< the solver's Goodbye: this process only (not earlier segments)
  std::vector<std::string> terms;  ///< the physics terms the solver reported (run.json)
  /// The fields of its snapshot file the solver declared (first state); empty: none declared.
  std::vector<coupling::OutputField> output_fields;
  bool finished = false;  ///< said Goodbye
  /// Summed from the per-state reports over all the run's segments (checkpointed).
  coupling::Timing reported;
  /// `reported` at the checkpoint this segment resumed from: the earlier segments' share.
  coupling::Timing before_resume;
  /// The largest |mass - (initial + inflow - outflow)| / (initial + inflow - outflow) over the
  /// outputs so far (checkpointed).
  double mass_imbalance_max = 0.0;

  /// The mass balance of an output's diagnostics (against `initial`).
  double mass_imbalance(const coupling::Diagnostics& d) const {
    const double expected = initial.mass + d.inflow_mass - d.outflow_mass;
    return expected > 0.0 ? std::abs(d.mass - expected) / expected : 0.0;
  }
  void note_mass_balance(const coupling::Diagnostics& d) {
    mass_imbalance_max = std::max(mass_imbalance_max, mass_imbalance(d));
  }
  /// The external-impulse books of the phase's solver (checkpointed; momentum_balance.h).
  ExternalImpulseRecord external;
};

/// The phase's wall, physics and communication seconds over all the run's segments: the earlier
/// segments' reports plus the Goodbye of this one, or the reports alone when the solver did not
/// say Goodbye (it failed). A solver that leaves the optional per-state wall / communication
/// fields at 0 gets only its last segment's figures.
coupling::Timing phase_timing(const PhaseRecord& phase);

struct RunRecord {
  std::string status = "running";  ///< "running" | "completed" | "failed"
  std::string message;
  std::string scene_name;
  std::string scene_path;
  std::string resolved_toml;
  int dimension = 2;
  std::uint64_t steps = 0;
  double time = 0;
  double end_time = 0;
  double wall_seconds = 0;     ///< all segments of the run; refreshed by update_wall_seconds()
  double coupler_seconds = 0;  ///< coupler's own work: interaction, dt, bookkeeping, I/O
  double dt_min = std::numeric_limits<double>::infinity();
  double dt_max = 0;
  double dt_sum = 0;
  double dt_over_limit_max = 0;  ///< max over the steps of dt / (smallest limit): <= 1
  std::map<std::string, PhaseRecord> phases;
  ConservationLedger ledger;
  InteractionRecord interaction;
  std::map<std::string, double> observables;  ///< latest value of every observable
  MachRecord mach;            ///< the water's largest Mach number (coupler/run_watch.h)
  std::uint32_t resumes = 0;  ///< times this run was resumed from a checkpoint (--resume)
  /// Payload bytes of the messages of the step loop (states, errors, goodbyes received; commands
  /// sent), without ZeroMQ's framing: the coupling's data volume.
  std::uint64_t transport_bytes_received = 0, transport_bytes_sent = 0;
  /// Messages the coupler dropped in this session (no or a wrong run token, a sender that is no
  /// phase's solver; docs/protocol.md): run.json "transport.dropped_messages".
  std::uint64_t dropped_messages = 0;
  /// The latest checkpoint: index (0: none yet), simulated time and step.
  std::uint32_t checkpoint_index = 0;
  double checkpoint_time = 0;
  std::uint64_t checkpoint_step = 0;
  /// The coupler process of this session (run.json "coupler": pid, host, and the heartbeat: the
  /// UTC time of each rewrite), so that a reader can tell a live run from a dead one.
  std::int64_t coupler_pid = 0;
  std::string coupler_host;

  /// Books one step's dt and the smallest of that step's limits (solvers' CFL, viscous, eq. 21
  /// and the interaction's eq. 21).
  void record_dt(double dt, double dt_limit);
  /// Starts this process's segment of the run: wall_seconds counts on from its current value
  /// (0, or the checkpoint's on a resume).
  void start_segment();
  /// wall_seconds = the earlier segments' + this segment's so far (before run.json and each
  /// checkpoint, so that a checkpoint holds the wall time up to its own step).
  void update_wall_seconds();

 private:
  std::chrono::steady_clock::time_point segment_start_ = std::chrono::steady_clock::now();
  double wall_seconds_before_segment_ = 0;
};

/// The interaction's impulse to `phase` booked so far (the ledger's; null for another phase).
const std::vector<double>* exchange_impulse(const RunRecord& record, const std::string& phase);

/// The momentum balance of `phase` (momentum_balance.h) at its latest state.
MomentumBalance phase_momentum_balance(const RunRecord& record, const std::string& phase);

/// Writes run.json (atomically: temp file + rename; "coupler.heartbeat_utc" the time of writing).
/// Throws std::runtime_error naming the file and the system's reason.
void write_run_json(const std::string& path, const RunRecord& record);

/// run.xdmf's content: every phase with snapshots whose HDF5 file exists in `out_dir` (a solver
/// need not write one, docs/solver-protocol.md: its phase is left out, with a note on stderr the
/// first time, remembered in `phases_without_h5`).
std::vector<io::XdmfPhaseSeries> xdmf_series(const RunRecord& record, const std::string& out_dir,
                                             std::set<std::string>& phases_without_h5);

/// The fields run.xdmf lists for a phase: those its solver declared, or, for a solver that
/// declared none, snapshot_fields_of_phase() (with the pore fields where the built-in water
/// solver runs in a scene with soil).
std::vector<io::XdmfField> xdmf_fields_of(const RunRecord& record, const PhaseRecord& phase);

/// What is wrong with a field a solver declared (empty: nothing): its name must be a dataset name
/// run.xdmf can carry ([A-Za-z0-9_.-], not "position"), components 1, D or 9, the type Float,
/// Int or UChar, the unit printable without quotes or angle brackets.
std::string output_field_problem(const coupling::OutputField& field, int dimension);

/// The fields each built-in phase writes besides position (docs/design.md section 6); with
/// `pore_fields` the water's porosity and pore_velocity too (the built-in water solver in a scene
/// with soil, docs/water-in-soil.md).
std::vector<io::XdmfField> snapshot_fields_of_phase(const std::string& phase, int dimension,
                                                    bool pore_fields = false);

/// The name the built-in water solver gives in its Hello (fluid_solver/main.cpp).
inline constexpr const char* kBuiltInWaterSolverName = "porosph-water";

/// The HDF5 file name of a phase in the run directory ("water.h5", "soil.h5").
std::string h5_file_of_phase(const std::string& phase);

}  // namespace porosph::coupler
