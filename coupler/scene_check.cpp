#include "coupler/scene_check.h"

#include "coupler/block_lattice.h"
#include "coupler/phase_slots.h"
#include "coupler/run_size.h"
#include "coupler/thin_walls.h"
#include "scene/scene_loader.h"
#include "scene/term_registry.h"

namespace porosph::coupler {
namespace {

std::string run_dir_of(const scene::Scene& scene, const std::string& out_dir) {
  return out_dir.empty() ? "runs/" + scene.name : out_dir;
}

}  // namespace

std::string size_gate(const scene::Scene& scene, const std::string& out_dir, bool force) {
  if (force) return "";
  return run_size_problem(scene, estimate_run_size(scene),
                          machine_limits(run_dir_of(scene, out_dir)));
}

std::string run_gate(const scene::Scene& scene, const std::string& out_dir, bool force) {
  if (const std::string too_big = size_gate(scene, out_dir, force); !too_big.empty())
    return "the run does not fit this machine: " + too_big;
  if (const std::string blocks = block_lattice_problem(scene); !blocks.empty())
    return "bad scene: " + blocks;
  return "";
}

int check_scene(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  scene::Scene scene;
  try {
    scene = scene::load_scene_file(options.scene_path, options.overrides);
  } catch (const scene::SceneError& e) {
    err << "coupler: bad scene: " << e.what() << "\n";
    return 2;
  }
  const RunSizeEstimate size = estimate_run_size(scene);
  const std::string problem =
      run_size_problem(scene, size, machine_limits(run_dir_of(scene, options.out_dir)));
  if (!problem.empty() && !options.force_size) {
    err << "coupler: the run does not fit this machine: " << problem << "\n";
    return 2;
  }
  if (const std::string overlap = block_lattice_problem(scene); !overlap.empty()) {
    err << "coupler: bad scene: " << overlap << "\n";
    return 2;
  }
  if (!problem.empty()) err << "coupler: warning (--force-size): " << problem << "\n";
  for (const std::string& warning : thin_wall_warnings(scene))
    err << "coupler: warning: " << warning << "\n";
  out << "# " << options.scene_path << ": valid scene '" << scene.name << "' (phases:";
  for (const auto& phase : scene.phases()) out << " " << phase;
  out << ")\n# size: " << describe_run_size(size) << "\n";
  for (const std::string phase : {"water", "soil", "interaction"}) {
    const std::vector<std::string> terms = scene::active_terms(scene, phase);
    if (terms.empty()) continue;
    const std::string own_solver =
        phase == "interaction" ? std::string() : scene_solver_command(scene, phase);
    if (!own_solver.empty()) {  // a replacement solver declares its terms when it starts
      out << "# " << phase << " terms: declared by " << own_solver << " at its start\n";
      continue;
    }
    out << "# " << phase << " terms:";
    for (const auto& term : terms) out << " " << term;
    out << "\n";
  }
  out << scene.resolved_toml << "\n";
  return 0;
}

}  // namespace porosph::coupler
