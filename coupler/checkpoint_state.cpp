#include "coupler/checkpoint_state.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace porosph::coupler {

namespace {

using nlohmann::json;

constexpr int kStateVersion = 1;

/// Finite doubles as numbers (nlohmann writes the shortest form that reads back exactly).
json exact(double value) {
  if (std::isfinite(value)) return value;
  if (std::isnan(value)) return "nan";
  return value > 0 ? "inf" : "-inf";
}

double exact_of(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string text = j.get<std::string>();
  if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  throw std::runtime_error("not a number: '" + text + "'");
}

json exact_vector(const std::vector<double>& v) {
  json out = json::array();
  for (double x : v) out.push_back(exact(x));
  return out;
}

std::vector<double> exact_vector_of(const json& j) {
  std::vector<double> out;
  for (const json& x : j) out.push_back(exact_of(x));
  return out;
}

json exact_map(const std::map<std::string, double>& m) {
  json out = json::object();
  for (const auto& [name, value] : m) out[name] = exact(value);
  return out;
}

std::map<std::string, double> exact_map_of(const json& j) {
  std::map<std::string, double> out;
  for (const auto& [name, value] : j.items()) out[name] = exact_of(value);
  return out;
}

json diagnostics_state(const coupling::Diagnostics& d) {
  return {{"particle_count", d.particle_count},
          {"free_count", d.free_count},
          {"removed_count", d.removed_count},
          {"mass", exact(d.mass)},
          {"kinetic_energy", exact(d.kinetic_energy)},
          {"max_speed", exact(d.max_speed)},
          {"momentum", exact_vector(d.momentum)},
          {"observables", exact_map(d.observables)},
          {"physics_seconds", exact(d.physics_seconds)},
          {"inflow_mass", exact(d.inflow_mass)},
          {"outflow_mass", exact(d.outflow_mass)},
          {"neighbours_per_particle", exact(d.neighbours_per_particle)},
          {"balance_momentum", exact_vector(d.balance_momentum)}};
}

coupling::Diagnostics diagnostics_of(const json& j) {
  coupling::Diagnostics d;
  d.particle_count = j.at("particle_count").get<std::uint64_t>();
  d.free_count = j.at("free_count").get<std::uint64_t>();
  d.removed_count = j.at("removed_count").get<std::uint64_t>();
  d.mass = exact_of(j.at("mass"));
  d.kinetic_energy = exact_of(j.at("kinetic_energy"));
  d.max_speed = exact_of(j.at("max_speed"));
  d.momentum = exact_vector_of(j.at("momentum"));
  d.observables = exact_map_of(j.at("observables"));
  d.physics_seconds = exact_of(j.at("physics_seconds"));
  d.inflow_mass = exact_of(j.at("inflow_mass"));
  d.outflow_mass = exact_of(j.at("outflow_mass"));
  d.neighbours_per_particle = exact_of(j.at("neighbours_per_particle"));
  if (j.contains("balance_momentum"))
    d.balance_momentum = exact_vector_of(j.at("balance_momentum"));
  return d;
}

json phase_state(const PhaseRecord& p) {
  json snapshots = json::array();
  for (const auto& s : p.snapshots) {
    snapshots.push_back(
        {{"index", s.index}, {"time", exact(s.time)}, {"particles", s.particle_count}});
  }
  return {{"phase", p.phase},
          {"solver_name", p.solver_name},
          {"solver_version", p.solver_version},
          {"h5_file", p.h5_file},
          {"initial", diagnostics_state(p.initial)},
          {"last", diagnostics_state(p.last)},
          {"snapshots", snapshots},
          {"physics_seconds", exact(p.reported.physics_seconds)},
          {"wall_seconds", exact(p.reported.wall_seconds)},
          {"communication_seconds", exact(p.reported.communication_seconds)},
          {"mass_imbalance_max", exact(p.mass_imbalance_max)},
          {"external_impulse",
           {{"sources", p.external.sources},
            {"impulse", exact_vector(p.external.impulse)},
            {"relative_residual_max", exact(p.external.relative_residual_max)},
            {"unknown", p.external.unknown}}}};
}

void restore_phase(const json& j, PhaseRecord& p) {
  p.phase = j.at("phase").get<std::string>();
  p.solver_name = j.at("solver_name").get<std::string>();
  p.solver_version = j.at("solver_version").get<std::string>();
  p.h5_file = j.at("h5_file").get<std::string>();
  p.initial = diagnostics_of(j.at("initial"));
  p.last = diagnostics_of(j.at("last"));
  p.mass_imbalance_max = exact_of(j.at("mass_imbalance_max"));
  p.external = ExternalImpulseRecord{};
  if (j.contains("external_impulse")) {
    const json& e = j.at("external_impulse");
    p.external.sources = e.at("sources").get<std::vector<std::string>>();
    p.external.impulse = exact_vector_of(e.at("impulse"));
    p.external.relative_residual_max = exact_of(e.at("relative_residual_max"));
    p.external.unknown = e.at("unknown").get<bool>();
  } else {  // a checkpoint from before the external-impulse books: their sums so far are unknown
    p.external.unknown = true;
  }
  p.snapshots.clear();
  for (const json& s : j.at("snapshots")) {
    p.snapshots.push_back({s.at("index").get<std::uint32_t>(), exact_of(s.at("time")),
                           s.at("particles").get<std::size_t>()});
  }
  p.reported.physics_seconds = exact_of(j.at("physics_seconds"));
  // Checkpoints written before the solvers reported wall and communication time lack them.
  p.reported.wall_seconds = j.contains("wall_seconds") ? exact_of(j.at("wall_seconds")) : 0.0;
  p.reported.communication_seconds =
      j.contains("communication_seconds") ? exact_of(j.at("communication_seconds")) : 0.0;
  p.before_resume = p.reported;
}

json interaction_state(const InteractionRecord& r) {
  return {{"active", r.active},
          {"evaluations", r.evaluations},
          {"pairs_min", r.pairs_min},
          {"pairs_max", r.pairs_max},
          {"pairs_last", r.pairs_last},
          {"pairs_sum", exact(r.pairs_sum)},
          {"water_overlap_max", r.water_overlap_max},
          {"soil_overlap_max", r.soil_overlap_max},
          {"seconds", exact(r.seconds)},
          {"dt_limit_min", exact(r.dt_limit_min)}};
}

void restore_interaction(const json& j, InteractionRecord& r) {
  r.active = j.at("active").get<bool>();
  r.evaluations = j.at("evaluations").get<std::uint64_t>();
  r.pairs_min = j.at("pairs_min").get<std::uint64_t>();
  r.pairs_max = j.at("pairs_max").get<std::uint64_t>();
  r.pairs_last = j.at("pairs_last").get<std::uint64_t>();
  r.pairs_sum = exact_of(j.at("pairs_sum"));
  r.water_overlap_max = j.at("water_overlap_max").get<std::uint64_t>();
  r.soil_overlap_max = j.at("soil_overlap_max").get<std::uint64_t>();
  r.seconds = exact_of(j.at("seconds"));
  r.dt_limit_min = exact_of(j.at("dt_limit_min"));
}

}  // namespace

