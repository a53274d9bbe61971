// The size estimate of a run (run_size.h). Where the numbers come from:
//  - particles: the lattice of sph/geometry.h counted, not generated: a box holds
//    prod_k ceil(extent_k / dp - 1/2) centres, a polygon |area| / dp^2, a container its outer box
//    (layers x dp beyond each closed face) less its inner box. Particles of a block inside a wall
//    are not subtracted and inflow zones add none: a slight overestimate at t = 0.
//  - memory: measured (peak VmHWM of each process, coupler run --set run.max_steps=30, 2D,
//    h = 1.2-1.3 dp): fluid_solver 29 MB at 4,928 particles, 59 MB at 16,873, 173 MB at 60,297
//    (dam break: 2.64 kB per particle); soil_solver 26 MB at 2,708, 45 MB at 9,398 (soil column:
//    2.74 kB per particle); the coupler 16 MB alone, and 0.38 kB more per particle of a coupled
//    run (still bed). Hence 3 kB per particle in 2D plus 0.5 kB in the coupler when both phases
//    run, on top of 64 MB for the three processes. 3D: not measured; the neighbour lists that
//    dominate grow with the neighbour count (~58 in a 2.4 dp sphere against ~18 in a disc), so
//    9 kB per particle.
//  - output: the HDF5 snapshot fields (docs: README's table): water position, velocity (D
//    doubles each), density, pressure, mass, id (8 bytes each) and fixed (1 byte): 65 bytes per
//    particle in 2D (measured: 7,848,634 bytes for 2 x 60,297 particles); soil position,
//    velocity, displacement (D each), stress (9), density, porosity, plastic strain, saturation,
//    id, material, fixed: 8 (3 D + 15) bytes, 168 in 2D (measured: 170).
#include "coupler/run_size.h"

#include <sys/statvfs.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "scene/scene_sanity.h"

namespace porosph::coupler {
namespace {

constexpr double kBaseBytes = 64.0 * 1024 * 1024;
constexpr double kBytesPerParticle2D = 3.0 * 1024;
constexpr double kBytesPerParticle3D = 9.0 * 1024;
constexpr double kCouplerBytesPerParticle = 512.0;

/// Lattice centres min + (i + 1/2) dp below max (sph::lattice_count, in doubles).
double axis_count(double min, double max, double dp) {
  return std::max(0.0, std::ceil((max - min) / dp - 0.5 - 1e-9));
}

double box_count(const std::vector<double>& lo, const std::vector<double>& hi, double dp) {
  double n = 1.0;
  for (std::size_t k = 0; k < lo.size() && k < hi.size(); ++k) n *= axis_count(lo[k], hi[k], dp);
  return n;
}

std::string bytes_text(double bytes) {
  static const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) {
    bytes /= 1000.0;
    ++u;
  }
  std::ostringstream out;
  out.precision(bytes < 10 ? 2 : 3);
  out << bytes << " " << units[u];
  return out.str();
}

std::string count_text(double n) {
  std::ostringstream out;
  if (n < 1e7)
    out << static_cast<long long>(std::llround(n));
  else
    out.precision(2), out << std::scientific << n;
  return out.str();
}

/// "SCENE:LINE: key 'k': " for `key` of the scene file, "--set: key 'k': " when the scene file
/// holds another value (an override), "SCENE: key 'k': " when it holds none.
std::string key_prefix(const scene::Scene& scene, const std::string& key, double value) {
  const std::string file = scene.source_path.empty() ? "<scene>" : scene.source_path;
  try {
    const toml::table root = toml::parse_file(file);
    const toml::node* node = root.at_path(key).node();
    if (node && node->value<double>() != value) return "--set: key '" + key + "': ";
    if (node)
      return file + ":" + std::to_string(node->source().begin.line) + ": key '" + key + "': ";
  } catch (const std::exception&) {
  }
  return file + ": key '" + key + "': ";
}

}  // namespace

double estimated_shape_particles(const scene::Shape& shape, double dp, int dimension) {
  using Kind = scene::Shape::Kind;
  if (shape.kind == Kind::Polygon) {
    double twice_area = 0.0;
    const auto& v = shape.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto& a = v[i];
      const auto& b = v[(i + 1) % v.size()];
      if (a.size() >= 2 && b.size() >= 2) twice_area += a[0] * b[1] - b[0] * a[1];
    }
    return std::fabs(twice_area) / 2.0 / (dp * dp);
  }
  const double inner = box_count(shape.min, shape.max, dp);
  if (shape.kind == Kind::Box) return inner;
  std::vector<double> lo = shape.min, hi = shape.max;
  for (int k = 0; k < dimension && k < static_cast<int>(lo.size()); ++k) {
    const std::string axis(1, static_cast<char>('x' + k));
    const auto open = [&](const char* side) {
      return std::find(shape.open_faces.begin(), shape.open_faces.end(), axis + side) !=
             shape.open_faces.end();
    };
    if (!open("-")) lo[k] -= shape.layers * dp;
    if (!open("+")) hi[k] += shape.layers * dp;
  }
  return std::max(0.0, box_count(lo, hi, dp) - inner);
}

