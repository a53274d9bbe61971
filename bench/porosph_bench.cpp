// porosph_bench: throughput of the solvers through the real coupler (a benchmark, never a test).
// Runs a case at about 30,000 particles for a fixed number of steps (dt pinned by dt0 below every
// stability limit) and prints particle-steps per second, the share of the solver's wall time spent
// in the coupler round trip, and the peak memory of the largest process. Cases: dam_break (water
// solver), granular_collapse (soil solver) and fluidized_bed (coupled: also the coupling overhead
// and the CPU budget).
//   porosph_bench [--case dam_break] [--particles 30000] [--steps 400] [--threads N] [--keep DIR]
//                 [--repeat N]
// --repeat N runs the case N times and ends with the min / median / max of the headline figures
// (the machine's speed drifts between runs: compare distributions, never one run).
#include <sys/resource.h>
#include <sys/wait.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#ifndef POROSPH_SOURCE_DIR
#define POROSPH_SOURCE_DIR "."
#endif

namespace {

std::string executable_dir() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path().string();
}

/// The headline figures of one run: particle-steps/s and (coupled) the coupling overhead share.
struct Headline {
  double rate = 0.0;
  double overhead = 0.0;
  double critical_physics = 0.0;  ///< coupled: the slower solver's physics wall time [s]
};

Headline headline(const nlohmann::json& run, bool coupled, const std::string& phase) {
  const double steps = run.at("steps").get<double>();
  Headline h;
  if (coupled) {
    double particles = 0.0;
    for (const char* p : {"water", "soil"}) {
      const auto& record = run.at("phases").at(p);
      particles += record.at("particles").at("total").get<double>();
      h.critical_physics =
          std::max(h.critical_physics, record.at("wall_seconds").at("physics").get<double>());
    }
    const double wall = run.at("wall_seconds").at("total").get<double>();
    h.rate = particles * steps / wall;
    h.overhead = 100.0 * (1.0 - h.critical_physics / wall);
  } else {
    const auto& record = run.at("phases").at(phase);
    h.rate = record.at("particles").at("free").get<double>() * steps /
             record.at("wall_seconds").at("total").get<double>();
  }
  return h;
}

/// The coupled figures: both phases' particles, the whole run's particle-steps per second, and the
/// coupling overhead: the share of the wall time the slower solver spent outside its own physics
/// (serialising, ZeroMQ, the coupler's interaction, waiting) - the solvers run in parallel, so the
/// slower one's physics is the step's critical path.
///
/// The CPU budget beside it: the CPU time of every process of the run (the coupler, both solvers,
/// ZeroMQ's I/O threads) against cores x the slower solver's physics. Where the whole run needs
/// more CPU time than the cores give while that solver computes, the wall time exceeds its physics
/// by at least the excess, however well the work overlaps: a lower bound of the overhead.
void print_coupled(const nlohmann::json& run, const std::string& case_name, double wall,
                   double peak_mib, double cpu_seconds) {
  const double steps = run.at("steps").get<double>();
  const Headline h = headline(run, true, "");
  std::printf("%-44s %12s\n", "figure", "value");
  std::printf("%-44s %12s\n", "case", case_name.c_str());
  for (const char* phase : {"water", "soil"}) {
    const auto& record = run.at("phases").at(phase);
    const double total = record.at("particles").at("total").get<double>();
    const double physics = record.at("wall_seconds").at("physics").get<double>();
    std::printf("%-44s %12.0f\n", (std::string(phase) + " particles (incl. fixed)").c_str(), total);
    std::printf("%-44s %12.1f\n", (std::string(phase) + " neighbours per particle").c_str(),
                record.at("final").at("neighbours_per_particle").get<double>());
    std::printf("%-44s %12.2f\n", (std::string(phase) + " physics wall time [s]").c_str(), physics);
  }
  const double run_wall = run.at("wall_seconds").at("total").get<double>();
  std::printf("%-44s %12.0f\n", "coupled steps", steps);
  std::printf("%-44s %12.0f\n", "soil-water pairs (last step)",
              run.at("interaction").at("pairs").at("last").get<double>());
  std::printf("%-44s %12.2f\n", "coupler interaction wall time [s]",
              run.at("interaction").at("seconds").get<double>());
  std::printf("%-44s %12.0f\n", "message bytes per step (states + commands)",
              run.at("transport").at("bytes_per_step").get<double>());
  std::printf("%-44s %12.2f\n", "run wall time (run.json) [s]", run_wall);
  std::printf("%-44s %12.3e\n", "particle-steps/s (both phases, whole run)", h.rate);
  std::printf("%-44s %11.1f%%\n", "coupling overhead share of step time", h.overhead);
  const double cores = std::max(1u, std::thread::hardware_concurrency());
  std::printf("%-44s %12.2f\n", "CPU time of all processes [s]", cpu_seconds);
  std::printf("%-44s %11.1f%%\n", "overhead bound from the CPU budget",
              100.0 * std::max(0.0, 1.0 - cores * h.critical_physics / cpu_seconds));
  std::printf("%-44s %12.2f\n", "whole run wall time incl. start [s]", wall);
  std::printf("%-44s %12.1f\n", "peak memory of the largest process [MiB]", peak_mib);
}

