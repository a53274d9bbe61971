// Unconfined seepage through a rectangular embankment (cases/seepage_embankment): the SPH run
// against Baiocchi's free surface (rectangular_dam.h) and the exact Dupuit-Charnyi discharge, for
// the pool heads that the run itself holds.
//
// The dam is the scene's first soil block (a box standing on the tank floor, homogeneous K:
// seepage "darcy_conductivity"); the tank is the first container wall; gravity along -y. Upstream
// pool: the water left of the dam, downstream pool: right of it. The reference problem: the dam
// 0 < x - x0 < L on an impermeable base, head h1 on its left face, h2 on its right face below h2,
// a seepage face above (rectangular_dam.h).
//
// Measured on the SPH run, averaged over the outputs in the last `window` seconds:
//   - pool heads h1, h2: mean of y + Phi(p)/g (still_water.h) over the water of each pool, 2 dp
//     away from the tank's side walls and the dam's faces, the pool's top row left out;
//   - discharge q: sum V u_x / w over the water in three vertical slabs across the dam, centred at
//     x/L = 0.25, 0.5, 0.75, w = 0.1 L, averaged over the slabs (the water velocity inside soil is
//     the Darcy velocity: no porosity factor);
//   - phreatic line at x/L = 0.1, 0.25, 0.5, 0.75, 0.9: the highest water particle within dp/2
//     of x among those connected to the floor (inside the dam, through neighbours at most 2 dp
//     apart: a drop that fell off the water table does not count; none was seen) + dp/2, the
//     reservoirs' surface convention; beside it, as a diagnostic, the water volume per width
//     sum V / (2 dp) within dp of x (the water fills the volume in this model, so that is the
//     saturated height, but a particle crossing the bin's edge moves it by dp/2);
//   - exit height: the same top + dp/2 in the dam's last particle column, x in [x1 - dp, x1],
//     compared with the reference surface at that column's centre, x1 - dp/2 (the surface is
//     tangent to the face, phi - h_s ~ sqrt(L - x): the exact exit point h_s is printed beside).
// Reference surface: Baiocchi's solution on 256 x 192 cells (dx 1.6 mm); the 128 x 96 solution's
// difference from it is reported as the reference's own error, and Polubarinova-Kochina's exact
// surface beside it (rectangular_dam_exact.h).
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

struct PhreaticStation {
  double x = 0;          ///< from the dam's upstream face [m]
  double surface = 0;    ///< SPH: connected top + dp/2 [m]
  double volume = 0;     ///< SPH: sum V / (2 dp) within dp of x [m] (diagnostic)
  double reference = 0;  ///< Baiocchi, 256 x 192 [m]
  double coarse = 0;     ///< Baiocchi, 128 x 96 [m]
  double exact = 0;      ///< Polubarinova-Kochina [m]
  double drift = 0;      ///< second half of the window's mean - first half's [m]
};

struct SeepageEmbankmentCheck {
  double window_start = 0, window_end = 0;                 ///< [s]
  std::size_t outputs = 0;                                 ///< outputs averaged
  double dp = 0, conductivity = 0, length = 0;             ///< [m], K [m/s], L [m]
  double level_upstream = 0, level_downstream = 0;         ///< the reservoirs' levels [m]
  double head_upstream = 0, head_downstream = 0;           ///< h1, h2 measured [m]
  double head_upstream_top = 0, head_upstream_bottom = 0;  ///< h in the top / bottom quarter
  double discharge = 0;                                    ///< SPH q [m^2/s], mean over the slabs
  std::vector<double> slab_x, slab_discharge;              ///< per slab (from the upstream face)
  double discharge_reference = 0;                          ///< K (h1^2 - h2^2) / (2 L), exact
  std::vector<double> discharge_history;                   ///< q of each averaged output
  std::vector<PhreaticStation> stations;                   ///< the phreatic line
  PhreaticStation exit;                                    ///< the last column, x = L - dp/2
  double exit_point_exact = 0;                             ///< h_s, Polubarinova-Kochina [m]
  /// The phreatic line in every particle column [i dp, (i + 1) dp] of the dam (top + dp/2, as at
  /// the stations), at the column centres x (from the upstream face), with the references there.
  std::vector<double> profile_x, profile_surface, profile_reference, profile_exact;
  double detached = 0;  ///< water particles in the dam not connected to the floor, per output

  double discharge_error() const { return discharge / discharge_reference - 1.0; }
  /// max |surface - reference| / h1 over the stations.
  double max_surface_error() const;
  double exit_error() const { return (exit.surface - exit.reference) / head_upstream; }
};

/// `window` <= 0: the last quarter of the run.
SeepageEmbankmentCheck check_seepage_embankment(const std::string& run_dir, double window = 0.0);

}  // namespace porosph::validation
