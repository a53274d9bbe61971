// Runs a case of cases/ through the real coupler with --set overrides, for the case tests.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/process_support.h"

namespace porosph::testing {

struct CaseRun {
  CommandResult result;
  nlohmann::json record;  ///< run.json (empty if the run wrote none)
  std::string out;        ///< the run directory
};

/// Runs cases/<name>/<scene_file> in a fresh directory named after `name` and the file.
inline CaseRun run_case_scene(const std::string& name, const std::string& scene_file,
                              const std::vector<std::string>& overrides,
                              double timeout_seconds = 300) {
  CaseRun run;
  const std::string dir = fresh_dir("case-" + name + "-" + scene_file);
  run.out = dir + "/out";
  std::vector<std::string> argv = {
      bin("coupler"), "run",   source("cases/" + name + "/" + scene_file),
      "--out",        run.out, "--no-progress"};
  for (const auto& o : overrides) argv.insert(argv.end(), {"--set", o});
  run.result = run_process(argv, dir + "/log.txt", timeout_seconds);
  if (std::filesystem::exists(run.out + "/run.json")) run.record = read_json(run.out + "/run.json");
  return run;
}

/// Writes `scene_toml` to a fresh directory named after `name` and runs it like run_case_scene.
inline CaseRun run_scene_text(const std::string& name, const std::string& scene_toml,
                              const std::vector<std::string>& overrides,
                              double timeout_seconds = 300) {
  CaseRun run;
  const std::string dir = fresh_dir("scene-" + name);
  run.out = dir + "/out";
  std::vector<std::string> argv = {
      bin("coupler"), "run",   write_text(dir + "/" + name + ".toml", scene_toml),
      "--out",        run.out, "--no-progress"};
  for (const auto& o : overrides) argv.insert(argv.end(), {"--set", o});
  run.result = run_process(argv, dir + "/log.txt", timeout_seconds);
  if (std::filesystem::exists(run.out + "/run.json")) run.record = read_json(run.out + "/run.json");
  return run;
}

/// Runs cases/<name>/scene.toml.
inline CaseRun run_case(const std::string& name, const std::vector<std::string>& overrides,
                        double timeout_seconds = 300) {
  return run_case_scene(name, "scene.toml", overrides, timeout_seconds);
}

}  // namespace porosph::testing
