#include "tools/validation/dam_case_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/snapshot_reader.h"
#include "porous/permeability.h"
#include "tools/validation/run_directory.h"

namespace porosph::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SoilParticles2D read_soil(const io::SnapshotReader& reader, std::uint32_t index) {
  SoilParticles2D s;
  const auto position = reader.read_f64(index, "position");
  if (position.cols != 2) throw std::runtime_error(reader.path() + ": the dam cases are 2D");
  s.position = position.values;
  s.displacement = reader.read_f64(index, "displacement").values;
  s.fixed = reader.read_u8(index, "fixed").values;
  s.material = reader.read_i64(index, "material").values;
  const auto fields = reader.fields(index);
  if (std::find(fields.begin(), fields.end(), "saturation") != fields.end())
    s.saturation = reader.read_f64(index, "saturation").values;
  return s;
}

/// Mean of a time-series column over the rows with t >= t_from (NaN rows skipped).
double mean_from(const TimeSeries& ts, const std::string& name, double t_from) {
  const auto& t = ts.column("t");
  const auto& v = ts.column(name);
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] >= t_from && std::isfinite(v[i])) {
      sum += v[i];
      ++n;
    }
  }
  return n ? sum / n : kNaN;
}

int material_index(const nlohmann::json& soil, const std::string& name) {
  const auto& materials = soil.at("materials");
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].at("name").get<std::string>() == name) return static_cast<int>(m);
  throw std::runtime_error("run.json: no soil material named '" + name + "'");
}

}  // namespace

double rockfill_b(const SoilParticles2D& soil, double x_toe, double x_crest, double threshold,
                  double wet_saturation) {
  if (wet_saturation > 0 && soil.saturation.size() != soil.size())
    throw std::runtime_error("rockfill B of the wet particles needs the saturation field");
  double x_most_upstream = x_toe;
  for (std::size_t i = 0; i < soil.size(); ++i) {
    if (soil.fixed[i]) continue;
    if (wet_saturation > 0 && soil.saturation[i] < wet_saturation) continue;
    const double ux = soil.displacement[2 * i], uy = soil.displacement[2 * i + 1];
    const double x0 = soil.position[2 * i] - ux;
    if (x0 < x_crest || std::hypot(ux, uy) <= threshold) continue;
    x_most_upstream = std::min(x_most_upstream, x0);
  }
  return x_toe - x_most_upstream;
}

double dupuit_forchheimer_height(double distance_from_exit, double discharge_per_metre, double a,
                                 double b) {
  const double q = discharge_per_metre;
  if (!(distance_from_exit > 0) || !(q > 0) || a < 0 || b < 0 || a + b == 0) return 0.0;
  // Distance from the exit at which the table reaches height h (increasing in h).
  const auto length_of = [a, b, q](double h) {
    if (b == 0) return h * h / (2 * a * q);
    const double x = a * h / (b * q);  // h / c
    if (x < 1e-2)                      // series of c^2 ln(1 + x): the closed form cancels
      return h * h * h / (3 * b * q * q) * (1 - 0.75 * x + 0.6 * x * x);
    const double c = b * q / a;
    return (0.5 * h * h - c * h + c * c * std::log1p(x)) / (a * q);
  };
  double lo = 0, hi = 1e-3;
  while (length_of(hi) < distance_from_exit) hi *= 2;
  for (int k = 0; k < 200 && hi - lo > 1e-12 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (length_of(mid) < distance_from_exit ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double lowest_in_band(const SoilParticles2D& soil, std::int64_t material, double x_lo,
                      double x_hi) {
  double lowest = kNaN;
  for (std::size_t i = 0; i < soil.size(); ++i) {
    const double x = soil.position[2 * i], y = soil.position[2 * i + 1];
    if (soil.fixed[i] || soil.material[i] != material || x < x_lo || x > x_hi) continue;
    if (!(y >= lowest)) lowest = y;  // also replaces the initial NaN
  }
  return lowest;
}

double free_area_left_of(const SoilParticles2D& soil, std::int64_t material, double x_max,
                         double dp) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < soil.size(); ++i)
    if (!soil.fixed[i] && soil.material[i] == material && soil.position[2 * i] < x_max) ++count;
  return static_cast<double>(count) * dp * dp;
}

double mean_settlement(const SoilParticles2D& soil, std::int64_t material, double x0_lo,
                       double x0_hi) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < soil.size(); ++i) {
    if (soil.fixed[i] || soil.material[i] != material) continue;
    const double x0 = soil.position[2 * i] - soil.displacement[2 * i];
    if (x0 < x0_lo || x0 > x0_hi) continue;
    sum -= soil.displacement[2 * i + 1];
    ++count;
  }
  return count ? sum / static_cast<double>(count) : kNaN;
}

