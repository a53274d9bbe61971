#include "tools/validation/consolidation_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/run_files.h"
#include "io/snapshot_reader.h"
#include "tools/validation/run_directory.h"
#include "tools/validation/terzaghi.h"

namespace porosph::validation {
namespace {

/// One snapshot of one phase: free particles only, the coordinate along the load's axis.
struct PhaseRows {
  std::vector<double> height;  ///< coordinate along the "up" axis [m]
  std::vector<double> value;   ///< pressure (water) or displacement along up (soil)
  std::vector<std::int64_t> id;
};

PhaseRows read_rows(const io::SnapshotReader& reader, std::uint32_t index, int up,
                    const std::string& field) {
  const auto position = reader.read_f64(index, "position");
  const auto fixed = reader.read_u8(index, "fixed");
  const auto values = reader.read_f64(index, field);
  const auto id = reader.read_i64(index, "id");
  PhaseRows rows;
  for (std::size_t i = 0; i < position.rows; ++i) {
    if (fixed.values[i]) continue;
    rows.height.push_back(position.values[i * position.cols + up]);
    rows.value.push_back(values.values[i * values.cols + (values.cols > 1 ? up : 0)]);
    rows.id.push_back(id.values[i]);
  }
  return rows;
}

/// Mean value per row [base + k dp, base + (k + 1) dp), k = 0 .. rows - 1 (NaN for an empty row).
std::vector<double> row_means(const PhaseRows& r, double base, double dp, std::size_t rows) {
  std::vector<double> sum(rows, 0.0), count(rows, 0.0);
  for (std::size_t i = 0; i < r.height.size(); ++i) {
    const double k = std::floor((r.height[i] - base) / dp);
    if (k < 0 || k >= static_cast<double>(rows)) continue;
    sum[static_cast<std::size_t>(k)] += r.value[i];
    count[static_cast<std::size_t>(k)] += 1.0;
  }
  for (std::size_t k = 0; k < rows; ++k) sum[k] = count[k] > 0 ? sum[k] / count[k] : std::nan("");
  return sum;
}

/// Mean value over the particles whose id is in `ids`.
double mean_of_ids(const PhaseRows& r, const std::map<std::int64_t, int>& ids) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < r.id.size(); ++i)
    if (ids.count(r.id[i])) sum += r.value[i], ++count;
  if (count == 0) throw std::runtime_error("the loaded top row left the soil output");
  return sum / count;
}

}  // namespace

