#include "tools/validation/seepage_weir_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "io/run_files.h"
#include "io/snapshot_reader.h"
#include "tools/validation/grid_series.h"
#include "tools/validation/laplace_fv.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/seepage_run.h"

namespace porosph::validation {

namespace {

using Box = SeepageBox;

/// The reference in units of the head difference: phi = (h - h2) / (h1 - h2) on the layer with
/// phi = 1 on the upstream top, 0 downstream, no flow under the weir; for K = 1: the discharge
/// (the shape factor q / (K (h1 - h2))), the exit gradient and phi at the probes, each
/// Richardson-extrapolated from a grid series (cells of 20, 10, 5, 2.5 mm).
GridSeries unit_reference(const Box& layer, double weir_x0, double weir_x1, double stretch,
                          const std::vector<SolidBlock>& cutoffs,
                          const std::vector<std::pair<double, double>>& probes) {
  std::vector<std::string> names = {"discharge", "exit_gradient"};
  for (std::size_t k = 0; k < probes.size(); ++k) names.push_back("phi" + std::to_string(k));
  const double base = 0.02;
  return run_grid_series(names, 4, [&](int refinement) {
    LaplaceProblem problem;
    problem.x0 = layer.x0;
    problem.x1 = layer.x1;
    problem.y0 = layer.y0;
    problem.y1 = layer.y1;
    problem.cells_x = static_cast<int>(std::lround((layer.x1 - layer.x0) / base)) * refinement;
    problem.cells_y = static_cast<int>(std::lround((layer.y1 - layer.y0) / base)) * refinement;
    problem.conductivity = 1.0;
    problem.fixed_heads.push_back({Side::kTop, layer.x0, weir_x0, 1.0});
    problem.fixed_heads.push_back({Side::kTop, weir_x1, layer.x1, 0.0});
    problem.solids = cutoffs;
    const LaplaceSolution solution = solve_laplace(problem);
    std::vector<double> values = {
        solution.discharge_across_vertical(0.5 * (weir_x0 + weir_x1), layer.y0, layer.y1),
        solution.mean_outward_gradient(Side::kTop, weir_x1, weir_x1 + stretch)};
    for (const auto& [x, y] : probes) values.push_back(solution.head(x, y));
    return values;
  });
}

/// The FV discharge under the weir's centre and the mean upward gradient over [exit_x0, exit_x1]
/// on the top (K = 1) with fixed heads on the top cells given per cell (NaN: no flow, under the
/// weir or without water above it); cells of `cell` m.
/// The FV solution of the layer alone with the given heads on its top cells (NaN: no flow).
struct LayerAlone {
  double discharge = 0, exit_gradient = 0;
  std::vector<double> probe_heads;  ///< at the probe points
};

LayerAlone layer_with_top_heads(const Box& layer, double weir_mid, double exit_x0, double exit_x1,
                                double cell, const std::vector<SolidBlock>& cutoffs,
                                const std::vector<double>& top_heads,
                                const std::vector<std::pair<double, double>>& probe_points) {
  LaplaceProblem problem;
  problem.solids = cutoffs;
  problem.x0 = layer.x0, problem.x1 = layer.x1, problem.y0 = layer.y0, problem.y1 = layer.y1;
  problem.cells_x = static_cast<int>(top_heads.size());
  problem.cells_y = static_cast<int>(std::lround((layer.y1 - layer.y0) / cell));
  for (std::size_t i = 0; i < top_heads.size(); ++i) {
    if (std::isnan(top_heads[i])) continue;
    const double centre = layer.x0 + (i + 0.5) * cell;
    problem.fixed_heads.push_back(
        {Side::kTop, centre - 0.25 * cell, centre + 0.25 * cell, top_heads[i]});
  }
  const LaplaceSolution solution = solve_laplace(problem);
  LayerAlone out{solution.discharge_across_vertical(weir_mid, layer.y0, layer.y1),
                 solution.mean_outward_gradient(Side::kTop, exit_x0, exit_x1),
                 {}};
  for (const auto& [x, y] : probe_points) out.probe_heads.push_back(solution.head(x, y));
  return out;
}

}  // namespace

double batch_standard_error(const std::vector<double>& history, int batches) {
  const std::size_t per_batch = history.size() / static_cast<std::size_t>(batches);
  if (batches < 2 || per_batch < 2) return 0.0;
  std::vector<double> means(batches, 0.0);
  for (int b = 0; b < batches; ++b) {
    for (std::size_t k = 0; k < per_batch; ++k) means[b] += history[b * per_batch + k];
    means[b] /= static_cast<double>(per_batch);
  }
  double mean = 0.0, square = 0.0;
  for (double m : means) mean += m / batches;
  for (double m : means) square += (m - mean) * (m - mean);
  return std::sqrt(square / (batches - 1) / batches);
}

double SeepageWeirCheck::max_pressure_error() const {
  double worst = 0;
  for (const auto& p : probes) worst = std::max(worst, std::abs(p.relative_error()));
  return worst;
}

double SeepageWeirCheck::max_head_error() const {
  double worst = 0;
  for (const auto& p : probes) worst = std::max(worst, std::abs(p.head - p.head_reference));
  return worst / (head_upstream - head_downstream);
}

SeepageWeirCheck check_seepage_weir(const std::string& run_dir, double window) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const SeepageScene scene = seepage_scene(parameters, "seepage_weir", "layer");
  const StillWater& water = scene.water;
  const Box layer =
      seepage_box(parameters.at("soil").at("blocks").at(0), "seepage_weir", "the first soil block");
  const nlohmann::json* weir_entry = nullptr;
  for (const auto& wall : parameters.at("walls"))
    if (wall.value("label", "") == "weir") weir_entry = &wall;
  if (weir_entry == nullptr) throw std::runtime_error("seepage_weir: no wall labelled 'weir'");
  const Box weir = seepage_box(*weir_entry, "seepage_weir", "the weir");
  // Walls inside the layer (a cut-off wall under the weir) are impermeable solids of the
  // reference; their edges must lie on the 20 mm grid of its coarsest level.
  std::vector<SolidBlock> cutoffs;
  for (const auto& wall : parameters.at("walls")) {
    if (wall.at("shape").get<std::string>() != "box") continue;
    const Box b = seepage_box(wall, "seepage_weir", "a wall");
    if (b.x0 < layer.x1 && b.x1 > layer.x0 && b.y0 < layer.y1 && b.y1 > layer.y0)
      cutoffs.push_back({std::max(b.x0, layer.x0), std::min(b.x1, layer.x1),
                         std::max(b.y0, layer.y0), std::min(b.y1, layer.y1)});
  }

