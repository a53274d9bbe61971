#include "coupler/block_lattice.h"

#include <sstream>
#include <vector>

#include "coupler/run_size.h"
#include "sph/geometry.h"

namespace porosph::coupler {
namespace {

constexpr double kMaxCheckedPoints = 2e7;

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

template <int D>
std::string lattice_problem_in(const scene::Scene& s, const std::vector<scene::Shape>& blocks,
                               const std::string& table) {
  const double dp = s.run.dp;
  for (std::size_t j = 0; j < blocks.size(); ++j) {
    const std::vector<sph::Vec<D>> points = sph::fill_shape<D>(blocks[j], dp);
    if (points.empty()) {
      return s.source_path + ":" + std::to_string(blocks[j].source_line) + ": key '" + table + "[" +
             std::to_string(j) + "]': holds no particle at run.dp = " + number(dp) +
             " m (thinner than dp along some axis): enlarge the block or lower run.dp";
    }
    for (std::size_t i = 0; i < j; ++i) {
      std::size_t shared = 0;
      for (const auto& x : points) shared += sph::inside_shape<D>(blocks[i], x, dp) ? 1 : 0;
      if (shared == 0) continue;
      const auto name = [&](std::size_t k) {
        return table + "[" + std::to_string(k) + "]" +
               (blocks[k].label.empty() ? "" : " '" + blocks[k].label + "'");
      };
      return s.source_path + ":" + std::to_string(blocks[j].source_line) + ": key '" + table + "[" +
             std::to_string(j) + "]': overlaps " + name(i) + " (line " +
             std::to_string(blocks[i].source_line) + ") at " + std::to_string(shared) +
             " lattice points of run.dp; blocks of one phase may touch but not overlap (split "
             "them so that each point lies in one)";
    }
  }
  return "";
}

template <int D>
std::string problem_of(const scene::Scene& s) {
  // The check fills every block's lattice; beyond this many points (a run the size gate refuses
  // unless forced) it is skipped rather than exhausting the memory.
  double points = 0.0;
  if (s.water)
    for (const auto& b : s.water->blocks) points += estimated_shape_particles(b, s.run.dp, D);
  if (s.soil)
    for (const auto& b : s.soil->blocks) points += estimated_shape_particles(b, s.run.dp, D);
  if (!(points <= kMaxCheckedPoints)) return "";
  if (s.water) {
    const std::string p = lattice_problem_in<D>(s, s.water->blocks, "water.blocks");
    if (!p.empty()) return p;
  }
  if (s.soil) return lattice_problem_in<D>(s, s.soil->blocks, "soil.blocks");
  return "";
}

}  // namespace

std::string block_lattice_problem(const scene::Scene& scene) {
  return scene.run.dimension == 3 ? problem_of<3>(scene) : problem_of<2>(scene);
}

}  // namespace porosph::coupler
