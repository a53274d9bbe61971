// Checks of still water against the closed form of still weakly compressible water (still_water.h):
// the hydrostatic tank (pressure per particle and row, the bias in the bottom quarter) and the
// still bed (water at rest over and inside a porous bed: speed and head).
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

/// Still water in a tank, in the last snapshot of water.h5. Heights s along -g; the free surface
/// H = top particle centre + dp/2; depth d = H - s. The reference is still weakly compressible
/// water p(d) (still_water.h); the incompressible rho0 g d is reported beside it.
struct HydrostaticCheck {
  double depth = 0;              ///< H - bottom [m]
  std::size_t particles = 0;     ///< free particles checked (below the top two rows)
  double max_rel_error = 0;      ///< per particle, max |p - p(d)| / p(d)
  double mean_rel_error = 0;     ///< per particle, mean
  double max_row_rel_error = 0;  ///< per lattice row: |mean p - p(d_row)| / p(d_row)
  /// max |p - p(d)| / (rho0 g depth) over the same particles: the error in units of the tank's
  /// pressure scale, which converges where the relative error of the third row from the surface
  /// (a constant surface offset over a depth of 2.5 dp) cannot.
  double max_scaled_error = 0;
  /// Mean of p - p(d) over the free particles in the bottom quarter of the depth, over
  /// rho0 g depth (issue 30: within 0.2 %); the same against rho0 g d.
  double bottom_quarter_bias = 0, bottom_quarter_bias_incompressible = 0;
  double max_speed_ratio = 0;  ///< max |v| / sqrt(|g| H) at the last snapshot
  double time = 0;             ///< time of the snapshot
  /// Per lattice row below the surface (row 0 = top): depth of the row centre, reference pressure,
  /// mean simulated pressure, and the largest per-particle relative error in the row.
  struct Row {
    double depth, exact, mean, max_rel_error;
  };
  std::vector<Row> rows;
};

HydrostaticCheck check_hydrostatic(const std::string& run_dir);

/// Still water over and inside a porous bed (the first soil block of the scene, a box), in the last
/// snapshot of water.h5: the water inside the box in the bottom quarter of its height along -g.
/// Head = s + Phi(p) / g, flat in still water (still_water.h).
struct StillBedCheck {
  double time = 0;
  double depth = 0;                     ///< free surface H minus the bed's bottom [m]
  double max_speed_ratio = 0;           ///< max |v| / sqrt(|g| depth) over all free water
  std::size_t particles = 0;            ///< water particles in the bottom quarter of the bed
  double head_bias = 0;                 ///< mean (head - H) there, over depth (target 0.2 %)
  double head_bias_incompressible = 0;  ///< the same with the head s + p / (rho0 g)
  double compressibility = 0;           ///< g depth / (2 c0^2): the predicted part of the latter
};

StillBedCheck check_still_bed(const std::string& run_dir);

}  // namespace porosph::validation
