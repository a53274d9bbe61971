#include "tools/validation/soil_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {
namespace {

/// The last snapshot of OUT/soil.h5 with the fields the checks need.
struct SoilSnapshot {
  double time = 0;
  std::size_t n = 0, dim = 0;
  std::vector<double> position, velocity, displacement, stress;
  std::vector<std::uint8_t> fixed;
  std::vector<std::int64_t> material, id;
};

SoilSnapshot read_last_soil_snapshot(const std::string& run_dir) {
  io::SnapshotReader reader(run_dir + "/soil.h5");
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/soil.h5 has no snapshot");
  const auto last = snapshots.back();
  SoilSnapshot s;
  s.time = last.time;
  const auto position = reader.read_f64(last.index, "position");
  s.n = position.rows;
  s.dim = position.cols;
  s.position = position.values;
  s.velocity = reader.read_f64(last.index, "velocity").values;
  s.displacement = reader.read_f64(last.index, "displacement").values;
  s.stress = reader.read_f64(last.index, "stress").values;
  s.fixed = reader.read_u8(last.index, "fixed").values;
  s.material = reader.read_i64(last.index, "material").values;
  s.id = reader.read_i64(last.index, "id").values;
  return s;
}

/// Replaces s.stress by each particle's mean over the snapshots later than `after` [s] (matched by
/// id) when there are at least two; returns their number and the first one's time (1 and s.time
/// when it keeps the last snapshot's stress).
std::pair<std::size_t, double> average_stress_after(const std::string& run_dir, double after,
                                                    SoilSnapshot& s) {
  io::SnapshotReader reader(run_dir + "/soil.h5");
  std::vector<io::SnapshotInfo> later;
  for (const auto& info : reader.snapshots())
    if (info.time > after * (1.0 + 1e-9)) later.push_back(info);
  if (later.size() < 2) return {1, s.time};
  std::map<std::int64_t, std::size_t> slot;
  for (std::size_t i = 0; i < s.n; ++i) slot[s.id[i]] = i;
  std::vector<double> sum(s.stress.size(), 0.0);
  for (const auto& info : later) {
    const auto id = reader.read_i64(info.index, "id").values;
    const auto stress = reader.read_f64(info.index, "stress").values;
    if (id.size() != s.n || stress.size() != s.stress.size())
      throw std::runtime_error(run_dir + "/soil.h5: the particles change between snapshots");
    for (std::size_t k = 0; k < id.size(); ++k) {
      const auto it = slot.find(id[k]);
      if (it == slot.end())
        throw std::runtime_error(run_dir + "/soil.h5: the particles change between snapshots");
      for (int c = 0; c < 9; ++c) sum[it->second * 9 + c] += stress[k * 9 + c];
    }
  }
  for (std::size_t k = 0; k < sum.size(); ++k)
    s.stress[k] = sum[k] / static_cast<double>(later.size());
  return {later.size(), later.front().time};
}

double speed_of(const SoilSnapshot& s, std::size_t i) {
  double v2 = 0;
  for (std::size_t k = 0; k < s.dim; ++k)
    v2 += s.velocity[i * s.dim + k] * s.velocity[i * s.dim + k];
  return std::sqrt(v2);
}

/// Initial position of particle i: x - displacement.
double initial(const SoilSnapshot& s, std::size_t i, std::size_t k) {
  return s.position[i * s.dim + k] - s.displacement[i * s.dim + k];
}

}  // namespace