ConsolidationCheck check_consolidation(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& par = run.at("parameters");
  const auto& soil = par.at("soil");
  if (!soil.contains("loads") || soil.at("loads").empty())
    throw std::runtime_error(run_dir +
                             ": the scene has no [[soil.loads]]: not a consolidation run");
  const auto& load = soil.at("loads").at(0);
  const auto& material = soil.at("materials").at(0);
  if (material.at("seepage").get<std::string>() != "darcy_conductivity")
    throw std::runtime_error(run_dir + ": the check needs seepage = \"darcy_conductivity\"");
  const auto traction = load.at("traction").get<std::vector<double>>();
  int up = 0;  // the load's axis; the load pushes against "up"
  for (std::size_t k = 0; k < traction.size(); ++k)
    if (traction[k] != 0.0) up = static_cast<int>(k);
  const auto gravity = par.at("run").at("gravity").get<std::vector<double>>();
  double g = 0.0;
  for (double c : gravity) g += c * c;
  g = std::sqrt(g);

  ConsolidationCheck out;
  out.dp = par.at("run").at("dp").get<double>();
  out.p0 = std::abs(traction[up]);
  out.load_time = load.at("start_time").get<double>();
  out.ramp_time = load.at("ramp_time").get<double>();
  const double rho_w = par.at("water").at("rho0").get<double>();
  const double c = par.at("water").at("sound_speed").get<double>();
  const double constrained = material.at("bulk_modulus").get<double>() +
                             4.0 / 3.0 * material.at("shear_modulus").get<double>();
  out.m_v = 1.0 / constrained;
  out.bulk_water = rho_w * c * c;
  const double k = material.at("hydraulic_conductivity").get<double>();
  out.c_v = k / (rho_w * g * (out.m_v + 1.0 / out.bulk_water));
  out.b_model = 1.0 / (1.0 + 1.0 / (out.m_v * out.bulk_water));
  const double n = material.at("porosity").get<double>();
  out.b_textbook = 1.0 / (1.0 + n / (out.m_v * out.bulk_water));

  io::SnapshotReader soil_h5(run_dir + "/soil.h5"), water_h5(io::water_snapshot_path(run_dir));
  const auto snapshots = soil_h5.snapshots();
  const auto water_snapshots = water_h5.snapshots();
  if (snapshots.size() < 3 || water_snapshots.size() != snapshots.size())
    throw std::runtime_error(run_dir + ": too few outputs, or soil.h5 and water.h5 differ");
  // The column at t = 0: its base, top and the loaded top row (ids).
  const PhaseRows soil0 = read_rows(soil_h5, snapshots[0].index, up, "displacement");
  const PhaseRows water0 = read_rows(water_h5, water_snapshots[0].index, up, "pressure");
  const double base = *std::min_element(soil0.height.begin(), soil0.height.end()) - 0.5 * out.dp;
  const double top_row = *std::max_element(soil0.height.begin(), soil0.height.end());
  const double pool = *std::max_element(water0.height.begin(), water0.height.end()) + 0.5 * out.dp;
  out.height = top_row + 0.5 * out.dp - base;
  std::map<std::int64_t, int> top_ids;
  for (std::size_t i = 0; i < soil0.id.size(); ++i)
    if (soil0.height[i] > top_row - 0.5 * out.dp) top_ids[soil0.id[i]] = 1;
  const double saturated = material.contains("saturated_density")
                               ? material.at("saturated_density").get<double>()
                               : material.at("density").get<double>() + n * rho_w;
  const double undrained_speed = std::sqrt((constrained + out.bulk_water) / saturated);
  out.undrained_period = 4.0 * (pool - base) / undrained_speed;

  const TerzaghiColumn closed(out.height, out.c_v, out.b_model, out.m_v, out.p0, out.ramp_time);
  const std::size_t rows = static_cast<std::size_t>(std::lround(out.height / out.dp));
  // The state when the load starts: the mean over the outputs of one undrained period before it
  // (the column still rings a little from its start; the reference must not catch one phase).
  std::size_t ref = 0;
  while (ref + 1 < snapshots.size() && snapshots[ref + 1].time <= out.load_time + 1e-12) ++ref;
  double s_ref = 0.0;
  std::vector<double> p_ref(rows, 0.0);
  int ref_count = 0;
  for (std::size_t s = 0; s <= ref; ++s) {
    if (snapshots[s].time < out.load_time - out.undrained_period - 1e-12) continue;
    s_ref += mean_of_ids(read_rows(soil_h5, snapshots[s].index, up, "displacement"), top_ids);
    const std::vector<double> p = row_means(
        read_rows(water_h5, water_snapshots[s].index, up, "pressure"), base, out.dp, rows);
    for (std::size_t r = 0; r < rows; ++r) p_ref[r] += p[r];
    ++ref_count;
  }
  s_ref /= ref_count;
  for (double& p : p_ref) p /= ref_count;
  const double bottom_depth = out.height - 0.5 * out.dp;

  std::vector<double> targets = {0.1, 0.2, 0.5};
  std::vector<std::size_t> nearest(targets.size(), ref);
  for (std::size_t s = ref + 1; s < snapshots.size(); ++s) {
    ConsolidationSample x;
    x.time_factor = closed.time_factor(snapshots[s].time - out.load_time);
    const double load = closed.load_fraction(x.time_factor);
    x.settlement =
        -(mean_of_ids(read_rows(soil_h5, snapshots[s].index, up, "displacement"), top_ids) - s_ref);
    x.settlement_closed = closed.settlement(x.time_factor);
    const double drained = out.m_v * out.height * out.p0 * load;
    x.degree = (x.settlement / drained - (1.0 - out.b_model)) / out.b_model;
    x.degree_closed = closed.degree(x.time_factor);
    const std::vector<double> p = row_means(
        read_rows(water_h5, water_snapshots[s].index, up, "pressure"), base, out.dp, rows);
    x.bottom_pressure = (p[0] - p_ref[0]) / out.p0;
    x.bottom_pressure_closed = closed.excess_pressure(bottom_depth, x.time_factor) / out.p0;
    out.samples.push_back(x);
    if (x.time_factor >= 0.05 && x.time_factor <= 1.0)
      out.max_degree_error = std::max(out.max_degree_error, std::abs(x.degree - x.degree_closed));
    for (std::size_t j = 0; j < targets.size(); ++j) {
      const double best = closed.time_factor(snapshots[nearest[j]].time - out.load_time);
      if (std::abs(x.time_factor - targets[j]) < std::abs(best - targets[j])) nearest[j] = s;
    }
  }
  if (out.samples.empty()) throw std::runtime_error(run_dir + ": no output after the load");
  // Isochrones: Terzaghi's quasi-static field against the dynamic model's, both averaged over the
  // outputs of one undrained period centred on the target time (the ringing the load's start
  // leaves, +-0.02 p0, averages out; the same filter as for B below).
  for (std::size_t j = 0; j < targets.size(); ++j) {
    Isochrone iso;
    const double centre = snapshots[nearest[j]].time;
    iso.time_factor = closed.time_factor(centre - out.load_time);
    iso.measured.assign(rows, 0.0);
    iso.closed.assign(rows, 0.0);
    int count = 0;
    for (std::size_t s = ref + 1; s < snapshots.size(); ++s) {
      if (std::abs(snapshots[s].time - centre) > 0.5 * out.undrained_period + 1e-12) continue;
      const double tf = closed.time_factor(snapshots[s].time - out.load_time);
      const std::vector<double> p = row_means(
          read_rows(water_h5, water_snapshots[s].index, up, "pressure"), base, out.dp, rows);
      for (std::size_t r = 0; r < rows; ++r) {
        iso.measured[r] += (p[r] - p_ref[r]) / out.p0;
        iso.closed[r] += closed.excess_pressure(out.height - (r + 0.5) * out.dp, tf) / out.p0;
      }
      ++count;
    }
    for (std::size_t r = 0; r < rows; ++r) {
      iso.depth.push_back(out.height - (r + 0.5) * out.dp);
      iso.measured[r] /= count;
      iso.closed[r] /= count;
      iso.max_error = std::max(iso.max_error, std::abs(iso.measured[r] - iso.closed[r]));
    }
    out.isochrones.push_back(iso);
  }
  // B: the lowest row's pore pressure over one undrained period after the ramp, against the
  // closed form over the same outputs (the ringing of the load's start averages out).
  const double w0 = closed.time_factor(out.ramp_time);
  const double w1 = closed.time_factor(out.ramp_time + out.undrained_period);
  double measured = 0.0, expected = 0.0;
  for (const auto& x : out.samples) {
    if (x.time_factor < w0 || x.time_factor > w1) continue;
    measured += x.bottom_pressure;
    expected += x.bottom_pressure_closed;
  }
  out.b_measured = expected > 0.0 ? out.b_model * measured / expected : std::nan("");
  out.b_error = out.b_measured / out.b_model - 1.0;
  const ConsolidationSample& last = out.samples.back();
  out.final_time_factor = last.time_factor;
  out.final_settlement = last.settlement;
  out.final_settlement_closed = last.settlement_closed;
  out.settlement_error = last.settlement / last.settlement_closed - 1.0;
  bool isochrones_met = true;
  for (const auto& iso : out.isochrones) isochrones_met = isochrones_met && iso.max_error <= 0.05;
  out.met = out.max_degree_error <= 0.03 && isochrones_met && std::abs(out.b_error) <= 0.03 &&
            std::abs(out.settlement_error) <= 0.03;
  return out;
}

}  // namespace porosph::validation
