// Comparison of a finished fluidized_bed run with the seed paper's section 4.1 (issue 4).
#pragma once

#include <string>

namespace porosph::validation {

/// Reads the observables sand_porosity, bed_height and sand_stress_yy of timeseries.csv and the
/// inflow ramp of run.json. Definitions (docs/validation-studies.md):
/// - steady porosity: mean of sand_porosity over the last `steady_window` seconds of the run;
///   its drift is the change of the window's second half mean against its first half mean.
/// - onset of fluidisation (incipient fluidisation: the drag carries the submerged weight): the
///   first output at which the mean vertical effective stress of the lower sand has fallen below
///   10 % of its settled value; the flow rate there from the ramp
///   Q(t) = Q_max min(1, (t - t_start) / t_ramp).
/// - onset of expansion: the first output at which the mean sand porosity has risen by 0.005
///   above its value when the flow started (the bed has grown by ~1 % in volume).
/// - effective stress ratio: mean of sand_stress_yy over the steady window divided by its value
///   at the first output after the flow started (the settled bed, Q ~ 0).
struct FluidizedBedCheck {
  double time = 0;                  ///< end of the run [s]
  double steady_window = 0;         ///< [s]
  double steady_porosity = 0;       ///< mean over the window
  double porosity_drift = 0;        ///< second half minus first half of the window
  double initial_porosity = 0;      ///< when the flow started
  double bed_height_initial = 0;    ///< top of the sand when the flow started [m]
  double bed_height_final = 0;      ///< mean over the window [m]
  double bed_rise_rate = 0;         ///< (second half - first half mean) / (window / 2) [m/s]
  double stress_initial = 0;        ///< sand_stress_yy when the flow started [Pa]
  double stress_ratio = 0;          ///< steady / initial effective vertical stress
  double onset_time = -1;           ///< effective stress below 10 % [s]; < 0: never
  double onset_flow_rate = -1;      ///< [m^3/s]; < 0: never
  double expansion_time = -1;       ///< porosity +0.005 [s]; < 0: never
  double expansion_flow_rate = -1;  ///< [m^3/s]; < 0: never
  double max_flow_rate = 0;         ///< Q_max of the ramp [m^3/s]
  bool porosity_in_target = false;  ///< 0.51 +- 0.02
  bool onset_in_target = false;     ///< 0.07 .. 0.12 l/s
  /// Issue 23: the mean water velocity along the inflow inside the bed (2 dp inside its bottom and
  /// its steady top), over the steady window, against the superficial velocity U = Q / A (in this
  /// model the water velocity inside soil is the Darcy velocity, docs/water-in-soil.md); and the
  /// same for the mass flux rho v against rho_inflow U, which steady mass conservation fixes.
  double superficial_velocity = 0;  ///< U = Q_max / cross_section [m/s]
  double velocity_ratio = 0;        ///< mean v / U
  /// Standard error of velocity_ratio over the window's snapshots (their spread / sqrt(count)):
  /// how far a single transient moves it. 0 with one snapshot.
  double velocity_ratio_error = 0;
  int window_snapshots = 0;  ///< snapshots in the steady window
  /// With the observables bed_water_velocity, bed_water_density and inflow_water_mass in
  /// timeseries.csv (cases/fluidized_bed/scene.toml), velocity_ratio (and its error) is the time
  /// mean over `whole_periods` inflow periods dp / U ending at the run's end (the inflow hands
  /// over a row of particles, and the outflow takes one, once a period;
  /// docs/validation-studies.md), and the snapshot mean above moves to snapshot_velocity_ratio.
  bool velocity_over_periods = false;
  double inflow_period = 0;  ///< dp / U [s]
  int whole_periods = 0;
  /// rho_bed v / (m_inflow / dp^D U) over the same periods (m_inflow: the inflow zone's particle
  /// mass): steady mass conservation makes it 1. The zone hands over mass at m_inflow / dp^D U,
  /// so weakly compressible water moves through the bed at U m_inflow / (dp^D rho_bed), above
  /// Q / A by about the pressure drop from the inflow to the bed over (rho c0^2).
  double period_mass_flux_ratio = 0;
  double period_mass_flux_ratio_error = 0;
  double snapshot_velocity_ratio = 0;
  double snapshot_velocity_ratio_error = 0;
  double mass_flux_ratio = 0;  ///< mean rho v / (rho_inflow U)
  /// The mass flux through the bed as a density, sum m v / V_region, against rho_inflow U: the
  /// conserved quantity, whatever the particles' spacing.
  double mass_flux_density_ratio = 0;
  /// sum (m / rho) / V_region: how much of the region the particles' volumes fill; 1 when their
  /// spacing matches their density. Above 1 the particles are crowded (their lattice has
  /// rearranged, which the continuity density does not register), and the mean particle velocity
  /// then reads the flux low by that factor.
  double volume_fill = 0;
};

FluidizedBedCheck check_fluidized_bed(const std::string& run_dir, double steady_window = 1.0);

}  // namespace porosph::validation