  SeepageWeirCheck out;
  out.dp = scene.dp;
  out.conductivity = scene.conductivity;
  out.exit_stretch = 0.05 * (layer.x1 - weir.x1) / 0.5;  // 5 cm on the case's 0.5 m pool
  const double dp = out.dp, margin = 2.0 * dp;
  const double mid = 0.5 * (weir.x0 + weir.x1), depth = layer.y1 - layer.y0;
  const std::vector<std::pair<double, double>> probe_points = {
      {weir.x0 - 0.1, layer.y0 + 0.25 * depth}, {weir.x0, layer.y0 + 0.25 * depth},
      {mid, layer.y0 + 0.25 * depth},           {weir.x1, layer.y0 + 0.25 * depth},
      {weir.x1 + 0.1, layer.y0 + 0.25 * depth}, {mid, layer.y0 + 0.75 * depth}};

  io::SnapshotReader reader(io::water_snapshot_path(run_dir));
  const auto snapshots = reader.snapshots();
  if (snapshots.size() < 2) throw std::runtime_error(run_dir + "/water.h5: too few snapshots");
  out.window_end = snapshots.back().time;
  out.window_start = out.window_end - (window > 0.0 ? window : 0.25 * out.window_end);
  const Box upstream{layer.x0 + margin, layer.y1 + margin, weir.x0 - margin, 1e9};
  const Box downstream{weir.x1 + margin, layer.y1 + margin, layer.x1 - margin, 1e9};
  const Box under{weir.x0 + margin, layer.y0, weir.x1 - margin, layer.y1};
  const Box exit{weir.x1, layer.y1 - dp, weir.x1 + out.exit_stretch, layer.y1 + dp};
  std::vector<double> probe_h(probe_points.size(), 0.0);
  double h1 = 0, h2 = 0, exit_gradient = 0;
  // The run's own heads on the layer's top, per FV cell of the finest reference grid.
  const double cell = 0.0025;
  const std::size_t top_cells = static_cast<std::size_t>(std::lround((layer.x1 - layer.x0) / cell));
  std::vector<double> top_sum(top_cells, 0.0), top_count(top_cells, 0.0);
  double near_sum = 0, near_count = 0;            // the upstream pool within 0.1 m of the weir
  double near_down_sum = 0, near_down_count = 0;  // the downstream pool within 0.1 m of it
  for (const auto& snap : snapshots) {
    if (snap.time < out.window_start - 1e-12) continue;
    const WaterSnapshot s = read_water_snapshot(reader, snap.index);
    const double top_up = highest_free_y(s, upstream), top_down = highest_free_y(s, downstream);
    double sum_h1 = 0, sum_h2 = 0, flux = 0, exit_v = 0;
    std::size_t n1 = 0, n2 = 0, n_exit = 0;
    std::vector<double> ph(probe_points.size(), 0.0);
    std::vector<std::size_t> pn(probe_points.size(), 0);
    for (std::size_t i = 0; i < s.rows(); ++i) {
      if (!s.free(i)) continue;
      const double xi = s.px(i), yi = s.py(i);
      const double head = yi + water.pressure_head(s.p.values[i]);
      if (upstream.contains(xi, yi) && yi < top_up - 1.5 * dp) {
        sum_h1 += head, ++n1;
        if (xi > weir.x0 - 0.1) near_sum += head, ++near_count;
      }
      if (yi > layer.y1 && yi < layer.y1 + margin) {    // 0 .. 2 dp above the layer
        const double u = (xi - layer.x0) / cell - 0.5;  // cells whose centre lies within dp
        const long first = std::max(0L, static_cast<long>(std::ceil(u - dp / cell)));
        const long last = std::min(static_cast<long>(top_cells) - 1,
                                   static_cast<long>(std::floor(u + dp / cell)));
        for (long k = first; k <= last; ++k) top_sum[k] += head, top_count[k] += 1.0;
      }
      if (downstream.contains(xi, yi) && yi < top_down - 1.5 * dp) {
        sum_h2 += head, ++n2;
        if (xi < weir.x1 + 0.1) near_down_sum += head, ++near_down_count;
      }
      if (under.contains(xi, yi)) flux += s.volume(i) * s.v.values[2 * i];
      if (exit.contains(xi, yi)) exit_v += s.v.values[2 * i + 1], ++n_exit;
      for (std::size_t k = 0; k < probe_points.size(); ++k) {
        if (std::abs(xi - probe_points[k].first) <= dp &&
            std::abs(yi - probe_points[k].second) <= dp)
          ph[k] += head, ++pn[k];
      }
    }
    if (n1 == 0 || n2 == 0 || n_exit == 0)
      throw std::runtime_error(
          run_dir + ": an empty pool or exit region at t = " + std::to_string(snap.time));
    h1 += sum_h1 / n1;
    h2 += sum_h2 / n2;
    out.discharge_history.push_back(flux / (under.x1 - under.x0));
    exit_gradient += exit_v / n_exit / out.conductivity;
    out.exit_gradient_history.push_back(exit_v / n_exit / out.conductivity);
    for (std::size_t k = 0; k < probe_points.size(); ++k) {
      if (pn[k] == 0) throw std::runtime_error(run_dir + ": a probe without water");
      probe_h[k] += ph[k] / pn[k];
    }
    ++out.outputs;
  }
  const double n = static_cast<double>(out.outputs);
  out.head_upstream = h1 / n;
  out.head_downstream = h2 / n;
  for (double q : out.discharge_history) out.discharge += q / n;
  out.exit_gradient = exit_gradient / n;
  std::vector<double> top_heads(top_cells, std::nan(""));
  for (std::size_t k = 0; k < top_cells; ++k) {
    const double centre = layer.x0 + (k + 0.5) * cell;
    if (top_count[k] > 0 && (centre < weir.x0 || centre > weir.x1))
      top_heads[k] = top_sum[k] / top_count[k];
  }
  const LayerAlone own = layer_with_top_heads(layer, mid, weir.x1, weir.x1 + out.exit_stretch, cell,
                                              cutoffs, top_heads, probe_points);
  out.discharge_own_heads = out.conductivity * own.discharge;
  // The 2.5 mm grid with fixed heads on half of each top cell puts the exit gradient of the
  // pools' means 0.3 % below the extrapolated reference (q 0.24 % below): the exit gradient is
  // scaled by the same grid's value with those means (unit heads) against the reference's.
  std::vector<double> unit_heads(top_cells, std::nan(""));
  for (std::size_t k = 0; k < top_cells; ++k) {
    const double centre = layer.x0 + (k + 0.5) * cell;
    if (centre < weir.x0) unit_heads[k] = 1.0;
    if (centre > weir.x1) unit_heads[k] = 0.0;
  }
  const LayerAlone unit = layer_with_top_heads(layer, mid, weir.x1, weir.x1 + out.exit_stretch,
                                               cell, cutoffs, unit_heads, probe_points);

