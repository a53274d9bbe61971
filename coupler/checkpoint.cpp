#include "coupler/checkpoint.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "coupler/run_directory.h"
#include "proto/checkpoint_names.h"

namespace porosph::coupler {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Writes `text` to `path` atomically (temp file + rename).
void write_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    errno = 0;
    std::ofstream file(tmp, std::ios::trunc);
    file << text;
    if (!file.flush())
      throw std::runtime_error("cannot write " + tmp + ": " + std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
  }
}

/// The first multiple of `interval` after `time` (by more than round-off).
double next_multiple(double time, double interval) {
  return (std::floor(time / interval + 1e-9) + 1.0) * interval;
}

}  // namespace

std::optional<CheckpointManifest> read_checkpoint_manifest(const std::string& out_dir) {
  const std::string dir = coupling::checkpoint_dir(out_dir);
  const std::string path = dir + "/latest.json";
  if (!fs::exists(path)) return std::nullopt;
  CheckpointManifest m;
  try {
    std::ifstream file(path);
    const json in = json::parse(file);
    m.index = in.at("index").get<std::uint32_t>();
    m.time = in.at("time").get<double>();
    m.step = in.at("step").get<std::uint64_t>();
    m.coupler_file = dir + "/" + in.at("coupler").get<std::string>();
    m.scene_hash = in.value("scene_hash", std::string());
    for (const auto& [phase, name] : in.at("solvers").items()) {
      m.solvers[phase] = dir + "/" + name.get<std::string>();
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a checkpoint manifest: " + e.what());
  }
  if (!fs::exists(m.coupler_file)) throw std::runtime_error(path + ": missing " + m.coupler_file);
  for (const auto& [phase, file] : m.solvers) {
    if (!fs::exists(file)) throw std::runtime_error(path + ": missing " + file);
  }
  return m;
}

std::optional<CheckpointManifest> load_latest_checkpoint(const std::string& out_dir,
                                                         RunRecord& record, LoopState& loop) {
  std::optional<CheckpointManifest> manifest = read_checkpoint_manifest(out_dir);
  if (!manifest) return manifest;
  std::ifstream file(manifest->coupler_file);
  std::stringstream text;
  text << file.rdbuf();
  restore_coupler_state(text.str(), manifest->coupler_file, record, loop);
  record.checkpoint_index = manifest->index;
  record.checkpoint_time = manifest->time;
  record.checkpoint_step = manifest->step;
  if (record.steps != manifest->step) {
    throw std::runtime_error(manifest->coupler_file + ": step " + std::to_string(record.steps) +
                             ", the manifest says " + std::to_string(manifest->step));
  }
  return manifest;
}

void check_checkpoint_scene(const std::string& out_dir, const CheckpointManifest& manifest,
                            const std::string& hash) {
  const std::string dir = coupling::checkpoint_dir(out_dir);
  if (!manifest.scene_hash.empty() && manifest.scene_hash != hash) {
    throw std::runtime_error(dir + "/latest.json names scene hash " + manifest.scene_hash + ", " +
                             manifest.coupler_file + " holds a scene with hash " + hash +
                             ": the checkpoint mixes files of two runs");
  }
  json record;
  try {
    std::ifstream file(out_dir + "/run.json");
    if (!file) return;  // no run.json to compare with
    record = json::parse(file);
  } catch (const std::exception&) {
    return;  // an unreadable run.json does not stop a resume
  }
  const json scene = record.value("scene", json::object());
  const std::string recorded = scene.is_object() ? scene.value("hash", std::string()) : "";
  if (!recorded.empty() && recorded != hash) {
    throw std::runtime_error("the checkpoint in " + dir + " is of another scene than " + out_dir +
                             "/run.json ('" + scene.value("name", std::string()) + "', hash " +
                             recorded + "; the checkpoint's: hash " + hash +
                             "): the directory holds files of two runs");
  }
}

namespace {

/// Each setting line of a resolved scene text, prefixed by its table: "coupling.x = 1" for a line
/// "x = 1" under [coupling], "[[water.reservoir]] x = 1" under an array of tables.
std::vector<std::string> qualified_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string table, line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string trimmed = line.substr(first);
    if (trimmed.rfind("[[", 0) == 0) {
      table = trimmed + " ";
    } else if (trimmed[0] == '[') {
      table = trimmed.substr(1, trimmed.find(']') - 1) + ".";
    } else {
      lines.push_back(table + trimmed);
    }
  }
  return lines;
}

}  // namespace

