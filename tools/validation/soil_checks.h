// Comparisons of finished soil runs with their references (issue 3): the settled dry column
// against the weight of the soil above, and the observables of the granular column collapse.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace porosph::validation {

/// Dry soil column at rest: the vertical stress u.sigma.u (u = -g/|g|) of every free particle
/// against the weight of the soil above it, -|g| (sum over the particles above it in its initial
/// column of rho_j dp + rho_i dp / 2), rho the material density (the particle's mass per lattice
/// volume). The stress is each particle's mean over the snapshots after the damping stage (the
/// centre of the free vibration that follows it; the last snapshot alone when fewer than two
/// follow it). Checked: the particles whose initial place lies more than `band` [m] below the
/// column's top and above its base. A fixed band compares the same material at every dp; a band of
/// two rows shrinks with dp, and the relative error of the second row below a free top, where the
/// exact stress is 2.5 dp rho g, does not fall with dp (it is reported apart).
struct SoilColumnCheck {
  double time = 0;
  double averaged_from = 0;   ///< [s] first snapshot of the average (= time: last only)
  std::size_t snapshots = 0;  ///< in the average
  double band = 0;            ///< [m] excluded at the top and the base
  std::size_t particles = 0;  ///< free particles checked
  double max_rel_error = 0;   ///< per particle, max |sigma_v - exact| / |exact|
  /// The same over the particles below the top two rows and above the bottom two (the free top's
  /// and the floor's particle layers), for information.
  double max_rel_error_two_rows = 0;
  double mean_rel_error = 0;            ///< per particle, mean
  double max_row_rel_error = 0;         ///< per initial row: |mean sigma_v - exact| / |exact|
  double mean_ratio = 0;                ///< mean of sigma_h / sigma_v over the checked particles
  double min_ratio = 0, max_ratio = 0;  ///< range of the row means of sigma_h / sigma_v
  double mean_out_of_plane_ratio = 0;   ///< 2D: mean sigma_zz / sigma_v
  double k0_elastic = 0, k0_jaky = 0;   ///< nu / (1 - nu) and 1 - sin(phi) of the first material
  double max_speed = 0;                 ///< [m/s] at the last snapshot
};

/// Every particle more than two rows from the top and the base: `band` = 0.
SoilColumnCheck check_soil_column(const std::string& run_dir, double band);

/// Final deposit of a collapsed column standing against a back wall at its initial minimum x.
struct CollapseMeasurement {
  double time = 0;
  double runout = 0;  ///< deposit front from the back wall: max (x - x_wall) + dp/2 [m]
  /// Bulk front from the back wall [m]: the farthest column (width dp) whose deposit is at least
  /// a tenth of the initial height thick (top + dp/2 above the base). Unlike the farthest
  /// particle, which at fine dp is a single particle on the floor, it converges with dp.
  double bulk_runout = 0;
  double height_at_wall = 0;  ///< top of the soil within 2 dp of the back wall, + dp/2 [m]
  double initial_height = 0, initial_width = 0;  ///< of the column at t = 0 [m]
  /// Angle [deg] of the failure surface: the boundary, in the initial configuration, between the
  /// particles that moved less than a threshold and the others, fitted by least squares through
  /// the top unmoved particle of each initial column. Thresholds dp/2, dp and 2 dp.
  double thresholds[3] = {0, 0, 0};
  double failure_angle_deg[3] = {0, 0, 0};
  double max_speed = 0;  ///< [m/s] at the last snapshot: ~0 once the deposit is at rest
  std::size_t particles = 0;
};

CollapseMeasurement measure_collapse(const std::string& run_dir);

/// The bulk front of a deposit [m from x_wall]: the far edge of the farthest column [x_wall + k dp,
/// x_wall + (k + 1) dp) whose highest free particle top (y + dp/2 - y_base) reaches
/// min_thickness; 0 when none does. `position` holds x, y pairs.
double bulk_front(const std::vector<double>& position, const std::vector<std::uint8_t>& fixed,
                  double x_wall, double y_base, double dp, double min_thickness);

}  // namespace porosph::validation
