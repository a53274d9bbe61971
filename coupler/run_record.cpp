#include "coupler/run_record.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "coupler/phase_slots.h"
#include "coupler/run_directory.h"

namespace porosph::coupler {

namespace {

using nlohmann::json;

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

/// JSON cannot hold NaN or infinity: those become null.
json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json vector_json(const std::vector<double>& v) {
  json out = json::array();
  for (double x : v) out.push_back(number(x));
  return out;
}

json resolved_scene_json(const std::string& toml_text) {
  if (toml_text.empty()) return nullptr;
  try {
    std::ostringstream text;
    text << toml::json_formatter{toml::parse(toml_text)};
    return json::parse(text.str());
  } catch (const std::exception&) {
    return toml_text;  // keep the text rather than lose it
  }
}

json diagnostics_json(const coupling::Diagnostics& d) {
  json out;
  out["particle_count"] = d.particle_count;
  out["free_count"] = d.free_count;
  out["removed_count"] = d.removed_count;
  out["mass"] = number(d.mass);
  out["momentum"] = vector_json(d.momentum);
  out["kinetic_energy"] = number(d.kinetic_energy);
  out["max_speed"] = number(d.max_speed);
  out["neighbours_per_particle"] = number(d.neighbours_per_particle);
  // The momentum the external-impulse books balance, where it is not `momentum` (the soil's
  // sum m^s v; docs/coupling.md).
  if (!d.balance_momentum.empty()) out["balance_momentum"] = vector_json(d.balance_momentum);
  return out;
}

json phase_json(const PhaseRecord& p) {
  json out;
  out["executable"] = p.executable;
  out["solver_name"] = p.solver_name;
  out["solver_version"] = p.solver_version;
  out["pid"] = p.pid;
  out["output_file"] = p.h5_file;
  out["particles"] = {{"total", p.last.particle_count},
                      {"free", p.last.free_count},
                      {"removed", p.last.removed_count}};
  // Mass balance: final = initial + inflow - outflow, apart from round-off (the ledger of mass),
  // at the end and at every output.
  out["mass"] = {{"initial", number(p.initial.mass)},
                 {"final", number(p.last.mass)},
                 {"inflow", number(p.last.inflow_mass)},
                 {"outflow", number(p.last.outflow_mass)},
                 {"relative_imbalance", number(p.mass_imbalance(p.last))},
                 {"relative_imbalance_max_over_outputs",
                  number(std::max(p.mass_imbalance_max, p.mass_imbalance(p.last)))}};
  out["initial"] = diagnostics_json(p.initial);
  out["final"] = diagnostics_json(p.last);
  out["snapshots"] = p.snapshots.size();
  out["terms"] = p.terms;
  json fields = json::array();
  for (const coupling::OutputField& f : p.output_fields)
    fields.push_back({{"name", f.name},
                      {"components", f.components},
                      {"type", f.number_type},
                      {"unit", f.unit}});
  out["output_fields"] = fields;  // as the solver declared them (empty: none declared)
  const coupling::Timing timing = phase_timing(p);
  out["wall_seconds"] = {{"total", number(timing.wall_seconds)},
                         {"physics", number(timing.physics_seconds)},
                         {"communication", number(timing.communication_seconds)}};
  out["finished"] = p.finished;
  return out;
}

json interaction_json(const InteractionRecord& r) {
  const double mean = r.evaluations ? r.pairs_sum / static_cast<double>(r.evaluations) : 0.0;
  return {{"evaluations", r.evaluations},
          {"pairs",
           {{"min", r.pairs_min},
            {"mean", number(mean)},
            {"max", r.pairs_max},
            {"last", r.pairs_last}}},
          {"overlap_max", {{"water", r.water_overlap_max}, {"soil", r.soil_overlap_max}}},
          {"dt_limit_min", number(r.dt_limit_min)},  // null: the interaction never limited dt
          {"seconds", number(r.seconds)},
          {"terms", r.terms}};
}

/// ledger.external_impulse.<phase> (the books by source) and ledger.momentum_balance.<phase> of
/// every phase whose solver books its external impulses (docs/coupling.md).
void add_external_ledgers(const RunRecord& r, json& ledger) {
  json books = json::object(), balances = json::object();
  const std::size_t dims = static_cast<std::size_t>(r.dimension);
  for (const auto& [name, phase] : r.phases) {
    if (!phase.external.booked()) continue;
    json sources = json::object();
    for (std::size_t s = 0; s < phase.external.sources.size(); ++s) {
      const auto first = phase.external.impulse.begin() + static_cast<std::ptrdiff_t>(s * dims);
      sources[phase.external.sources[s]] =
          vector_json(std::vector<double>(first, first + static_cast<std::ptrdiff_t>(dims)));
    }
    books[name] = sources;
    const MomentumBalance b = phase_momentum_balance(r, name);
    balances[name] = {{"momentum_change", vector_json(b.change)},
                      {"external_impulse", vector_json(b.external)},
                      {"exchange", vector_json(b.exchange)},
                      {"residual", vector_json(b.residual)},
                      {"scale", number(b.scale)},
                      {"relative_residual", number(b.relative)},
                      {"relative_residual_max_over_outputs",
                       number(std::max(b.relative, phase.external.relative_residual_max))}};
  }
  ledger["external_impulse"] = books;
  ledger["momentum_balance"] = balances;
}

}  // namespace

const std::vector<double>* exchange_impulse(const RunRecord& record, const std::string& phase) {
  if (phase == "water") return &record.ledger.impulse_to_water;
  if (phase == "soil") return &record.ledger.impulse_to_soil;
  return nullptr;
}

MomentumBalance phase_momentum_balance(const RunRecord& record, const std::string& phase) {
  const PhaseRecord& p = record.phases.at(phase);
  return momentum_balance(p.external, p.initial, p.last, exchange_impulse(record, phase),
                          record.dimension);
}

void ConservationLedger::add_step(double dt, const std::vector<double>& force_on_water,
                                  const std::vector<double>& force_on_soil,
                                  double force_magnitude_sum) {
  for (std::size_t k = 0; k < impulse_to_water.size() && k < force_on_water.size(); ++k) {
    impulse_to_water[k] += dt * force_on_water[k];
  }
  for (std::size_t k = 0; k < impulse_to_soil.size() && k < force_on_soil.size(); ++k) {
    impulse_to_soil[k] += dt * force_on_soil[k];
  }
  impulse_magnitude_sum += dt * force_magnitude_sum;
}

void InteractionRecord::add_step(bool evaluated, std::uint64_t pairs, std::uint64_t water_overlap,
                                 std::uint64_t soil_overlap, double dt_limit, double step_seconds) {
  seconds += step_seconds;
  water_overlap_max = std::max(water_overlap_max, water_overlap);
  soil_overlap_max = std::max(soil_overlap_max, soil_overlap);
  dt_limit_min = std::min(dt_limit_min, dt_limit);
  pairs_last = pairs;
  if (!evaluated) return;
  pairs_min = evaluations == 0 ? pairs : std::min(pairs_min, pairs);
  pairs_max = std::max(pairs_max, pairs);
  pairs_sum += static_cast<double>(pairs);
  ++evaluations;
}

void ConservationLedger::add_explicit_share(double dt, const std::vector<double>& force_on_water,
                                            const std::vector<double>& force_on_soil) {
  for (std::size_t k = 0; k < explicit_impulse_to_water.size() && k < force_on_water.size(); ++k)
    explicit_impulse_to_water[k] += dt * force_on_water[k];
  for (std::size_t k = 0; k < explicit_impulse_to_soil.size() && k < force_on_soil.size(); ++k)
    explicit_impulse_to_soil[k] += dt * force_on_soil[k];
}

double ConservationLedger::relative_imbalance() const {
  std::vector<double> total(impulse_to_water.size());
  for (std::size_t k = 0; k < total.size(); ++k)
    total[k] = impulse_to_water[k] + impulse_to_soil[k];
  return impulse_magnitude_sum > 0 ? norm(total) / impulse_magnitude_sum : 0.0;
}

coupling::Timing phase_timing(const PhaseRecord& p) {
  if (!p.finished) return p.reported;
  coupling::Timing t = p.before_resume;
  t.wall_seconds += p.timing.wall_seconds;
  t.physics_seconds += p.timing.physics_seconds;
  t.communication_seconds += p.timing.communication_seconds;
  return t;
}

void RunRecord::start_segment() {
  segment_start_ = std::chrono::steady_clock::now();
  wall_seconds_before_segment_ = wall_seconds;
}

void RunRecord::update_wall_seconds() {
  wall_seconds =
      wall_seconds_before_segment_ +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - segment_start_).count();
}