RockfillCheck check_rockfill(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& p = run.at("parameters");
  RockfillCheck c;
  c.dp = p.at("run").at("dp").get<double>();
  const auto& soil = p.at("soil");
  c.d15 = soil.at("materials").at(0).at("d15").get<double>();
  const auto& inflow = p.at("water").at("inflow").at(0);
  c.flow_rate = inflow.at("flow_rate").get<double>();
  const double sheet = inflow.at("max").at(1).get<double>() - inflow.at("min").at(1).get<double>();
  c.flume_width = inflow.at("cross_section").get<double>() / sheet;
  c.discharge_per_metre = c.flow_rate / c.flume_width;
  // Toe: the shell polygon's vertex furthest downstream; crest end: the highest vertex furthest
  // downstream (the top of the slope).
  const auto& vertices = soil.at("blocks").at(0).at("vertices");
  double y_top = -1e300;
  for (const auto& v : vertices) y_top = std::max(y_top, v.at(1).get<double>());
  c.x_toe = -1e300;
  c.x_crest = -1e300;
  for (const auto& v : vertices) {
    c.x_toe = std::max(c.x_toe, v.at(0).get<double>());
    if (v.at(1).get<double>() == y_top) c.x_crest = std::max(c.x_crest, v.at(0).get<double>());
  }
  c.thresholds = {0.5 * c.d15, c.d15, 2 * c.d15};
  if (p.contains("coupling")) c.wet_saturation = p.at("coupling").value("wet_saturation", 0.1);
  if (std::abs(c.flow_rate - 0.01936) < 1e-6) {
    c.b_experiment = 0.32;
    c.b_paper_sph = 0.317;
  } else if (std::abs(c.flow_rate - 0.03045) < 1e-6) {
    c.b_experiment = 0.68;
    c.b_paper_sph = 0.697;
  }

  io::SnapshotReader reader(run_dir + "/soil.h5");
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/soil.h5 has no snapshot");
  for (const auto& snap : snapshots) {
    const auto s = read_soil(reader, snap.index);
    c.times.push_back(snap.time);
    c.b_history.push_back(rockfill_b(s, c.x_toe, c.x_crest, c.d15));
    c.b_wet_history.push_back(rockfill_b(s, c.x_toe, c.x_crest, c.d15, c.wet_saturation));
    if (&snap == &snapshots.back()) {
      c.time = snap.time;
      c.particles = s.size();
      for (int k = 0; k < 3; ++k) {
        c.b[k] = rockfill_b(s, c.x_toe, c.x_crest, c.thresholds[k]);
        c.b_wet[k] = rockfill_b(s, c.x_toe, c.x_crest, c.thresholds[k], c.wet_saturation);
      }
    }
  }
  const auto& gravel = soil.at("materials").at(0);
  const auto& water = p.at("water");
  double g = 0;
  for (const auto& component : p.at("run").at("gravity")) g += std::pow(component.get<double>(), 2);
  const auto coefficients = porous::forchheimer_den_adel(
      gravel.at("porosity").get<double>(), c.d15, std::sqrt(g),
      water.at("viscosity").get<double>() / water.at("rho0").get<double>(),
      gravel.at("den_adel_alpha").get<double>(), gravel.at("den_adel_beta").get<double>());
  c.seepage_a = coefficients.a;
  c.seepage_b = coefficients.b;
  for (int k = 0; k <= 100; ++k) {
    c.dupuit_x.push_back(c.x_toe * k / 100.0);
    c.dupuit_h.push_back(dupuit_forchheimer_height(
        c.x_toe - c.dupuit_x.back(), c.discharge_per_metre, c.seepage_a, c.seepage_b));
  }
  const auto ts = read_timeseries(run_dir);
  for (const auto& name : ts.names) {
    if (name.rfind("level_x", 0) != 0) continue;
    c.level_names.push_back(name);
    c.levels.push_back(mean_from(ts, name, 0.9 * c.time));
    double x = kNaN;
    for (const auto& o : p.value("observables", nlohmann::json::array()))
      if (o.at("name").get<std::string>() == name)
        x = 0.5 * (o.at("region_min").at(0).get<double>() + o.at("region_max").at(0).get<double>());
    c.level_x.push_back(x);
    c.level_dupuit.push_back(
        dupuit_forchheimer_height(c.x_toe - x, c.discharge_per_metre, c.seepage_a, c.seepage_b));
  }
  return c;
}

