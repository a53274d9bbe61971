// How big a run will be, before any particle exists (issue 29): `coupler check` prints the
// estimate and both `check` and `run` refuse (exit 2) a run that does not fit this machine -
// memory, disk, or a senseless number of snapshots - unless given --force-size. The numbers and
// where they come from are in run_size.cpp; docs/reliability.md states the rules.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace porosph::coupler {

/// At most this many snapshots without --force-size (a snapshot per step of a long run is a
/// mistake: run.output_interval far below the time step, or an end_time far beyond the need).
inline constexpr double kMaxSnapshots = 10000;
/// The share of the physical memory a run may plan to use, and of the free disk space its outputs.
inline constexpr double kMemoryShare = 0.8;
inline constexpr double kDiskShare = 0.9;

/// The particles one phase's solver holds at t = 0 (estimated from the lattice, as doubles: a
/// count beyond any integer still compares).
struct PhaseSize {
  std::string phase;
  double free_particles = 0.0;  ///< its blocks (particles inside walls not subtracted)
  double wall_particles = 0.0;  ///< the walls acting on it (each phase holds its own copy)
  double snapshot_bytes = 0.0;  ///< bytes one particle takes in a snapshot of this phase
};

struct RunSizeEstimate {
  std::vector<PhaseSize> phases;
  double particles = 0.0;     ///< all phases, walls included
  double memory_bytes = 0.0;  ///< the solver and coupler processes together, at their peak
  double time_step = 0.0;     ///< the expected dt (scene/scene_sanity.h) [s]
  double steps = 0.0;         ///< end_time / dt, or max_steps if smaller
  double snapshots = 0.0;     ///< outputs written (at most one per step, plus t = 0)
  double output_bytes = 0.0;  ///< snapshots x particles x bytes per particle (the HDF5 files)
};

/// What this machine offers a run whose directory is `run_dir`.
struct MachineLimits {
  double memory_bytes = 0.0;     ///< physical memory (sysconf)
  double disk_free_bytes = 0.0;  ///< free space of the file system of run_dir (statvfs)
  std::string disk_path;         ///< the existing directory measured (run_dir or its ancestor)
};

RunSizeEstimate estimate_run_size(const scene::Scene& scene);

/// The lattice count of one block or wall at spacing dp in `dimension` (containers: the wall
/// layers only).
double estimated_shape_particles(const scene::Shape& shape, double dp, int dimension);

MachineLimits machine_limits(const std::string& run_dir);

/// "# size: ~4928 particles (water 3200 + 1728 wall), ~78 MB of memory, ~2000 steps, 51
/// snapshots, ~16 MB of output" (one line, for `coupler check` and the run's log).
std::string describe_run_size(const RunSizeEstimate& size);

/// Empty when the run fits `limits`; else why not, starting with "file:line: key 'k': " of the
/// key to change (run.dp for memory, run.output_interval for snapshots and disk) and ending with
/// how to insist (--force-size).
std::string run_size_problem(const scene::Scene& scene, const RunSizeEstimate& size,
                             const MachineLimits& limits);

}  // namespace porosph::coupler
