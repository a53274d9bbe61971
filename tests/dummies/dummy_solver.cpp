// dummy_solver: plays one phase of the coupling with a few fake particles moving at constant
// velocity (plus whatever interaction acceleration the coupler returns), so the coupler can be
// tested without any physics. Links only the coupling client.
//
//   dummy_solver --phase water|soil [--endpoint E] [--connect-timeout S] [--particles N]
//                [--overlap N] [--dt-limit S] [--protocol-version V] [--fail-at-step N]
//                [--nan-at-step N] [--crash-at-step N] [--hang-at-step N]
//
// --overlap N sends the first N particles as overlap particles each step (ids 0..N-1, positions,
// velocities, density, mass; soil also porosity 0.4 and material 0). The dt limit defaults to
// 10 dt0 (never the active one). Interaction accelerations from the coupler are applied.
//
// Fault injection ("at step N" = instead of sending the state of step N):
//   --fail-at-step N   report_error("injected failure at step N") and exit 3
//   --nan-at-step N    particle 7 gets a NaN velocity; the finiteness check reports it with
//                      particle id 7 ("non-finite velocity of particle 7 at step N, t=...") and
//                      exits 3
//   --crash-at-step N  std::abort() without a message (SIGABRT, no core file)
//   --hang-at-step N   sleep forever without a message
// Exit codes: 0 after Goodbye, 1 coupling error (timeout, Shutdown...), 2 bad arguments, 3 failure.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "proto/coupling_client.h"

namespace {

using porosph::coupling::CouplingClient;
using porosph::coupling::CouplingError;

constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();

struct Options {
  std::string phase;
  std::string endpoint;
  double connect_timeout = 60;
  std::size_t particles = 10;
  std::size_t overlap = 0;
  double dt_limit = -1;  // < 0: 10 dt0, i.e. never the active limit
  std::uint32_t protocol_version = porosph::coupling::kProtocolVersion;
  std::uint64_t fail_at = kNever, nan_at = kNever, crash_at = kNever, hang_at = kNever;
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "dummy_solver: " << problem
            << "\nusage: dummy_solver --phase water|soil [--endpoint E] [--connect-timeout S] "
               "[--particles N] "
               "[--overlap N] [--dt-limit S] [--protocol-version V] [--fail-at-step N] "
               "[--nan-at-step N] [--crash-at-step N] [--hang-at-step N]\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) usage("missing value after " + flag);
    const std::string value = argv[++i];
    try {
      if (flag == "--phase")
        o.phase = value;
      else if (flag == "--endpoint")
        o.endpoint = value;
      else if (flag == "--connect-timeout")
        o.connect_timeout = std::stod(value);
      else if (flag == "--particles")
        o.particles = std::stoul(value);
      else if (flag == "--overlap")
        o.overlap = std::stoul(value);
      else if (flag == "--dt-limit")
        o.dt_limit = std::stod(value);
      else if (flag == "--protocol-version")
        o.protocol_version = std::stoul(value);
      else if (flag == "--fail-at-step")
        o.fail_at = std::stoull(value);
      else if (flag == "--nan-at-step")
        o.nan_at = std::stoull(value);
      else if (flag == "--crash-at-step")
        o.crash_at = std::stoull(value);
      else if (flag == "--hang-at-step")
        o.hang_at = std::stoull(value);
      else
        usage("unknown option " + flag);
    } catch (const std::logic_error&) {
      usage("bad value '" + value + "' for " + flag);
    }
  }
  if (o.phase != "water" && o.phase != "soil") usage("--phase must be water or soil");
  return o;
}

/// Fake particles: a row along x, all moving with the same velocity (water right, soil down).
struct Particles {
  int dim = 2;
  std::vector<double> position, velocity, density, mass;

  Particles(std::size_t n, int d, double dp, bool water) : dim(d) {
    position.assign(n * d, 0.0);
    velocity.assign(n * d, 0.0);
    density.assign(n, water ? 1000.0 : 2000.0);
    mass.assign(n, density[0] * std::pow(dp, d));
    for (std::size_t i = 0; i < n; ++i) {
      position[i * d] = static_cast<double>(i) * dp;
      if (d > 1) position[i * d + 1] = water ? 2.0 * dp : 0.0;
      velocity[i * d + (water ? 0 : d - 1)] = water ? 0.1 : -0.05;
    }
  }
  std::size_t count() const { return density.size(); }
};

/// Index of the first particle with a non-finite velocity component, or -1.
long first_non_finite(const Particles& p) {
  for (std::size_t k = 0; k < p.velocity.size(); ++k) {
    if (!std::isfinite(p.velocity[k])) return static_cast<long>(k / p.dim);
  }
  return -1;
}