std::string coupler_state_json(const RunRecord& r, const LoopState& loop) {
  json phases = json::object();
  for (const auto& [name, phase] : r.phases) phases[name] = phase_state(phase);
  const json out = {
      {"version", kStateVersion},
      {"loop",
       {{"output_index", loop.output_index},
        {"next_output_time", exact(loop.next_output_time)},
        {"last_output_time", exact(loop.last_output_time)},
        {"row_index", loop.row_index},
        {"next_row_time", exact(loop.next_row_time)},
        {"last_row_time", exact(loop.last_row_time)},
        {"outputs_pending", loop.outputs_pending},
        {"controller_dt", exact(loop.controller_dt)}}},
      {"record",
       {{"scene_name", r.scene_name},
        {"scene_path", r.scene_path},
        {"resolved_toml", r.resolved_toml},
        {"dimension", r.dimension},
        {"steps", r.steps},
        {"time", exact(r.time)},
        {"end_time", exact(r.end_time)},
        {"wall_seconds", exact(r.wall_seconds)},
        {"coupler_seconds", exact(r.coupler_seconds)},
        {"dt_min", exact(r.dt_min)},
        {"dt_max", exact(r.dt_max)},
        {"dt_sum", exact(r.dt_sum)},
        {"dt_over_limit_max", exact(r.dt_over_limit_max)},
        {"phases", phases},
        {"ledger",
         {{"impulse_to_water", exact_vector(r.ledger.impulse_to_water)},
          {"impulse_to_soil", exact_vector(r.ledger.impulse_to_soil)},
          {"impulse_magnitude_sum", exact(r.ledger.impulse_magnitude_sum)},
          {"explicit_impulse_to_water", exact_vector(r.ledger.explicit_impulse_to_water)},
          {"explicit_impulse_to_soil", exact_vector(r.ledger.explicit_impulse_to_soil)}}},
        {"interaction", interaction_state(r.interaction)},
        {"observables", exact_map(r.observables)},
        {"resumes", r.resumes},
        {"transport_bytes_received", r.transport_bytes_received},
        {"transport_bytes_sent", r.transport_bytes_sent}}}};
  return out.dump(1) + "\n";
}

