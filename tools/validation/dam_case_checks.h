// Measurements of the seed paper's dam and excavation cases (issue 6): the B parameter of the
// overtopped rockfill shell (section 4.2, Table 3) and the failure time of the hydraulic heave next
// to a sheet pile (section 4.3, Table 4 and Fig. 8). Definitions: docs/validation-studies.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace porosph::validation {

/// Soil particles of one snapshot, 2D, row-major (x0, y0, x1, y1, ...).
struct SoilParticles2D {
  std::vector<double> position, displacement;
  std::vector<std::uint8_t> fixed;
  std::vector<std::int64_t> material;
  std::vector<double> saturation;  ///< water volume fraction (soil.h5 field); may be empty
  std::size_t size() const { return fixed.size(); }
};

/// B parameter (paper 4.2): horizontal distance from the original toe x_toe to the most upstream
/// initial position x0 = x - u of a free particle that moved more than `threshold` (|u|), among
/// the particles that started on the slope (x0 >= x_crest, the downstream end of the crest; the
/// column under the crest settles along the core and is not part of the slope). With
/// wet_saturation > 0 only particles whose saturation is at least that count (movement where the
/// water is). 0 when no slope particle moved that far.
double rockfill_b(const SoilParticles2D& soil, double x_toe, double x_crest, double threshold,
                  double wet_saturation = -1);

/// Steady phreatic height H [m] at a distance L [m] upstream of the seepage exit of a horizontal
/// aquifer carrying the discharge per metre q [m^2/s] (Dupuit-Forchheimer: horizontal flow, the
/// specific discharge u = q / H uniform over the height, the slope of the water table the
/// hydraulic gradient i = a u + b u^2 of eq. 13, H = 0 at the exit). Integrating
/// -dH/dx = a q / H + b q^2 / H^2 from the exit gives, with c = b q / a,
///   a q L = H^2 / 2 - c H + c^2 ln(1 + H / c),
/// solved for H by bisection (the right side grows with H). b = 0: Darcy, H = sqrt(2 a q L);
/// a = 0: H = (3 b q^2 L)^(1/3).
/// A reference for the level inside the shell away from the toe: near the exit the flow is not
/// horizontal and a seepage face forms (the Dupuit height there is too low).
double dupuit_forchheimer_height(double distance_from_exit, double discharge_per_metre, double a,
                                 double b);

/// Lowest y of a free particle of `material` whose x lies in [x_lo, x_hi]; NaN if there is none.
double lowest_in_band(const SoilParticles2D& soil, std::int64_t material, double x_lo, double x_hi);

/// Rockfill run: B at the last snapshot for thresholds D15/2, D15, 2 D15, over every slope
/// particle and over the wet ones (saturation >= coupling.wet_saturation); the reported value is
/// the wet one at D15: the dry shell's surface creeps (SPH surface particles), the paper's B is
/// the movement the seepage causes. B(t) of both at D15, and the steady water levels.
struct RockfillCheck {
  double time = 0, flow_rate = 0, dp = 0, d15 = 0, x_toe = 0, x_crest = 0;
  /// Flume width W = inflow cross_section / sheet thickness (the zone's height), q = Q / W.
  double flume_width = 0, discharge_per_metre = 0;
  double wet_saturation = 0.1;
  std::array<double, 3> thresholds{}, b{}, b_wet{};
  std::vector<double> times, b_history, b_wet_history;  ///< at threshold D15, every snapshot
  double b_experiment = -1;                ///< 0.32 m / 0.68 m for Q 19.36 / 30.45 l/s; < 0: none
  double b_paper_sph = -1;                 ///< 0.317 / 0.697
  std::vector<std::string> level_names;    ///< observables level_x* of timeseries.csv
  std::vector<double> levels;              ///< their mean over the last 10 % of the run [m]
  std::vector<double> level_x;             ///< where each is measured (its region's centre) [m]
  std::vector<double> level_dupuit;        ///< dupuit_forchheimer_height there, exit at the toe [m]
  double seepage_a = 0, seepage_b = 0;     ///< eq. 13 coefficients at the initial porosity
  std::vector<double> dupuit_x, dupuit_h;  ///< the whole Dupuit-Forchheimer table, core to toe
  std::size_t particles = 0;
};

RockfillCheck check_rockfill(const std::string& run_dir);

/// Hydraulic heave run. Failure: the first snapshot at which the bottom of the gravel within
/// 2 cm of the pile's upstream face has sunk to the pile tip, counted from the end of the damping
/// stage. Head: upstream_level - downstream_level of timeseries.csv.
///
/// The failure follows one particle (the lowest gravel particle in the band), whose depth jumps by
/// a particle when another one becomes the lowest. Two bulk measures of the same mechanism, for
/// self-convergence (no experiment reports them), sum over many particles:
/// - sand_crossed: the sand that the seepage has carried under the pile into the pit, the free
///   sand area (dp^2 per particle, per metre of flume) left of the pile's pit-side face less that
///   area in the first snapshot;
/// - gravel_settlement: the mean downward displacement (displacement field, since t = 0) of the
///   free gravel particles that started in the band beside the pile (x0 = x - u_x).
struct HeaveCheck {
  double damping_end = 0, pile_tip = 0, pile_face = 0, gravel_top_of_sand = 0;
  double pile_pit_face = 0;           ///< x of the pile's face towards the pit [m]
  std::vector<double> times;          ///< snapshot times [s] (from the end of the damping stage)
  std::vector<double> gravel_bottom;  ///< lowest gravel particle next to the pile [m]
  std::vector<double> sand_crossed;   ///< [m^2 per m], see above
  std::vector<double> gravel_settlement;  ///< [m], see above
  std::vector<double> head_times, head;   ///< overall head [m] vs time from the damping end
  double failure_time = -1;  ///< [s] after the damping stage; < 0: no failure in the run
  double head_at_start = 0, head_at_failure = 0;
  double end_time = 0;
};

HeaveCheck check_heave(const std::string& run_dir);

/// Area (dp^2 per particle) of the free particles of `material` left of x_max [m^2 per m].
double free_area_left_of(const SoilParticles2D& soil, std::int64_t material, double x_max,
                         double dp);

/// Mean of -u_y over the free particles of `material` whose initial x0 = x - u_x lies in
/// [x0_lo, x0_hi] (NaN when there is none) [m].
double mean_settlement(const SoilParticles2D& soil, std::int64_t material, double x0_lo,
                       double x0_hi);

}  // namespace porosph::validation
