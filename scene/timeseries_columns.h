// The columns every timeseries.csv has before the scene's observables (docs/design.md, run
// directory): t, dt, per phase its totals and momentum balance, and for a scene with both phases
// the cumulative interaction impulses and the soil-water pair count. One list for the coupler that
// writes them and for the scene check that keeps observable names from shadowing them.
#pragma once

#include <string>
#include <vector>

namespace porosph::scene {

inline const char* axis_name(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

/// Built-in columns for the given phases (in order) and dimension; `coupled`: water and soil.
inline std::vector<std::string> builtin_timeseries_columns(const std::vector<std::string>& phases,
                                                           int dimension, bool coupled) {
  std::vector<std::string> columns = {"t", "dt"};
  for (const std::string& phase : phases) {
    columns.push_back(phase + "_kinetic_energy");
    for (int k = 0; k < dimension; ++k) columns.push_back(phase + "_momentum_" + axis_name(k));
    for (const char* total : {"_mass", "_particles", "_removed", "_overlap"})
      columns.push_back(phase + total);
    // Cumulative mass that entered (inflow zones) and left (outflow zones, the domain)
    // [kg/m^(3-D)]: <phase>_mass = its first row + inflow - outflow, to round-off, at every row.
    for (const char* total : {"_mass_inflow", "_mass_outflow"}) columns.push_back(phase + total);
    // The external-impulse ledger (docs/coupling.md): the cumulative sum of the impulses the
    // phase's solver booked [N s], and the relative residual of its momentum balance (0 when the
    // solver books nothing).
    for (int k = 0; k < dimension; ++k)
      columns.push_back(phase + "_external_impulse_" + axis_name(k));
    columns.push_back(phase + "_momentum_residual");
  }
  if (coupled) {
    // Cumulative interaction impulses [N s] up to t, and the soil-water pairs at t.
    for (const char* phase : {"soil", "water"}) {
      for (int k = 0; k < dimension; ++k)
        columns.push_back(std::string("impulse_to_") + phase + "_" + axis_name(k));
    }
    columns.push_back("soil_water_pairs");
  }
  return columns;
}

}  // namespace porosph::scene