void restore_coupler_state(const std::string& text, const std::string& source, RunRecord& r,
                           LoopState& loop) {
  try {
    const json in = json::parse(text);
    if (in.at("version").get<int>() != kStateVersion) {
      throw std::runtime_error("written by another version of the coupler");
    }
    const json& l = in.at("loop");
    loop.output_index = l.at("output_index").get<std::uint32_t>();
    loop.next_output_time = exact_of(l.at("next_output_time"));
    loop.last_output_time = exact_of(l.at("last_output_time"));
    if (l.contains("row_index")) {
      loop.row_index = l.at("row_index").get<std::uint64_t>();
      loop.next_row_time = exact_of(l.at("next_row_time"));
      loop.last_row_time = exact_of(l.at("last_row_time"));
    } else {  // a checkpoint from before run.timeseries_interval: one row per snapshot
      loop.row_index = loop.output_index;
      loop.next_row_time = loop.next_output_time;
      loop.last_row_time = loop.last_output_time;
    }
    loop.outputs_pending = l.at("outputs_pending").get<bool>();
    loop.controller_dt = exact_of(l.at("controller_dt"));
    const json& j = in.at("record");
    r.scene_name = j.at("scene_name").get<std::string>();
    r.scene_path = j.at("scene_path").get<std::string>();
    r.resolved_toml = j.at("resolved_toml").get<std::string>();
    r.dimension = j.at("dimension").get<int>();
    r.steps = j.at("steps").get<std::uint64_t>();
    r.time = exact_of(j.at("time"));
    r.end_time = exact_of(j.at("end_time"));
    r.wall_seconds = exact_of(j.at("wall_seconds"));
    r.coupler_seconds = exact_of(j.at("coupler_seconds"));
    r.dt_min = exact_of(j.at("dt_min"));
    r.dt_max = exact_of(j.at("dt_max"));
    r.dt_sum = exact_of(j.at("dt_sum"));
    if (j.contains("dt_over_limit_max")) r.dt_over_limit_max = exact_of(j.at("dt_over_limit_max"));
    for (const auto& [name, phase] : j.at("phases").items()) restore_phase(phase, r.phases[name]);
    const json& ledger = j.at("ledger");
    r.ledger.impulse_to_water = exact_vector_of(ledger.at("impulse_to_water"));
    r.ledger.impulse_to_soil = exact_vector_of(ledger.at("impulse_to_soil"));
    r.ledger.impulse_magnitude_sum = exact_of(ledger.at("impulse_magnitude_sum"));
    r.ledger.explicit_impulse_to_water = exact_vector_of(ledger.at("explicit_impulse_to_water"));
    r.ledger.explicit_impulse_to_soil = exact_vector_of(ledger.at("explicit_impulse_to_soil"));
    restore_interaction(j.at("interaction"), r.interaction);
    r.observables = exact_map_of(j.at("observables"));
    if (j.contains("transport_bytes_received")) {  // absent in checkpoints before 2026-12-02
      r.transport_bytes_received = j.at("transport_bytes_received").get<std::uint64_t>();
      r.transport_bytes_sent = j.at("transport_bytes_sent").get<std::uint64_t>();
    }
    r.resumes = j.at("resumes").get<std::uint32_t>();
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ": not a coupler checkpoint: " + e.what());
  }
}

}  // namespace porosph::coupler