void RunRecord::record_dt(double dt, double dt_limit) {
  if (dt_limit > 0.0) dt_over_limit_max = std::max(dt_over_limit_max, dt / dt_limit);
  dt_min = std::min(dt_min, dt);
  dt_max = std::max(dt_max, dt);
  dt_sum += dt;
}

void write_run_json(const std::string& path, const RunRecord& r) {
  json out;
  out["status"] = r.status;
  out["message"] = r.message;
  out["scene"] = {
      {"name", r.scene_name}, {"path", r.scene_path}, {"hash", scene_hash(r.resolved_toml)}};
  out["coupler"] = {{"pid", r.coupler_pid}, {"host", r.coupler_host}, {"heartbeat_utc", utc_now()}};
  out["parameters"] = resolved_scene_json(r.resolved_toml);
  out["dimension"] = r.dimension;
  out["steps"] = r.steps;
  out["simulated_time"] = number(r.time);
  out["end_time"] = number(r.end_time);
  const double steps = static_cast<double>(std::max<std::uint64_t>(r.steps, 1));
  out["dt"] = {{"min", number(r.steps ? r.dt_min : 0.0)},
               {"mean", number(r.dt_sum / steps)},
               {"max", number(r.dt_max)},
               {"max_over_limit", number(r.dt_over_limit_max)}};
  json wall = {{"total", number(r.wall_seconds)}, {"coupler", number(r.coupler_seconds)}};
  for (const auto& [name, phase] : r.phases) wall[name] = phase_json(phase)["wall_seconds"];
  out["wall_seconds"] = wall;
  json phases = json::object();
  for (const auto& [name, phase] : r.phases) phases[name] = phase_json(phase);
  out["phases"] = phases;
  out["ledger"] = {{"impulse_to_water", vector_json(r.ledger.impulse_to_water)},
                   {"impulse_to_soil", vector_json(r.ledger.impulse_to_soil)},
                   {"impulse_magnitude_sum", number(r.ledger.impulse_magnitude_sum)},
                   {"relative_imbalance", number(r.ledger.relative_imbalance())}};
  {
    std::vector<double> implicit_water = r.ledger.impulse_to_water;
    std::vector<double> implicit_soil = r.ledger.impulse_to_soil;
    for (std::size_t k = 0; k < implicit_water.size(); ++k) {
      implicit_water[k] -= r.ledger.explicit_impulse_to_water[k];
      implicit_soil[k] -= r.ledger.explicit_impulse_to_soil[k];
    }
    out["ledger"]["explicit_share"] = {
        {"impulse_to_water", vector_json(r.ledger.explicit_impulse_to_water)},
        {"impulse_to_soil", vector_json(r.ledger.explicit_impulse_to_soil)}};
    out["ledger"]["implicit_share"] = {{"impulse_to_water", vector_json(implicit_water)},
                                       {"impulse_to_soil", vector_json(implicit_soil)}};
  }
  add_external_ledgers(r, out["ledger"]);
  if (r.interaction.active) out["interaction"] = interaction_json(r.interaction);
  out["transport"] = {
      {"bytes_received", r.transport_bytes_received},
      {"bytes_sent", r.transport_bytes_sent},
      {"dropped_messages", r.dropped_messages},
      {"bytes_per_step",
       number(static_cast<double>(r.transport_bytes_received + r.transport_bytes_sent) / steps)}};
  json observables = json::object();
  for (const auto& [name, value] : r.observables) observables[name] = number(value);
  out["observables"] = observables;
  if (r.phases.count("water"))
    out["mach"] = {{"max", number(r.mach.max)},
                   {"time", number(r.mach.time)},
                   {"step", r.mach.step},
                   {"warn_above", scene::kMachWarn},
                   {"limit", scene::kMachLimit}};
  out["resumes"] = r.resumes;
  out["checkpoint"] = r.checkpoint_index == 0 ? json(nullptr)
                                              : json{{"index", r.checkpoint_index},
                                                     {"time", number(r.checkpoint_time)},
                                                     {"step", r.checkpoint_step}};

  const std::string tmp = path + ".tmp";
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());  // no half-written run.json.tmp left behind
    throw std::runtime_error("cannot " + what + ": " + reason);
  };
  {
    errno = 0;
    std::ofstream file(tmp, std::ios::trunc);
    if (!file) fail("create " + tmp);
    file << out.dump(2) << "\n";
    file.close();
    if (!file) fail("write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("rename " + tmp + " to " + path);
}

std::vector<io::XdmfPhaseSeries> xdmf_series(const RunRecord& record, const std::string& out_dir,
                                             std::set<std::string>& phases_without_h5) {
  std::vector<io::XdmfPhaseSeries> series;
  for (const auto& [phase, phase_record] : record.phases) {
    if (phase_record.snapshots.empty()) continue;
    if (!std::filesystem::exists(std::filesystem::path(out_dir) / phase_record.h5_file)) {
      if (phases_without_h5.insert(phase).second) {
        std::fprintf(stderr, "coupler: the %s solver wrote no %s; run.xdmf leaves that phase out\n",
                     phase.c_str(), phase_record.h5_file.c_str());
      }
      continue;
    }
    series.push_back({phase, phase_record.h5_file, record.dimension,
                      xdmf_fields_of(record, phase_record), phase_record.snapshots});
  }
  return series;
}

std::string output_field_problem(const coupling::OutputField& field, int dimension) {
  const auto name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  };
  if (field.name.empty() || field.name.size() > 64 || field.name == "position" ||
      !std::all_of(field.name.begin(), field.name.end(), name_char))
    return "name '" + field.name + "' (1-64 of A-Z a-z 0-9 _ . -, not position)";
  const auto d = static_cast<std::uint32_t>(dimension);
  if (field.components != 1 && field.components != d && field.components != 9)
    return field.name + ": " + std::to_string(field.components) + " components (1, " +
           std::to_string(d) + " or 9)";
  if (field.number_type != "Float" && field.number_type != "Int" && field.number_type != "UChar")
    return field.name + ": type '" + field.number_type + "' (Float, Int or UChar)";
  const auto unit_char = [](char c) {
    return std::isprint(static_cast<unsigned char>(c)) && c != '"' && c != '<' && c != '>' &&
           c != '&';
  };
  if (field.unit.size() > 32 || !std::all_of(field.unit.begin(), field.unit.end(), unit_char))
    return field.name + ": unit '" + field.unit + "'";
  return "";
}

