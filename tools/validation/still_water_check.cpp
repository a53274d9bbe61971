#include "tools/validation/still_water_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/run_files.h"
#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/still_water.h"

namespace porosph::validation {

namespace {

/// The last snapshot of a run's water.h5: heights along -g of the free particles, their pressure
/// and speed; the water's EOS; dp.
struct StillSnapshot {
  double time = 0, dp = 0, top = -INFINITY;
  StillWater water;
  std::vector<double> height, pressure, speed;
  std::vector<std::vector<double>> position;
};

StillSnapshot read_still_snapshot(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const auto& w = parameters.at("water");
  const auto gravity = parameters.at("run").at("gravity").get<std::vector<double>>();
  double g2 = 0;
  for (double x : gravity) g2 += x * x;
  StillSnapshot out;
  out.water = StillWater{w.at("rho0").get<double>(), w.at("sound_speed").get<double>(),
                         w.at("gamma").get<double>(), std::sqrt(g2)};
  out.dp = parameters.at("run").at("dp").get<double>();
  const std::size_t dim = gravity.size();

  io::SnapshotReader reader(io::water_snapshot_path(run_dir));
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/water.h5 has no snapshot");
  const auto last = snapshots.back();
  out.time = last.time;
  const auto position = reader.read_f64(last.index, "position");
  const auto velocity = reader.read_f64(last.index, "velocity");
  const auto pressure = reader.read_f64(last.index, "pressure");
  const auto fixed = reader.read_u8(last.index, "fixed");
  for (std::size_t i = 0; i < position.rows; ++i) {
    if (fixed.values[i]) continue;
    double s = 0, v2 = 0;
    for (std::size_t k = 0; k < dim; ++k) {
      s -= position.values[i * dim + k] * gravity[k] / out.water.g;
      v2 += velocity.values[i * dim + k] * velocity.values[i * dim + k];
    }
    out.height.push_back(s);
    out.pressure.push_back(pressure.values[i]);
    out.speed.push_back(std::sqrt(v2));
    out.position.emplace_back(position.values.begin() + i * dim,
                              position.values.begin() + (i + 1) * dim);
    out.top = std::max(out.top, s);
  }
  if (out.height.empty()) throw std::runtime_error(run_dir + "/water.h5: no free water");
  return out;
}

}  // namespace

HydrostaticCheck check_hydrostatic(const std::string& run_dir) {
  const StillSnapshot snap = read_still_snapshot(run_dir);
  const StillWater& water = snap.water;
  const double dp = snap.dp, top = snap.top;
  const double surface = top + 0.5 * dp;
  const double bottom = *std::min_element(snap.height.begin(), snap.height.end());
  HydrostaticCheck out;
  out.time = snap.time;
  out.depth = surface - (bottom - 0.5 * dp);
  const double scale = water.rho0 * water.g * out.depth;

  std::map<long, std::pair<double, double>> rows;  // row -> (sum of p, count)
  std::map<long, double> row_max_error;
  double sum_error = 0, bias = 0, bias_incompressible = 0;
  std::size_t in_bottom_quarter = 0;
  for (std::size_t i = 0; i < snap.height.size(); ++i) {
    out.max_speed_ratio =
        std::max(out.max_speed_ratio, snap.speed[i] / std::sqrt(water.g * out.depth));
    const double depth = surface - snap.height[i];
    const double exact = water.pressure(depth);
    if (snap.height[i] < bottom - 0.5 * dp + 0.25 * out.depth) {
      bias += snap.pressure[i] - exact;
      bias_incompressible += snap.pressure[i] - water.rho0 * water.g * depth;
      ++in_bottom_quarter;
    }
    const long row = std::lround((top - snap.height[i]) / dp);
    if (row < 2) continue;  // the top two rows are excluded (issue 2)
    const double error = std::abs(snap.pressure[i] - exact) / exact;
    out.max_rel_error = std::max(out.max_rel_error, error);
    out.max_scaled_error =
        std::max(out.max_scaled_error, std::abs(snap.pressure[i] - exact) / scale);
    sum_error += error;
    ++out.particles;
    row_max_error[row] = std::max(row_max_error[row], error);
    rows[row].first += snap.pressure[i];
    rows[row].second += 1.0;
  }
  if (out.particles == 0) throw std::runtime_error(run_dir + ": no water below the top two rows");
  out.mean_rel_error = sum_error / static_cast<double>(out.particles);
  out.bottom_quarter_bias = bias / static_cast<double>(in_bottom_quarter) / scale;
  out.bottom_quarter_bias_incompressible =
      bias_incompressible / static_cast<double>(in_bottom_quarter) / scale;
  for (const auto& [row, sum_count] : rows) {
    const double depth = surface - (top - row * dp);
    const double exact = water.pressure(depth);
    const double mean = sum_count.first / sum_count.second;
    out.max_row_rel_error = std::max(out.max_row_rel_error, std::abs(mean - exact) / exact);
    out.rows.push_back({depth, exact, mean, row_max_error[row]});
  }
  return out;
}

StillBedCheck check_still_bed(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& blocks = run.at("parameters").at("soil").at("blocks");
  if (blocks.empty() || blocks.at(0).at("shape").get<std::string>() != "box")
    throw std::runtime_error(run_dir + ": the still-bed check needs a box as first soil block");
  const auto lo = blocks.at(0).at("min").get<std::vector<double>>();
  const auto hi = blocks.at(0).at("max").get<std::vector<double>>();
  const auto gravity = run.at("parameters").at("run").at("gravity").get<std::vector<double>>();
  // The bed's extent along -g: the extremes of -g . x over the box's corners.
  double g2 = 0;
  for (double x : gravity) g2 += x * x;
  double bed_low = 0, bed_high = 0;
  for (std::size_t k = 0; k < gravity.size(); ++k) {
    const double a = -lo[k] * gravity[k] / std::sqrt(g2), b = -hi[k] * gravity[k] / std::sqrt(g2);
    bed_low += std::min(a, b);
    bed_high += std::max(a, b);
  }

  const StillSnapshot snap = read_still_snapshot(run_dir);
  const StillWater& water = snap.water;
  const double surface = snap.top + 0.5 * snap.dp;
  StillBedCheck out;
  out.time = snap.time;
  out.depth = surface - bed_low;
  out.compressibility = water.g * out.depth / (2.0 * water.c0 * water.c0);
  double head = 0, head_incompressible = 0;
  for (std::size_t i = 0; i < snap.height.size(); ++i) {
    out.max_speed_ratio =
        std::max(out.max_speed_ratio, snap.speed[i] / std::sqrt(water.g * out.depth));
    if (snap.height[i] > bed_low + 0.25 * (bed_high - bed_low)) continue;
    bool in_box = true;
    for (std::size_t k = 0; k < lo.size(); ++k)
      in_box = in_box && snap.position[i][k] >= lo[k] && snap.position[i][k] <= hi[k];
    if (!in_box) continue;
    head += snap.height[i] + water.pressure_head(snap.pressure[i]) - surface;
    head_incompressible += snap.height[i] + snap.pressure[i] / (water.rho0 * water.g) - surface;
    ++out.particles;
  }
  if (out.particles == 0) throw std::runtime_error(run_dir + ": no water in the bed's bottom");
  out.head_bias = head / static_cast<double>(out.particles) / out.depth;
  out.head_bias_incompressible =
      head_incompressible / static_cast<double>(out.particles) / out.depth;
  return out;
}

}  // namespace porosph::validation
