// porosph_validate: compares a finished run with its case's reference and prints the error.
//   porosph_validate dam_break RUN_DIR [--reference cases/dam_break/reference.csv]
//   porosph_validate hydrostatic_tank RUN_DIR
// Exit code 0 when the target is met, 1 when not, 2 on unreadable input.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "tools/validation/case_checks.h"

#ifndef POROSPH_SOURCE_DIR
#define POROSPH_SOURCE_DIR "."
#endif

int main(int argc, char** argv) {
  CLI::App app{"Compare a finished PoroSPH run with its reference"};
  app.require_subcommand(1);
  std::string run_dir;
  std::string reference = std::string(POROSPH_SOURCE_DIR) + "/cases/dam_break/reference.csv";
  auto* dam = app.add_subcommand("dam_break", "Martin & Moyce (1952) surge front");
  dam->add_option("run_dir", run_dir)->required();
  dam->add_option("--reference", reference, "reference table (T,Z)");
  auto* tank = app.add_subcommand("hydrostatic_tank", "still water: pressure and speed");
  tank->add_option("run_dir", run_dir)->required();
  bool print_rows = false;
  tank->add_flag("--rows", print_rows, "print the error of every lattice row");
  CLI11_PARSE(app, argc, argv);
  try {
    if (*dam) {
      const auto c = porosph::validation::compare_dam_break(run_dir, reference);
      std::printf("dam_break vs Martin & Moyce (1952), a = %.5f m\n%8s %8s %8s %8s\n", c.a, "T",
                  "Z_ref", "Z_sim", "dZ");
      for (std::size_t i = 0; i < c.T.size(); ++i) {
        std::printf("%8.2f %8.2f %8.3f %+8.3f\n", c.T[i], c.Z_reference[i], c.Z_simulated[i],
                    c.Z_simulated[i] - c.Z_reference[i]);
      }
      std::printf("mean |dZ| = %.3f  max |dZ| = %.3f  (target: mean <= 0.10)\n", c.mean_abs_error,
                  c.max_abs_error);
      std::printf("diagnostic: a release delay of dT = %.2f would leave mean |dZ| = %.3f\n",
                  c.best_shift, c.mean_abs_error_shifted);
      return c.mean_abs_error <= 0.10 ? 0 : 1;
    }
    const auto h = porosph::validation::check_hydrostatic(run_dir);
    std::printf(
        "hydrostatic_tank at t = %.3f s, depth %.4f m, %zu particles below the top two rows\n"
        "pressure error vs rho g (H - z): per particle max %.2f%% mean %.2f%%; row mean max %.2f%%"
        " (target 2%%)\nmax speed / sqrt(g H) = %.3f%% (target 1%%)\n",
        h.time, h.depth, h.particles, 100 * h.max_rel_error, 100 * h.mean_rel_error,
        100 * h.max_row_rel_error, 100 * h.max_speed_ratio);
    if (print_rows) {
      std::printf("%10s %12s %12s %10s %12s\n", "depth[m]", "p_exact", "p_mean", "mean err", "max err");
      for (const auto& row : h.rows) {
        std::printf("%10.4f %12.2f %12.2f %9.2f%% %11.2f%%\n", row.depth, row.exact, row.mean,
                    100 * (row.mean - row.exact) / row.exact, 100 * row.max_rel_error);
      }
    }
    return h.max_rel_error <= 0.02 && h.max_speed_ratio <= 0.01 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "porosph_validate: %s\n", e.what());
    return 2;
  }
}
