// Confined seepage under a weir (cases/seepage_weir): the SPH run against the grid-converged
// finite-volume solution of Laplace's equation on the same permeable layer (laplace_fv.h), with
// the pool heads that the run itself holds.
//
// The layer is the scene's first soil block (a box, homogeneous K: seepage "darcy_conductivity");
// the weir is the wall labelled "weir" (a box standing on the layer); gravity along -y. Upstream
// pool: x below the weir, downstream pool: x beyond it. The reference problem: Laplace on the
// layer, the top at the measured pool heads h1 (upstream) and h2 (downstream), no flow under the
// weir, on the floor and the side walls.
//
// Measured on the SPH run, averaged over the outputs in the last `window` seconds:
//   - pool heads h1, h2: mean of z + Phi(p)/g (still_water.h) over the water in each pool (2 dp
//     away from the layer, the walls and the weir, below the two top rows);
//   - discharge q: sum V u_x / w over the water in the layer under the weir, x within the weir's
//     width less 2 dp on each side (in this model the water velocity inside soil is the Darcy
//     velocity, so q is its integral over the depth);
//   - exit gradient: mean upward velocity / K of the water within dp of the layer's top (the Darcy
//     velocity inside, the same flux just above; the water there seeps upwards, so a band of the
//     top row alone empties from time to time at coarse dp) over the stretch
//     `exit_stretch` next to the weir's downstream face, against the FV mean upward gradient there;
//   - pore pressure at probes: the mean head z + Phi(p)/g of the water in a box of +-dp around
//     the point, converted to the pressure at the point, p(h - z) of still weakly compressible
//     water, against p(h_ref - z); and the head error over h1 - h2.
#pragma once

#include <string>
#include <vector>

namespace porosph::validation {

struct SeepageProbe {
  double x = 0, y = 0;
  double pressure = 0, pressure_reference = 0;  ///< [Pa]
  double head = 0, head_reference = 0;          ///< [m]
  double head_own_heads = 0;  ///< [m] FV of the layer alone with the run's own top heads
  double relative_error() const { return (pressure - pressure_reference) / pressure_reference; }
};

struct SeepageWeirCheck {
  double window_start = 0, window_end = 0;        ///< [s]
  std::size_t outputs = 0;                        ///< outputs averaged
  double dp = 0, conductivity = 0;                ///< [m], K [m/s]
  double head_upstream = 0, head_downstream = 0;  ///< h1, h2 measured [m]
  double discharge = 0;                           ///< SPH q [m^2/s]
  double discharge_reference = 0;                 ///< FV q, Richardson-extrapolated
  double discharge_reference_order = 0;           ///< observed order of the FV series
  double exit_gradient = 0, exit_gradient_reference = 0;
  double exit_stretch = 0;  ///< [m]
  std::vector<SeepageProbe> probes;
  std::vector<double> discharge_history;      ///< q of each averaged output (steadiness)
  std::vector<double> exit_gradient_history;  ///< the exit gradient of each averaged output
  /// The layer alone: the FV discharge (2.5 mm cells) with the run's own heads as the top
  /// boundary (per cell, the water 0 .. 2 dp above the layer within dp of its centre, averaged
  /// over the window) instead of the pools' means. Agreement here and not with
  /// discharge_reference puts the error in the pools, not in the sand.
  double discharge_own_heads = 0;
  /// The exit gradient of the same FV solution: linear in the top heads, so the window mean of
  /// the instantaneous references; a pool's seiche, which moves the heads at the exit, moves it
  /// as it moves the run's exit gradient. Scaled by the extrapolated reference over the same
  /// grid's exit gradient with the pools' means (that grid's own error, -0.3 %).
  double exit_gradient_own_heads = 0;
  /// The upstream pool's head within 0.1 m of the weir, from its mean, over dh.
  double upstream_head_near_weir = 0;
  /// The same for the downstream pool: where most of the water leaves the sand, so a pool that
  /// stands higher there than its mean (a tilt or a seiche, docs/verification.md) takes discharge.
  double downstream_head_near_weir = 0;

  double discharge_error() const { return discharge / discharge_reference - 1.0; }
  double layer_error() const { return discharge / discharge_own_heads - 1.0; }
  double exit_gradient_error() const { return exit_gradient / exit_gradient_reference - 1.0; }
  double layer_exit_gradient_error() const { return exit_gradient / exit_gradient_own_heads - 1.0; }
  double max_pressure_error() const;  ///< max |relative_error()| over the probes
  double max_head_error() const;      ///< max |head - head_reference| / (h1 - h2)
};

/// The standard error of the mean of `history` by batch means: the outputs in `batches`
/// consecutive blocks, the spread of the blocks' means over sqrt(batches - 1) (the outputs of a
/// seiche or a slow drift are correlated, so their own spread would understate it); 0 with fewer
/// than 2 outputs per block.
double batch_standard_error(const std::vector<double>& history, int batches = 4);

/// `window` <= 0: the last quarter of the run.
SeepageWeirCheck check_seepage_weir(const std::string& run_dir, double window = 0.0);

}  // namespace porosph::validation
