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

inline CaseRun run_case(const std::string& name, const std::vector<std::string>& overrides,
                        double timeout_seconds = 300) {
  CaseRun run;
  const std::string dir = fresh_dir("case-" + name);
  run.out = dir + "/out";
  std::vector<std::string> argv = {bin("coupler"), "run",   source("cases/" + name + "/scene.toml"),
                                   "--out",        run.out, "--no-progress"};
  for (const auto& o : overrides) argv.insert(argv.end(), {"--set", o});
  run.result = run_process(argv, dir + "/log.txt", timeout_seconds);
  if (std::filesystem::exists(run.out + "/run.json")) run.record = read_json(run.out + "/run.json");
  return run;
}

}  // namespace porosph::testing
