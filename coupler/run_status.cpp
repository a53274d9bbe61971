#include "coupler/run_status.h"

#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "coupler/run_directory.h"

namespace porosph::coupler {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// "coupler pid 1234 on host node7" from run.json's "coupler" object (or the lock file's text).
std::string coupler_of(const json& record, const LockProbe& lock) {
  if (record.is_object() && record.contains("coupler") && record["coupler"].is_object()) {
    const json& c = record["coupler"];
    return "coupler pid " + c.value("pid", json(0)).dump() + " on host " +
           c.value("host", std::string("?"));
  }
  if (!lock.owner.empty()) return "coupler " + lock.owner;
  return "coupler unknown";
}

/// "heartbeat 2026-12-03T14:05:09Z (42 s ago)", or "" without one.
std::string heartbeat_of(const json& record) {
  if (!record.is_object() || !record.contains("coupler")) return "";
  const std::string beat = record["coupler"].value("heartbeat_utc", std::string());
  if (beat.empty()) return "";
  std::tm utc{};
  std::istringstream in(beat);
  in >> std::get_time(&utc, "%Y-%m-%dT%H:%M:%SZ");
  std::string text = "; heartbeat " + beat;
  if (!in.fail()) {
    const double ago = std::difftime(std::time(nullptr), timegm(&utc));
    text += " (" + std::to_string(static_cast<long long>(ago)) + " s ago)";
  }
  return text;
}

/// "t = 0.1 s of 1 s, step 123" from run.json.
std::string progress_of(const json& record) {
  if (!record.is_object()) return "";
  std::ostringstream text;
  text << "t = " << record.value("simulated_time", json(0)).dump() << " s of "
       << record.value("end_time", json(0)).dump() << " s, step "
       << record.value("steps", json(0)).dump();
  return text.str();
}

}  // namespace

RunStatusReport run_status(const std::string& dir) {
  RunStatusReport report;
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    report.text = "no run: '" + dir + "' is not a directory";
    return report;
  }
  const LockProbe lock = probe_run_directory_lock(dir);
  const std::string record_path = (fs::path(dir) / "run.json").string();
  json record;
  std::string unreadable;
  if (fs::exists(record_path, error)) {
    try {
      std::ifstream file(record_path);
      record = json::parse(file);
    } catch (const std::exception& e) {
      unreadable = record_path + ": " + e.what();
    }
  }
  if (lock.held) {
    report.code = kStatusRunning;
    report.text = "running: " + coupler_of(record, lock) + " holds " + dir + "/" + kLockFileName;
    if (record.is_object()) report.text += "; " + progress_of(record) + heartbeat_of(record);
    return report;
  }
  if (!unreadable.empty()) {
    report.text = "no run: cannot read " + unreadable;
    return report;
  }
  const std::string status = record.is_object() ? record.value("status", std::string()) : "";
  if (status == "completed") {
    report.code = kStatusCompleted;
    report.text = "completed: " + progress_of(record);
  } else if (status == "failed") {
    report.code = kStatusFailed;
    report.text =
        "failed: " + record.value("message", std::string()) + " (" + progress_of(record) + ")";
  } else if (status == "running" || lock.exists) {
    report.code = kStatusDied;
    report.text =
        "died: " +
        std::string(record.is_object() ? "run.json says running" : "the run wrote no run.json") +
        " but no coupler holds " + dir + "/" + kLockFileName + " (" + coupler_of(record, lock) +
        heartbeat_of(record) +
        "): the coupler was killed, or it could not write run.json (its stderr says "
        "why); coupler run --resume " +
        dir + " continues from its checkpoint, if any";
    if (record.is_object()) report.text += "; last " + progress_of(record);
  } else {
    report.text = "no run: " + dir + " holds no run.json";
  }
  return report;
}

}  // namespace porosph::coupler
