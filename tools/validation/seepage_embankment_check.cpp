#include "tools/validation/seepage_embankment_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/run_files.h"
#include "io/snapshot_reader.h"
#include "tools/validation/rectangular_dam.h"
#include "tools/validation/rectangular_dam_exact.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/seepage_run.h"

namespace porosph::validation {

namespace {

using Box = SeepageBox;

/// Marks the particles (xs, ys) connected to the floor y0: from every particle below y0 + link,
/// through neighbours at most `link` apart (cell lists of width link). Drops that fell off the
/// water table are not marked.
std::vector<char> connected_to_floor(const std::vector<double>& xs, const std::vector<double>& ys,
                                     double y0, double link) {
  const std::size_t n = xs.size();
  std::vector<char> marked(n, 0);
  if (n == 0) return marked;
  const double x_min = *std::min_element(xs.begin(), xs.end());
  const double y_min = *std::min_element(ys.begin(), ys.end());
  auto cell_of = [&](std::size_t i, int& cx, int& cy) {
    cx = static_cast<int>((xs[i] - x_min) / link);
    cy = static_cast<int>((ys[i] - y_min) / link);
  };
  std::map<std::pair<int, int>, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < n; ++i) {
    int cx, cy;
    cell_of(i, cx, cy);
    cells[{cx, cy}].push_back(i);
  }
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < n; ++i)
    if (ys[i] < y0 + link) marked[i] = 1, stack.push_back(i);
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    int cx, cy;
    cell_of(i, cx, cy);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find({cx + dx, cy + dy});
        if (it == cells.end()) continue;
        for (std::size_t j : it->second) {
          if (marked[j] || std::hypot(xs[j] - xs[i], ys[j] - ys[i]) > link) continue;
          marked[j] = 1;
          stack.push_back(j);
        }
      }
  }
  return marked;
}

/// The level of the reservoir whose box lies nearest to x along x (0 where it holds x: a surface
/// reservoir over its pool; an open reservoir's buffer lies beyond its pool's end); NaN if none.
double reservoir_level(const nlohmann::json& water, double x) {
  if (!water.contains("reservoir")) return std::nan("");
  double level = std::nan(""), nearest = 1e300;
  for (const auto& r : water.at("reservoir")) {
    const auto lo = r.at("min").get<std::vector<double>>();
    const auto hi = r.at("max").get<std::vector<double>>();
    const double distance = std::max({0.0, lo[0] - x, x - hi[0]});
    if (distance < nearest) nearest = distance, level = r.at("level").get<double>();
  }
  return level;
}

/// The tank: the container wall, or (a pool open onto a reservoir's buffer) the bounding box of the
/// water blocks that are boxes.
Box tank_box(const nlohmann::json& parameters) {
  for (const auto& wall : parameters.at("walls"))
    if (wall.at("shape").get<std::string>() == "container")
      return seepage_box(wall, "seepage_embankment", "the tank", "container");
  Box tank{1e300, 1e300, -1e300, -1e300};
  for (const auto& block : parameters.at("water").at("blocks")) {
    if (block.at("shape").get<std::string>() != "box") continue;
    const auto lo = block.at("min").get<std::vector<double>>();
    const auto hi = block.at("max").get<std::vector<double>>();
    tank = {std::min(tank.x0, lo[0]), std::min(tank.y0, lo[1]), std::max(tank.x1, hi[0]),
            std::max(tank.y1, hi[1])};
  }
  if (!(tank.x1 > tank.x0))
    throw std::runtime_error("seepage_embankment: no container wall and no box of water");
  return tank;
}

}  // namespace

double SeepageEmbankmentCheck::max_surface_error() const {
  double worst = 0;
  for (const auto& s : stations) worst = std::max(worst, std::abs(s.surface - s.reference));
  return worst / head_upstream;
}