SoilColumnCheck check_soil_column(const std::string& run_dir, double band) {
  const auto run = read_run_json(run_dir);
  const auto& parameters = run.at("parameters");
  const double dp = parameters.at("run").at("dp").get<double>();
  const auto gravity = parameters.at("run").at("gravity").get<std::vector<double>>();
  const auto& materials = parameters.at("soil").at("materials");
  const double damping = parameters.at("soil").value("damping_duration", 0.0);
  SoilSnapshot s = read_last_soil_snapshot(run_dir);
  SoilColumnCheck out;
  std::tie(out.snapshots, out.averaged_from) = average_stress_after(run_dir, damping, s);
  out.band = band;
  const std::size_t dim = s.dim;
  double g = 0;
  for (double c : gravity) g += c * c;
  g = std::sqrt(g);
  std::vector<double> up(dim);
  for (std::size_t k = 0; k < dim; ++k) up[k] = -gravity[k] / g;

  out.time = s.time;
  const double nu = materials.at(0).value("poisson_ratio", std::nan(""));
  const double phi = materials.at(0).at("friction_angle").get<double>() * M_PI / 180.0;
  out.k0_elastic = nu / (1.0 - nu);
  out.k0_jaky = 1.0 - std::sin(phi);

  // Initial columns: bin by the initial horizontal position (the part of x0 normal to up).
  struct Member {
    double height;
    std::size_t i;
  };
  std::map<std::vector<long>, std::vector<Member>> columns;
  double top = -INFINITY, bottom = INFINITY;
  std::vector<double>
      origin;  // a free particle's initial position: the lattice is whole dp from it
  for (std::size_t i = 0; i < s.n && origin.empty(); ++i) {
    if (!s.fixed[i])
      for (std::size_t k = 0; k < dim; ++k) origin.push_back(initial(s, i, k));
  }
  for (std::size_t i = 0; i < s.n; ++i) {
    if (s.fixed[i]) continue;
    out.max_speed = std::max(out.max_speed, speed_of(s, i));
    double height = 0;
    for (std::size_t k = 0; k < dim; ++k) height += (initial(s, i, k) - origin[k]) * up[k];
    std::vector<long> key;
    for (std::size_t k = 0; k < dim; ++k) {
      key.push_back(std::lround((initial(s, i, k) - origin[k] - height * up[k]) / dp));
    }
    columns[key].push_back({height, i});
    top = std::max(top, height);
    bottom = std::min(bottom, height);
  }
  std::map<long, std::pair<double, double>> row_error;  // row -> (sum sigma_v, sum exact)
  std::map<long, std::pair<double, double>> row_ratio;  // row -> (sum ratio, count)
  double sum_error = 0, sum_ratio = 0, sum_zz = 0;
  for (auto& [key, members] : columns) {
    std::sort(members.begin(), members.end(),
              [](const Member& a, const Member& b) { return a.height > b.height; });
    double weight_above = 0;
    for (const Member& m : members) {
      const double rho = materials.at(s.material[m.i]).at("density").get<double>();
      const double exact = -g * (weight_above + 0.5 * rho * dp);
      weight_above += rho * dp;
      const long row_from_top = std::lround((top - m.height) / dp);
      const long row_from_bottom = std::lround((m.height - bottom) / dp);
      if (row_from_top < 2 || row_from_bottom < 2) continue;
      const bool in_band = top - m.height + 0.5 * dp > band && m.height - bottom + 0.5 * dp > band;
      const double* sigma = &s.stress[m.i * 9];
      double sigma_v = 0, trace_in_plane = 0;
      for (std::size_t a = 0; a < dim; ++a) {
        trace_in_plane += sigma[a * 3 + a];
        for (std::size_t b = 0; b < dim; ++b) sigma_v += up[a] * sigma[a * 3 + b] * up[b];
      }
      const double sigma_h = (trace_in_plane - sigma_v) / static_cast<double>(dim - 1);
      const double error = std::abs(sigma_v - exact) / std::abs(exact);
      out.max_rel_error_two_rows = std::max(out.max_rel_error_two_rows, error);
      if (!in_band) continue;
      out.max_rel_error = std::max(out.max_rel_error, error);
      sum_error += error;
      sum_ratio += sigma_h / sigma_v;
      if (dim == 2) sum_zz += sigma[8] / sigma_v;
      ++out.particles;
      row_error[row_from_top].first += sigma_v;
      row_error[row_from_top].second += exact;
      row_ratio[row_from_top].first += sigma_h / sigma_v;
      row_ratio[row_from_top].second += 1.0;
    }
  }
  if (out.particles == 0)
    throw std::runtime_error(run_dir + ": no soil below the top two rows and the top band");
  const double count = static_cast<double>(out.particles);
  out.mean_rel_error = sum_error / count;
  out.mean_ratio = sum_ratio / count;
  out.mean_out_of_plane_ratio = sum_zz / count;
  out.min_ratio = INFINITY;
  out.max_ratio = -INFINITY;
  for (const auto& [row, sums] : row_error) {
    out.max_row_rel_error =
        std::max(out.max_row_rel_error, std::abs(sums.first - sums.second) / std::abs(sums.second));
    const double ratio = row_ratio[row].first / row_ratio[row].second;
    out.min_ratio = std::min(out.min_ratio, ratio);
    out.max_ratio = std::max(out.max_ratio, ratio);
  }
  return out;
}

