// coupler: the PoroSPH command line (docs/design.md section 6).
// clang-format off
//   coupler run SCENE.toml [--out DIR] [--overwrite] [--set key=value ...] [--water-solver EXE] [--soil-solver EXE]
//   coupler run --attach --endpoint tcp://HOST:PORT SCENE.toml
//   coupler run --resume DIR          continue DIR's run from its latest checkpoint
//   coupler status DIR                running / completed / failed / died (docs/reliability.md)
//   coupler check SCENE.toml [--set ...] [--out DIR] [--force-size]   validate, estimate the size
//   coupler schema --markdown                the scene key reference (docs/scene.md)
//   coupler schema --terms                   the physics terms and their switches (docs/terms.md)
// clang-format on
// Exit codes of run: 0 completed, 1 the run failed, 2 bad input (a busy or unwritable run
// directory, or one holding an earlier run without --overwrite, included). Of status: 0 completed,
// 1 failed, 2 no run there, 3 running, 4 died.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "coupler/phase_slots.h"
#include "coupler/run_session.h"
#include "coupler/run_status.h"
#include "coupler/scene_check.h"
#include "scene/scene_loader.h"
#include "scene/term_registry.h"

int main(int argc, char** argv) {
  CLI::App app{"PoroSPH coupler: runs water and soil SPH solvers as coupled processes"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "0.1.0");

  porosph::coupler::RunOptions run_options;
  bool no_progress = false;
  auto* run = app.add_subcommand("run", "run a scene and write the run directory");
  run->add_option("scene", run_options.scene_path, "scene file (TOML)");
  run->add_option("--resume", run_options.resume_dir,
                  "continue the run in this directory from its latest checkpoint "
                  "(docs/checkpoints.md)");
  run->add_option("--out", run_options.out_dir, "run directory (default runs/<scene name>)");
  run->add_flag("--overwrite", run_options.overwrite,
                "replace the outputs of an earlier run in the run directory (without it such a "
                "directory is refused)");
  run->add_option("--set", run_options.overrides, "override a scene key: key=value (repeatable)")
      ->take_all()
      ->allow_extra_args(false);
  for (const porosph::coupler::PhaseSlot& slot : porosph::coupler::kPhaseSlots) {
    const std::string phase = slot.phase;
    run->add_option("--" + phase + "-solver", run_options.solver_overrides[phase],
                    phase + " solver executable (default: " + slot.builtin_solver + ")");
  }
  // Before the phases had one name (issue 24) the water solver's option was --fluid-solver.
  std::string deprecated_fluid_solver;
  run->add_option("--fluid-solver", deprecated_fluid_solver)->group("");
  run->add_flag("--attach", run_options.attach,
                "do not start solvers: wait for solvers started by hand at --endpoint (it "
                "prints the run token they need in POROSPH_RUN_TOKEN)");
  run->add_option("--endpoint", run_options.endpoint,
                  "ZeroMQ endpoint to bind: ipc://PATH or tcp://HOST:PORT, HOST an address, "
                  "[IPv6], a host name or * (default: a fresh ipc:// socket in a private "
                  "directory; docs/protocol.md)");
  run->add_flag("--no-progress", no_progress, "do not print the progress line");
  run->add_flag("--force-size", run_options.force_size,
                "run even when the size estimate does not fit this machine (memory, disk, "
                "snapshots; docs/reliability.md)");

  porosph::coupler::CheckOptions check_options;
  auto* check = app.add_subcommand(
      "check", "validate a scene, print its size estimate and the resolved scene");
  check->add_option("scene", check_options.scene_path, "scene file (TOML)")->required();
  check->add_option("--set", check_options.overrides,
                    "override a scene key: key=value (repeatable)");
  check->add_option("--out", check_options.out_dir,
                    "run directory whose disk the outputs must fit (default runs/<scene name>)");
  check->add_flag("--force-size", check_options.force_size,
                  "pass a scene whose size estimate does not fit this machine");

  std::string status_dir;
  auto* status = app.add_subcommand(
      "status", "say whether the run in a directory is running, completed, failed or died");
  status->add_option("dir", status_dir, "run directory")->required();

  bool markdown = false;
  auto* schema = app.add_subcommand("schema", "print the reference of every scene key");
  schema->add_flag("--markdown", markdown, "as Markdown (the content of docs/scene.md)");
  bool terms = false;
  schema->add_flag("--terms", terms,
                   "the physics terms, what switches them and their keys (docs/terms.md)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : porosph::coupler::kBadInput;
  }

  if (*run) {
    if (run_options.resume_dir.empty() && run_options.scene_path.empty()) {
      std::fprintf(stderr, "coupler: run needs a scene file (or --resume DIR)\n");
      return porosph::coupler::kBadInput;
    }
    if (!run_options.resume_dir.empty() &&
        (!run_options.scene_path.empty() || !run_options.out_dir.empty() ||
         !run_options.overrides.empty() || run_options.overwrite)) {
      std::fprintf(stderr,
                   "coupler: --resume DIR takes the scene and the run directory from DIR's "
                   "checkpoint: give no scene, --out, --set or --overwrite with it\n");
      return porosph::coupler::kBadInput;
    }
    if (run_options.attach && run_options.endpoint.empty()) {
      std::fprintf(stderr, "coupler: --attach needs --endpoint tcp://HOST:PORT\n");
      return porosph::coupler::kBadInput;
    }
    if (!deprecated_fluid_solver.empty()) {
      if (!run_options.solver_overrides["water"].empty()) {
        std::fprintf(stderr, "coupler: give --water-solver or --fluid-solver, not both\n");
        return porosph::coupler::kBadInput;
      }
      std::fprintf(stderr,
                   "coupler: --fluid-solver is deprecated, it is now --water-solver (the phase "
                   "is called water everywhere)\n");
      run_options.solver_overrides["water"] = deprecated_fluid_solver;
    }
    run_options.progress = !no_progress;
    return porosph::coupler::run_scene(run_options);
  }
  if (*check) return porosph::coupler::check_scene(check_options, std::cout, std::cerr);
  if (*status) {
    const auto report = porosph::coupler::run_status(status_dir);
    std::cout << report.text << "\n";
    return report.code;
  }
  if (*schema) {
    std::cout << (terms ? porosph::scene::term_reference_markdown()
                        : porosph::scene::scene_reference_markdown());
    return 0;
  }
  return porosph::coupler::kBadInput;
}