SeepageEmbankmentCheck check_seepage_embankment(const std::string& run_dir, double window) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const SeepageScene scene = seepage_scene(parameters, "seepage_embankment", "dam");
  const StillWater& water = scene.water;
  const auto& w = parameters.at("water");
  const Box dam = seepage_box(parameters.at("soil").at("blocks").at(0), "seepage_embankment",
                              "the first soil block");
  const Box tank = tank_box(parameters);

  SeepageEmbankmentCheck out;
  out.dp = scene.dp;
  out.conductivity = scene.conductivity;
  out.length = dam.x1 - dam.x0;
  out.level_upstream = reservoir_level(w, 0.5 * (tank.x0 + dam.x0));
  out.level_downstream = reservoir_level(w, 0.5 * (dam.x1 + tank.x1));
  const double dp = out.dp, margin = 2.0 * dp, L = out.length;
  const std::vector<double> fractions = {0.1, 0.25, 0.5, 0.75, 0.9};
  std::vector<double> station_x;  // absolute x of the stations, then of the last column
  for (double f : fractions) station_x.push_back(dam.x0 + f * L);
  station_x.push_back(dam.x1 - 0.5 * dp);
  for (double f : {0.25, 0.5, 0.75}) out.slab_x.push_back(f * L);
  const double slab_width = 0.1 * L;

  io::SnapshotReader reader(io::water_snapshot_path(run_dir));
  const auto snapshots = reader.snapshots();
  if (snapshots.size() < 2) throw std::runtime_error(run_dir + "/water.h5: too few snapshots");
  out.window_end = snapshots.back().time;
  out.window_start = out.window_end - (window > 0.0 ? window : 0.25 * out.window_end);
  const Box upstream{tank.x0 + margin, tank.y0, dam.x0 - margin, 1e9};
  const Box downstream{dam.x1 + margin, tank.y0, tank.x1 - margin, 1e9};
  const std::size_t n_st = station_x.size();
  std::vector<std::vector<double>> surface_history(n_st);
  std::vector<double> volume(n_st, 0.0), slab_q(out.slab_x.size(), 0.0);
  const auto n_columns = static_cast<std::size_t>(std::lround(L / dp));
  std::vector<double> column_sum(n_columns, 0.0);
  double h1 = 0, h2 = 0, h1_top = 0, h1_bottom = 0;
  for (const auto& snap : snapshots) {
    if (snap.time < out.window_start - 1e-12) continue;
    const WaterSnapshot s = read_water_snapshot(reader, snap.index);
    const double top_up = highest_free_y(s, upstream), top_down = highest_free_y(s, downstream);
    const double depth_up = top_up + 0.5 * dp - dam.y0;
    double sum_h1 = 0, sum_h2 = 0, sum_top = 0, sum_bottom = 0;
    std::size_t n1 = 0, n2 = 0, n_top = 0, n_bottom = 0;
    std::vector<double> top(n_st, -1e9), column_top(n_columns, -1e9), dam_x, dam_y;
    std::vector<double> flux(out.slab_x.size(), 0.0);
    for (std::size_t i = 0; i < s.rows(); ++i) {
      if (!s.free(i)) continue;
      const double xi = s.px(i), yi = s.py(i);
      const double head = yi + water.pressure_head(s.p.values[i]);
      const double vol = s.volume(i);
      if (upstream.contains(xi, yi) && yi < top_up - 0.5 * dp) {
        sum_h1 += head, ++n1;
        if (yi > dam.y0 + 0.75 * depth_up) sum_top += head, ++n_top;
        if (yi < dam.y0 + 0.25 * depth_up) sum_bottom += head, ++n_bottom;
      }
      if (downstream.contains(xi, yi) && yi < top_down - 0.5 * dp) sum_h2 += head, ++n2;
      if (xi < dam.x0 || xi > dam.x1) continue;  // below: the water inside the dam
      for (std::size_t k = 0; k < out.slab_x.size(); ++k)
        if (std::abs(xi - dam.x0 - out.slab_x[k]) <= 0.5 * slab_width)
          flux[k] += vol * s.v.values[2 * i];
      dam_x.push_back(xi), dam_y.push_back(yi);
      for (std::size_t k = 0; k + 1 < n_st; ++k)
        if (std::abs(xi - station_x[k]) <= dp) volume[k] += vol / (2.0 * dp);
      if (xi >= dam.x1 - dp) volume[n_st - 1] += vol / dp;  // the last column: width dp
    }
    const auto marked = connected_to_floor(dam_x, dam_y, dam.y0, 2.0 * dp);
    for (std::size_t j = 0; j < dam_x.size(); ++j) {
      if (!marked[j]) {
        out.detached += 1.0;
        continue;
      }
      for (std::size_t k = 0; k < n_st; ++k) {
        const bool in =
            k + 1 == n_st ? dam_x[j] >= dam.x1 - dp : std::abs(dam_x[j] - station_x[k]) <= 0.5 * dp;
        if (in) top[k] = std::max(top[k], dam_y[j]);
      }
      const auto c = static_cast<std::size_t>((dam_x[j] - dam.x0) / dp);
      if (c < n_columns) column_top[c] = std::max(column_top[c], dam_y[j]);
    }
    if (n1 == 0 || n2 == 0 || n_top == 0 || n_bottom == 0)
      throw std::runtime_error(run_dir + ": an empty pool at t = " + std::to_string(snap.time));
    h1 += sum_h1 / n1;
    h2 += sum_h2 / n2;
    h1_top += sum_top / n_top;
    h1_bottom += sum_bottom / n_bottom;
    double q = 0;
    for (std::size_t k = 0; k < flux.size(); ++k) {
      slab_q[k] += flux[k] / slab_width;
      q += flux[k] / slab_width / flux.size();
    }
    out.discharge_history.push_back(q);
    for (std::size_t k = 0; k < n_st; ++k) {
      if (top[k] < dam.y0)
        throw std::runtime_error(run_dir +
                                 ": no water in the dam at x = " + std::to_string(station_x[k]));
      surface_history[k].push_back(top[k] + 0.5 * dp - dam.y0);
    }
    for (std::size_t c = 0; c < n_columns; ++c)
      column_sum[c] += std::max(column_top[c] + 0.5 * dp, dam.y0) - dam.y0;
    ++out.outputs;
  }
  const double n = static_cast<double>(out.outputs);
  out.head_upstream = h1 / n - dam.y0;
  out.head_downstream = h2 / n - dam.y0;
  out.head_upstream_top = h1_top / n - dam.y0;
  out.head_upstream_bottom = h1_bottom / n - dam.y0;
  out.detached /= n;
  for (double q : out.discharge_history) out.discharge += q / n;
  for (double q : slab_q) out.slab_discharge.push_back(q / n);

  RectangularDam reference{L, out.head_upstream, out.head_downstream, out.conductivity};
  out.discharge_reference = reference.charnyi_discharge();
  const DamSolution fine = solve_rectangular_dam(reference, 256, 192);
  const DamSolution coarse = solve_rectangular_dam(reference, 128, 96);
  const RectangularDamExact exact(reference);
  out.exit_point_exact = exact.exit_height();
  for (std::size_t k = 0; k < n_st; ++k) {
    PhreaticStation s;
    s.x = station_x[k] - dam.x0;
    const auto& history = surface_history[k];
    const std::size_t half = history.size() / 2;
    double first = 0, second = 0;
    for (std::size_t j = 0; j < history.size(); ++j) {
      s.surface += history[j] / n;
      (j < half ? first : second) += history[j];
    }
    if (half > 0) s.drift = second / (history.size() - half) - first / half;
    s.volume = volume[k] / n;
    s.reference = fine.free_surface(s.x);
    s.coarse = coarse.free_surface(s.x);
    s.exact = exact.free_surface(s.x);
    if (k + 1 == n_st)
      out.exit = s;
    else
      out.stations.push_back(s);
  }
  for (std::size_t c = 0; c < n_columns; ++c) {
    const double xc = (c + 0.5) * dp;
    out.profile_x.push_back(xc);
    out.profile_surface.push_back(column_sum[c] / n);
    out.profile_reference.push_back(fine.free_surface(xc));
    out.profile_exact.push_back(exact.free_surface(xc));
  }
  return out;
}

}  // namespace porosph::validation