  const GridSeries reference =
      unit_reference(layer, weir.x0, weir.x1, out.exit_stretch, cutoffs, probe_points);
  const double dh = out.head_upstream - out.head_downstream;
  if (near_count > 0)
    out.upstream_head_near_weir = (near_sum / near_count - out.head_upstream) / dh;
  if (near_down_count > 0)
    out.downstream_head_near_weir = (near_down_sum / near_down_count - out.head_downstream) / dh;
  out.discharge_reference = out.conductivity * dh * reference.estimates[0].extrapolated;
  out.discharge_reference_order = reference.estimates[0].order;
  out.exit_gradient_reference = dh * reference.estimates[1].extrapolated;
  out.exit_gradient_own_heads =
      own.exit_gradient * reference.estimates[1].extrapolated / unit.exit_gradient;
  for (std::size_t k = 0; k < probe_points.size(); ++k) {
    SeepageProbe probe;
    probe.x = probe_points[k].first;
    probe.y = probe_points[k].second;
    probe.head = probe_h[k] / n;
    // The pressure that the SPH head implies at the probe point: the particles of the +-dp box
    // sit on average off the point, where p differs by rho g dy, while the head is smooth.
    probe.pressure = water.pressure(probe.head - probe.y);
    probe.head_reference = out.head_downstream + dh * reference.estimates[2 + k].extrapolated;
    // The layer alone at the probe: the run's own top heads on the 2.5 mm grid, that grid's error
    // (the unit-head solution's against the extrapolated reference, times dh) taken out.
    probe.head_own_heads =
        own.probe_heads[k] + dh * (reference.estimates[2 + k].extrapolated - unit.probe_heads[k]);
    probe.pressure_reference = water.pressure(probe.head_reference - probe.y);
    out.probes.push_back(probe);
  }
  return out;
}

}  // namespace porosph::validation