std::vector<io::XdmfField> xdmf_fields_of(const RunRecord& record, const PhaseRecord& phase) {
  if (phase.output_fields.empty()) {
    // The built-in water solver also writes the pore fields where the scene has soil; another
    // water solver need not.
    const bool pore_fields = phase.phase == "water" && record.phases.count("soil") > 0 &&
                             phase.solver_name == kBuiltInWaterSolverName;
    return snapshot_fields_of_phase(phase.phase, record.dimension, pore_fields);
  }
  std::vector<io::XdmfField> fields;
  for (const coupling::OutputField& f : phase.output_fields)
    fields.push_back({f.name, f.components, f.number_type});
  return fields;
}

std::vector<io::XdmfField> snapshot_fields_of_phase(const std::string& phase, int dimension,
                                                    bool pore_fields) {
  const std::size_t d = static_cast<std::size_t>(dimension);
  std::vector<io::XdmfField> fields = {{"velocity", d, "Float"}, {"density", 1, "Float"}};
  if (phase == "water") {  // fluid_solver/water_solver_output.cpp
    fields.push_back({"pressure", 1, "Float"});
    fields.push_back({"mass", 1, "Float"});
    if (pore_fields) {
      fields.push_back({"porosity", 1, "Float"});
      fields.push_back({"pore_velocity", d, "Float"});
    }
  }
  if (phase == "soil") {  // soil_solver/soil_output.h
    fields.push_back({"stress", 9, "Float"});
    fields.push_back({"porosity", 1, "Float"});
    fields.push_back({"plastic_strain", 1, "Float"});
    fields.push_back({"displacement", d, "Float"});
    fields.push_back({"saturation", 1, "Float"});
    fields.push_back({"material", 1, "Int"});
  }
  fields.push_back({"id", 1, "Int"});
  fields.push_back({"fixed", 1, "UChar"});
  return fields;
}

std::string h5_file_of_phase(const std::string& phase) { return phase_slot(phase).snapshot_file; }

}  // namespace porosph::coupler