RunSizeEstimate estimate_run_size(const scene::Scene& scene) {
  RunSizeEstimate size;
  const int d = scene.run.dimension;
  const double dp = scene.run.dp;
  for (const std::string& phase : scene.phases()) {
    PhaseSize p;
    p.phase = phase;
    const bool water = phase == "water";
    for (const auto& block : water ? scene.water->blocks : scene.soil->blocks)
      p.free_particles += estimated_shape_particles(block, dp, d);
    for (const auto& wall : scene.walls_acting_on(phase))
      p.wall_particles += estimated_shape_particles(wall, dp, d);
    p.snapshot_bytes = water ? 8.0 * (2 * d + 4) + 1.0 : 8.0 * (3 * d + 15);
    size.particles += p.free_particles + p.wall_particles;
    size.phases.push_back(p);
  }
  const double per_particle =
      (d == 3 ? kBytesPerParticle3D : kBytesPerParticle2D) +
      (scene.has_water() && scene.has_soil() ? kCouplerBytesPerParticle : 0.0);
  size.memory_bytes = kBaseBytes + size.particles * per_particle;
  size.time_step = scene::expected_time_step(scene);
  size.steps = std::ceil(scene.run.end_time / size.time_step);
  if (scene.run.max_steps > 0) size.steps = std::min(size.steps, double(scene.run.max_steps));
  size.snapshots =
      std::min(std::ceil(scene.run.end_time / scene.run.output_interval), size.steps) + 1;
  for (const PhaseSize& p : size.phases)
    size.output_bytes += size.snapshots * (p.free_particles + p.wall_particles) * p.snapshot_bytes;
  return size;
}

MachineLimits machine_limits(const std::string& run_dir) {
  MachineLimits limits;
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0) limits.memory_bytes = double(pages) * double(page_size);
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path dir = fs::absolute(run_dir.empty() ? "." : run_dir, error).lexically_normal();
  while (!fs::is_directory(dir, error) && dir.has_parent_path() && dir != dir.parent_path())
    dir = dir.parent_path();
  limits.disk_path = dir.string();
  struct statvfs fs_info {};
  if (statvfs(limits.disk_path.c_str(), &fs_info) == 0)
    limits.disk_free_bytes = double(fs_info.f_bavail) * double(fs_info.f_frsize);
  return limits;
}

std::string describe_run_size(const RunSizeEstimate& size) {
  std::ostringstream out;
  out << "~" << count_text(size.particles) << " particles (";
  for (std::size_t i = 0; i < size.phases.size(); ++i) {
    const PhaseSize& p = size.phases[i];
    out << (i ? ", " : "") << p.phase << " " << count_text(p.free_particles) << " + "
        << count_text(p.wall_particles) << " wall";
  }
  out.precision(3);
  out << "), ~" << bytes_text(size.memory_bytes) << " of memory, dt ~" << size.time_step << " s, ~"
      << count_text(size.steps) << " steps, " << count_text(size.snapshots) << " snapshots, ~"
      << bytes_text(size.output_bytes) << " of output";
  return out.str();
}

std::string run_size_problem(const scene::Scene& scene, const RunSizeEstimate& size,
                             const MachineLimits& limits) {
  const std::string insist = "; --force-size runs it anyway";
  if (limits.memory_bytes > 0 && !(size.memory_bytes <= kMemoryShare * limits.memory_bytes))
    return key_prefix(scene, "run.dp", scene.run.dp) + "~" + count_text(size.particles) +
           " particles need ~" + bytes_text(size.memory_bytes) + " of memory; this machine has " +
           bytes_text(limits.memory_bytes) + " (a run may plan on " +
           std::to_string(int(kMemoryShare * 100)) + " %): choose a larger run.dp" + insist;
  if (!(size.snapshots <= kMaxSnapshots))
    return key_prefix(scene, "run.output_interval", scene.run.output_interval) +
           "the run would write " + count_text(size.snapshots) +
           " snapshots (end_time / output_interval, at most one per "
           "step of ~" +
           count_text(size.steps) + "), more than " + count_text(kMaxSnapshots) +
           ": choose a larger run.output_interval" + insist;
  if (limits.disk_free_bytes > 0 && !(size.output_bytes <= kDiskShare * limits.disk_free_bytes))
    return key_prefix(scene, "run.output_interval", scene.run.output_interval) + "~" +
           count_text(size.snapshots) + " snapshots of ~" + count_text(size.particles) +
           " particles need ~" + bytes_text(size.output_bytes) + " of disk; " + limits.disk_path +
           " has " + bytes_text(limits.disk_free_bytes) +
           " free: choose a larger run.output_interval (or run.dp, or another --out)" + insist;
  return "";
}

}  // namespace porosph::coupler