double bulk_front(const std::vector<double>& position, const std::vector<std::uint8_t>& fixed,
                  double x_wall, double y_base, double dp, double min_thickness) {
  std::map<long, double> column_top;  // column index from the wall -> highest top
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    if (fixed[i]) continue;
    const long column = static_cast<long>(std::floor((position[i * 2] - x_wall) / dp));
    const double top = position[i * 2 + 1] - y_base + 0.5 * dp;
    auto [it, inserted] = column_top.emplace(column, top);
    if (!inserted) it->second = std::max(it->second, top);
  }
  for (auto it = column_top.rbegin(); it != column_top.rend(); ++it)
    if (it->second >= min_thickness) return static_cast<double>(it->first + 1) * dp;
  return 0.0;
}

CollapseMeasurement measure_collapse(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const double dp = run.at("parameters").at("run").at("dp").get<double>();
  const SoilSnapshot s = read_last_soil_snapshot(run_dir);
  if (s.dim != 2) throw std::runtime_error(run_dir + ": the collapse measurement is 2D only");
  CollapseMeasurement out;
  out.time = s.time;
  double x_wall = INFINITY, x_end = -INFINITY, y_top = -INFINITY;
  for (std::size_t i = 0; i < s.n; ++i) {
    if (s.fixed[i]) continue;
    x_wall = std::min(x_wall, initial(s, i, 0) - 0.5 * dp);
    x_end = std::max(x_end, initial(s, i, 0) + 0.5 * dp);
    y_top = std::max(y_top, initial(s, i, 1) + 0.5 * dp);
  }
  double y_base = INFINITY;
  for (std::size_t i = 0; i < s.n; ++i)
    if (!s.fixed[i]) y_base = std::min(y_base, initial(s, i, 1) - 0.5 * dp);
  out.initial_width = x_end - x_wall;
  out.initial_height = y_top - y_base;
  for (std::size_t i = 0; i < s.n; ++i) {
    if (s.fixed[i]) continue;
    ++out.particles;
    const double x = s.position[i * 2], y = s.position[i * 2 + 1];
    out.runout = std::max(out.runout, x - x_wall + 0.5 * dp);
    if (x - x_wall < 2.0 * dp)
      out.height_at_wall = std::max(out.height_at_wall, y - y_base + 0.5 * dp);
    out.max_speed = std::max(out.max_speed, speed_of(s, i));
  }
  out.bulk_runout = bulk_front(s.position, s.fixed, x_wall, y_base, dp, 0.1 * out.initial_height);
  const double factors[3] = {0.5, 1.0, 2.0};
  for (int t = 0; t < 3; ++t) {
    const double threshold = factors[t] * dp;
    out.thresholds[t] = threshold;
    // Top unmoved particle of each initial column (initial coordinates).
    std::map<long, double> top_unmoved;
    for (std::size_t i = 0; i < s.n; ++i) {
      if (s.fixed[i]) continue;
      const double u = std::hypot(s.displacement[i * 2], s.displacement[i * 2 + 1]);
      if (u >= threshold) continue;
      const long column = std::lround((initial(s, i, 0) - x_wall) / dp - 0.5);  // whole numbers
      const double y0 = initial(s, i, 1) - y_base + 0.5 * dp;
      auto [it, inserted] = top_unmoved.emplace(column, y0);
      if (!inserted) it->second = std::max(it->second, y0);
    }
    // Fit through the columns where the surface is inside the column (not at its top or base).
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (const auto& [column, y] : top_unmoved) {
      if (y >= out.initial_height - 1.01 * dp || y <= 1.01 * dp) continue;
      const double x = (column + 0.5) * dp;
      sx += x, sy += y, sxx += x * x, sxy += x * y, n += 1;
    }
    const double slope = n >= 2 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : std::nan("");
    out.failure_angle_deg[t] = std::atan(std::abs(slope)) * 180.0 / M_PI;
  }
  return out;
}

}  // namespace porosph::validation
