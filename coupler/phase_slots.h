// The phase slots a scene can fill, named in one table (issue 24: the coupler asks this table
// instead of comparing phase names where a phase is only a slot for a solver process). What is
// physics between two phases (the soil-water interaction, the water's Mach watch) still names
// them where that physics lives.
#pragma once

#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace porosph::coupler {

struct PhaseSlot {
  const char* phase;           ///< as in the scene and the wire: "water", "soil"
  const char* builtin_solver;  ///< the executable started when nothing else is named
  const char* snapshot_file;   ///< the phase's snapshot file in the run directory
  /// The snapshot file's name in runs written before the phase had one name (issue 24), which a
  /// resume renames; nullptr: never renamed.
  const char* former_snapshot_file;
};

/// The built-in water solver keeps the program name of the repository's layout (fluid_solver/,
/// docs/design.md "Names"); everything a run writes calls the phase water.
inline constexpr PhaseSlot kPhaseSlots[] = {{"water", "fluid_solver", "water.h5", "fluid.h5"},
                                            {"soil", "soil_solver", "soil.h5", nullptr}};

/// The slot of `phase`; throws std::invalid_argument for a phase the coupler has no slot for.
inline const PhaseSlot& phase_slot(const std::string& phase) {
  for (const PhaseSlot& slot : kPhaseSlots)
    if (phase == slot.phase) return slot;
  throw std::invalid_argument("no phase slot '" + phase + "' (water, soil)");
}

/// The solver command the scene names for `phase` (water.solver, soil.solver); empty: the
/// built-in one. Empty also for a phase the scene does not have.
inline std::string scene_solver_command(const scene::Scene& scene, const std::string& phase) {
  phase_slot(phase);  // an unknown phase is a defect, not "no solver"
  if (phase == "water") return scene.water ? scene.water->solver : std::string();
  return scene.soil ? scene.soil->solver : std::string();
}

}  // namespace porosph::coupler