HeaveCheck check_heave(const std::string& run_dir) {
  const auto run = read_run_json(run_dir);
  const auto& p = run.at("parameters");
  HeaveCheck c;
  const auto& soil = p.at("soil");
  c.damping_end = soil.at("damping_duration").get<double>();
  bool found = false;
  for (const auto& wall : p.at("walls")) {
    if (wall.value("label", "") != "sheet_pile") continue;
    c.pile_tip = wall.at("min").at(1).get<double>();
    c.pile_face = wall.at("max").at(0).get<double>();
    c.pile_pit_face = wall.at("min").at(0).get<double>();
    found = true;
  }
  if (!found) throw std::runtime_error(run_dir + "/run.json: no wall labelled 'sheet_pile'");
  const int gravel = material_index(soil, "gravel");
  const int sand = material_index(soil, "sand");
  const double dp = p.at("run").at("dp").get<double>();
  const double band = 0.02;  // next to the pile: within 2 cm of its upstream face
  double sand_in_pit_at_start = kNaN;

  io::SnapshotReader reader(run_dir + "/soil.h5");
  const auto snapshots = reader.snapshots();
  if (snapshots.empty()) throw std::runtime_error(run_dir + "/soil.h5 has no snapshot");
  for (const auto& snap : snapshots) {
    const auto s = read_soil(reader, snap.index);
    const double bottom = lowest_in_band(s, gravel, c.pile_face, c.pile_face + band);
    const double t = snap.time - c.damping_end;
    if (c.times.empty()) c.gravel_top_of_sand = bottom;
    c.times.push_back(t);
    c.gravel_bottom.push_back(bottom);
    const double sand_in_pit = free_area_left_of(s, sand, c.pile_pit_face, dp);
    if (c.sand_crossed.empty()) sand_in_pit_at_start = sand_in_pit;
    c.sand_crossed.push_back(sand_in_pit - sand_in_pit_at_start);
    c.gravel_settlement.push_back(mean_settlement(s, gravel, c.pile_face, c.pile_face + band));
    if (c.failure_time < 0 && t >= 0 && bottom <= c.pile_tip) c.failure_time = t;
    c.end_time = t;
  }
  const auto ts = read_timeseries(run_dir);
  const auto& t = ts.column("t");
  const auto& up = ts.column("upstream_level");
  const auto& down = ts.column("downstream_level");
  for (std::size_t i = 0; i < t.size(); ++i) {
    c.head_times.push_back(t[i] - c.damping_end);
    c.head.push_back(up[i] - down[i]);
  }
  c.head_at_start = interpolate(c.head_times, c.head, 0.0);
  if (c.failure_time >= 0) c.head_at_failure = interpolate(c.head_times, c.head, c.failure_time);
  return c;
}

}  // namespace porosph::validation