void fill_state(const Particles& p, const Options& o, double dt0, std::uint64_t step, double t,
                porosph::coupling::StepState& s) {
  const int d = p.dim;
  const std::size_t n = p.count(), m = std::min(o.overlap, n);
  s.step = step;
  s.time = t;
  s.dt_limit = s.dt_cfl = s.dt_viscous = s.dt_force = o.dt_limit >= 0 ? o.dt_limit : 10 * dt0;
  s.overlap_id.resize(m);
  for (std::size_t i = 0; i < m; ++i) s.overlap_id[i] = static_cast<std::int64_t>(i);
  s.overlap_position.assign(p.position.begin(), p.position.begin() + m * d);
  s.overlap_velocity.assign(p.velocity.begin(), p.velocity.begin() + m * d);
  s.overlap_density.assign(p.density.begin(), p.density.begin() + m);
  s.overlap_mass.assign(p.mass.begin(), p.mass.begin() + m);
  s.overlap_porosity.assign(o.phase == "soil" ? m : 0, 0.4);
  s.overlap_material.assign(o.phase == "soil" ? m : 0, 0);
  auto& g = s.diagnostics;
  g.particle_count = g.free_count = n;
  g.mass = g.kinetic_energy = g.max_speed = 0;
  g.momentum.assign(d, 0.0);
  s.region_min.assign(d, std::numeric_limits<double>::max());
  s.region_max.assign(d, std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < n; ++i) {
    double speed2 = 0;
    for (int k = 0; k < d; ++k) {
      const double v = p.velocity[i * d + k], x = p.position[i * d + k];
      g.momentum[k] += p.mass[i] * v;
      speed2 += v * v;
      s.region_min[k] = std::min(s.region_min[k], x);
      s.region_max[k] = std::max(s.region_max[k], x);
    }
    g.mass += p.mass[i];
    g.kinetic_energy += 0.5 * p.mass[i] * speed2;
    g.max_speed = std::max(g.max_speed, std::sqrt(speed2));
  }
  g.observables["step"] = static_cast<double>(step);
}

int run(const Options& o) {
  const auto start = std::chrono::steady_clock::now();
  porosph::coupling::SolverIdentity identity{o.phase, "porosph-dummy", "1.0"};
  identity.protocol_version = o.protocol_version;
  CouplingClient client(porosph::coupling::resolve_endpoint(o.endpoint), identity,
                        o.connect_timeout);
  const auto& setup = client.setup();
  const int d = std::max(1, setup.dimension);
  Particles particles(std::max(o.particles, o.overlap), d, setup.dp > 0 ? setup.dp : 0.01,
                      o.phase == "water");
  porosph::coupling::StepState state;
  std::uint64_t step = 0;
  double t = 0;
  for (;;) {
    if (step == o.fail_at) {
      client.report_error("injected failure at step " + std::to_string(step), step, t);
      return 3;
    }
    if (step == o.nan_at) particles.velocity[7 * d] = std::numeric_limits<double>::quiet_NaN();
    if (step == o.crash_at) {
      const rlimit no_core{0, 0};
      setrlimit(RLIMIT_CORE, &no_core);
      std::abort();
    }
    if (step == o.hang_at) {
      for (;;) pause();
    }
    if (const long bad = first_non_finite(particles); bad >= 0) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "non-finite velocity of particle %ld at step %llu, t=%g", bad,
                    static_cast<unsigned long long>(step), t);
      client.report_error(message, step, t, bad);
      std::cerr << "dummy_solver (" << o.phase << "): " << message << "\n";
      return 3;
    }
    fill_state(particles, o, setup.dt0, step, t, state);
    const auto& command = client.exchange(state);
    if (command.stop) break;
    const std::size_t m = state.overlap_id.size();
    const auto& a = command.interaction_acceleration;
    if (command.step != step || (!a.empty() && a.size() != m * d)) {
      const std::string message = "bad command: step " + std::to_string(command.step) +
                                  " (expected " + std::to_string(step) + "), " +
                                  std::to_string(a.size()) + " acceleration values for " +
                                  std::to_string(m) + " overlap particles";
      client.report_error(message, step, t);
      std::cerr << "dummy_solver (" << o.phase << "): " << message << "\n";
      return 3;
    }
    for (std::size_t k = 0; k < a.size(); ++k) particles.velocity[k] += a[k] * command.dt;
    for (std::size_t k = 0; k < particles.position.size(); ++k) {
      particles.position[k] += particles.velocity[k] * command.dt;
    }
    t += command.dt;
    ++step;
  }
  porosph::coupling::Timing timing;
  timing.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  client.finalize(timing);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    return run(options);
  } catch (const CouplingError& e) {
    std::cerr << "dummy_solver (" << options.phase << "): " << e.what() << "\n";
    return 1;
  }
}