void print_distribution(const char* name, std::vector<double> values, const char* unit) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  std::printf("%-44s %.4g / %.4g / %.4g%s (min / median / max of %zu runs)\n", name, values.front(),
              median, values.back(), unit, n);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"PoroSPH throughput benchmark (dam break through the coupler)"};
  std::string case_name = "dam_break";
  int particles = 30000;
  int steps = 400;
  int threads = 0;
  std::string keep;
  int repeat = 1;
  app.add_option("--case", case_name, "dam_break (water) or granular_collapse (soil)")
      ->check(CLI::IsMember({"dam_break", "granular_collapse", "fluidized_bed"}));
  app.add_option("--particles", particles, "approximate number of free particles");
  app.add_option("--steps", steps, "number of coupled steps");
  app.add_option("--threads", threads, "OpenMP threads (default: all cores)");
  app.add_option("--keep", keep, "run directory to keep (default: a temporary one)");
  app.add_option("--repeat", repeat, "runs of the case (the last one's table is printed in full)")
      ->check(CLI::Range(1, 1000));
  CLI11_PARSE(app, argc, argv);

  const bool soil = case_name == "granular_collapse";
  const bool coupled = case_name == "fluidized_bed";
  const std::string phase = soil ? "soil" : "water";
  double dp = 0.0, dt = 0.0;
  if (coupled) {
    // The paper's bed at its own resolution (7,500 particles), dt from its limits, past the
    // damping stage so that the interaction acts.
  } else if (soil) {
    // Bui et al. column 0.2 m x 0.1 m: n = 0.5 (0.2 / dp)^2. CFL with the P-wave speed 20.7 m/s
    // and |v| up to ~1.5 m/s: 0.2 * 1.2 dp / 22.
    dp = 0.2 / std::round(std::sqrt(2.0 * particles));
    dt = 0.2 * 1.2 * dp / 22.0;
  } else {
    // Martin & Moyce column a x 2a: n = 2 (a/dp)^2 water particles. CFL limit with c = 20 m/s and
    // |v| up to ~3 m/s early in the collapse: 0.2*1.3dp/23.
    const double a = 0.05715;
    dp = a / std::round(std::sqrt(particles / 2.0));
    dt = 0.2 * 1.3 * dp / 23.0;
  }
  const std::string out =
      keep.empty() ? (std::filesystem::temp_directory_path() / "porosph-bench").string() : keep;
  char settings[512];
  if (coupled) {
    std::snprintf(settings, sizeof settings,
                  " --set run.max_steps=%d --set run.output_interval=100 --no-progress"
                  " --set soil.damping_duration=1e-4 --set water.inflow.0.start_time=1e-4",
                  steps);
  } else {
    std::snprintf(settings, sizeof settings,
                  " --set run.dp=%.9g --set run.dt0=%.9g --set run.end_time=%.9g"
                  " --set run.output_interval=1.0 --no-progress",
                  dp, dt, dt * steps * (1 + 1e-9));
  }
  const std::string command =
      (threads > 0 ? "OMP_NUM_THREADS=" + std::to_string(threads) + " " : "") + executable_dir() +
      "/coupler run " + POROSPH_SOURCE_DIR + "/cases/" + case_name +
      "/scene.toml --overwrite --out " + out + settings;
  std::printf("# %s\n", command.c_str());
  std::vector<double> rates, overheads;
  nlohmann::json run;
  double wall = 0.0;
  rusage before_last{};  // the children's CPU time before the last run
  for (int k = 1; k <= repeat; ++k) {
    getrusage(RUSAGE_CHILDREN, &before_last);
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status != 0) {
      std::fprintf(stderr, "porosph_bench: the run failed (status %d)\n", status);
      return 1;
    }
    std::ifstream file(out + "/run.json");
    run = nlohmann::json::parse(file);
    const Headline h = headline(run, coupled, phase);
    rates.push_back(h.rate);
    overheads.push_back(h.overhead);
    if (repeat > 1) {
      std::printf("run %d of %d: %.4g particle-steps/s", k, repeat, h.rate);
      if (coupled) std::printf(", coupling overhead %.1f %%", h.overhead);
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  if (repeat > 1) {
    print_distribution("particle-steps/s", rates, "");
    if (coupled) print_distribution("coupling overhead share of step time", overheads, " %");
  }
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  if (coupled) {
    const auto seconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
    const double cpu = seconds(usage.ru_utime) + seconds(usage.ru_stime) -
                       seconds(before_last.ru_utime) - seconds(before_last.ru_stime);
    print_coupled(run, case_name, wall, usage.ru_maxrss / 1024.0, cpu);
    if (keep.empty()) std::filesystem::remove_all(out);
    return 0;
  }
  const auto& record = run.at("phases").at(phase);
  const double total = record.at("particles").at("total").get<double>();
  const double free_particles = record.at("particles").at("free").get<double>();
  const double run_steps = run.at("steps").get<double>();
  const auto& seconds = record.at("wall_seconds");
  const double solver_wall = seconds.at("total").get<double>();
  const double communication = seconds.at("communication").get<double>();

  std::printf("%-44s %12s\n", "figure", "value");
  std::printf("%-44s %12s\n", "case", case_name.c_str());
  std::printf("%-44s %12.0f\n", (phase + " particles (free)").c_str(), free_particles);
  std::printf("%-44s %12.0f\n", "all particles (incl. walls)", total);
  std::printf("%-44s %12.1f\n", "neighbours per particle",
              record.at("final").at("neighbours_per_particle").get<double>());
  std::printf("%-44s %12.0f\n", "coupled steps", run_steps);
  std::printf("%-44s %12.2f\n", (phase + " solver wall time [s]").c_str(), solver_wall);
  std::printf("%-44s %12.3e\n", "particle-steps/s (free particles)",
              headline(run, false, phase).rate);
  std::printf("%-44s %12.3e\n", "particle-steps/s (all particles)",
              total * run_steps / solver_wall);
  std::printf("%-44s %11.1f%%\n", "coupler round trip share of solver time",
              100.0 * communication / solver_wall);
  std::printf("%-44s %12.2f\n", "whole run wall time [s]", wall);
  std::printf("%-44s %12.1f\n", "peak memory of the largest process [MiB]",
              usage.ru_maxrss / 1024.0);
  if (keep.empty()) std::filesystem::remove_all(out);
  return 0;
}
