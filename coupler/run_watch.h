// What the coupler watches in the solvers' reports besides finiteness (issue 29, "no silent
// nonsense"; docs/reliability.md): the water's Mach number (warned about once above
// scene::kMachWarn and recorded in run.json; the water solver itself fails the run above
// scene::kMachLimit, naming the particle: sph/mach_watch.h) and the observables' values.
#pragma once

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "scene/scene.h"
#include "scene/scene_sanity.h"

namespace porosph::coupler {

/// The largest Mach number max|v| / c0 the water reached (run.json "mach").
struct MachRecord {
  double max = 0.0;        ///< over the steps so far
  double time = 0.0;       ///< when [s]
  std::uint64_t step = 0;  ///< at which step
  bool warned = false;     ///< the warning above kMachWarn was given
};

/// Books the water's `max_speed` at (`time`, `step`); returns the warning to print the first time
/// the Mach number passes scene::kMachWarn ("" otherwise).
inline std::string note_mach(MachRecord& record, double max_speed, double c0, double time,
                             std::uint64_t step) {
  if (!(c0 > 0.0)) return "";
  const double mach = max_speed / c0;
  if (mach > record.max) record = {mach, time, step, record.warned};
  if (record.warned || !(mach > scene::kMachWarn)) return "";
  record.warned = true;
  std::ostringstream msg;
  msg.precision(3);
  msg << "warning: the water reached Mach " << mach << " (max |v| = " << max_speed
      << " m/s, c0 = " << c0 << " m/s) at step " << step << ", t = " << time << " s: above "
      << scene::kMachWarn
      << " the weakly compressible model's density errors exceed ~1 % (the run fails above "
      << scene::kMachLimit << "; run.json \"mach\" holds the maximum)";
  return msg.str();
}

/// Why `value` of `observable` is nonsense, or "": infinity always; NaN where the observable
/// cannot be empty (max_speed, kinetic_energy, particle_count, max_displacement; front_position,
/// max_height, mean_field over the whole phase while it has free particles). NaN is an empty
/// region's value (and pressure_at's with no particle near its point): sph/observables.h.
inline std::string observable_problem(const scene::Observable& o, double value,
                                      std::uint64_t free_particles) {
  if (std::isfinite(value)) return "";
  bool can_be_empty = o.kind == "pressure_at";
  if (o.kind == "front_position" || o.kind == "max_height" || o.kind == "mean_field")
    can_be_empty = !o.region_min.empty() || free_particles == 0;
  if (std::isnan(value) && can_be_empty) return "";
  return "observable '" + o.name + "' (" + o.kind + " of the " + o.phase + ") is " +
         (std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf")) +
         (std::isnan(value) ? " while the phase has particles for it" : "");
}

}  // namespace porosph::coupler