std::vector<std::string> keys_added_since(const std::string& run_text,
                                          const std::string& resolved_now) {
  std::multiset<std::string> before;
  for (std::string& line : qualified_lines(run_text)) before.insert(std::move(line));
  std::vector<std::string> added;
  for (std::string& line : qualified_lines(resolved_now)) {
    const auto found = before.find(line);
    if (found != before.end()) {
      before.erase(found);
    } else {
      added.push_back(std::move(line));
    }
  }
  return added;
}

std::vector<std::string> newer_key_notices(const std::string& run_text,
                                           const std::string& resolved_now) {
  std::vector<std::string> notices;
  for (const std::string& setting : keys_added_since(run_text, resolved_now)) {
    const std::size_t eq = setting.find(" = ");
    notices.push_back(setting.substr(0, eq) +
                      " is newer than the run's scene; from here on it takes this binary's "
                      "default, " +
                      (eq == std::string::npos ? "" : setting.substr(eq + 3)));
  }
  return notices;
}

CheckpointKeeper::CheckpointKeeper(const scene::Scene& scene, const std::string& out_dir,
                                   std::vector<std::string> phases, std::uint32_t last_index,
                                   double time)
    : dir_(coupling::checkpoint_dir(out_dir)),
      scene_hash_(scene_hash(scene.resolved_toml)),
      phases_(std::move(phases)),
      interval_(scene.run.checkpoint_interval),
      wall_seconds_(60.0 * scene.run.checkpoint_wall_minutes),
      last_wall_(Clock::now()),
      last_index_(last_index),
      last_time_(last_index > 0 ? time : 0.0) {
  if (interval_ > 0) next_time_ = next_multiple(time, interval_);
}

bool CheckpointKeeper::due(double time, double dt, bool final_step, bool forced) {
  if (!enabled_ || pending_) return false;
  if (forced) return true;
  if (final_step) return false;
  if (interval_ > 0 && time + dt >= next_time_ - 1e-9 * interval_) return true;
  return wall_seconds_ > 0 &&
         std::chrono::duration<double>(Clock::now() - last_wall_).count() >= wall_seconds_;
}

std::uint32_t CheckpointKeeper::begin() {
  index_ = last_index_ + 1;
  return index_;
}

void CheckpointKeeper::hold(std::string coupler_state, double time, std::uint64_t step) {
  state_ = std::move(coupler_state);
  time_ = time;
  step_ = step;
  pending_ = true;
  if (interval_ > 0) next_time_ = next_multiple(time, interval_);
  last_wall_ = Clock::now();
}

std::string CheckpointKeeper::complete(const std::map<std::string, coupling::StepState>& states) {
  pending_ = false;
  for (const std::string& phase : phases_) {
    const auto it = states.find(phase);
    if (it == states.end() || it->second.checkpoint_written != index_) {
      return "the " + phase + " solver did not confirm checkpoint " + std::to_string(index_) +
             " (does it support checkpoints?)";
    }
  }
  const std::string coupler_name = coupling::checkpoint_file_name("coupler", index_, "json");
  write_atomically(dir_ + "/" + coupler_name, state_);
  json solvers = json::object();
  for (const std::string& phase : phases_) {
    solvers[phase] = coupling::checkpoint_file_name(phase, index_);
  }
  const json manifest = {{"index", index_},    {"time", time_},
                         {"step", step_},      {"coupler", coupler_name},
                         {"solvers", solvers}, {"scene_hash", scene_hash_}};
  write_atomically(dir_ + "/latest.json", manifest.dump(2) + "\n");
  // The manifest names the new files now: the previous checkpoint can go.
  if (last_index_ > 0 && last_index_ != index_) {
    std::error_code ignored;
    fs::remove(dir_ + "/" + coupling::checkpoint_file_name("coupler", last_index_, "json"),
               ignored);
    for (const std::string& phase : phases_) {
      fs::remove(dir_ + "/" + coupling::checkpoint_file_name(phase, last_index_), ignored);
    }
  }
  last_index_ = index_;
  last_time_ = time_;
  last_step_ = step_;
  state_.clear();
  return "";
}

}  // namespace porosph::coupler
