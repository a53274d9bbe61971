// porosph_seepage_reference: prints the grid series of the 2D seepage references
// (docs/verification.md, "Reference solutions for 2D seepage") as Markdown tables.
//   porosph_seepage_reference sheet_pile [--width 1.2] [--depth 0.2] [--pile 0.1] [--drop 0.05]
//                                        [--base-rows 10] [--levels 5]
//   porosph_seepage_reference rectangular_dam [--length 0.4] [--upstream 0.3]
//                                             [--downstream 0.05] [--base-x 8] [--base-y 6]
//                                             [--levels 5]
#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "tools/validation/rectangular_dam.h"
#include "tools/validation/rectangular_dam_exact.h"
#include "tools/validation/sheet_pile.h"

namespace v = porosph::validation;

int main(int argc, char** argv) {
  CLI::App app{"Grid-converged references of 2D steady seepage"};
  app.require_subcommand(1);
  v::SheetPile pile;
  int rows = 10, pile_levels = 5;
  auto* sp = app.add_subcommand("sheet_pile", "sheet pile in a layer: FV grid series and Harr");
  sp->add_option("--width", pile.width, "L [m]");
  sp->add_option("--depth", pile.layer_depth, "T [m]");
  sp->add_option("--pile", pile.pile_depth, "s [m]");
  sp->add_option("--drop", pile.head_upstream, "h1 - h2 [m] (h2 = 0)");
  sp->add_option("--base-rows", rows, "cells across T on the coarsest grid (square cells)");
  sp->add_option("--levels", pile_levels, "grids, each refined by 2");
  v::RectangularDam dam;
  int base_x = 8, base_y = 6, dam_levels = 5;
  auto* rd = app.add_subcommand("rectangular_dam", "Baiocchi free surface: grid series");
  rd->add_option("--length", dam.length, "L [m]");
  rd->add_option("--upstream", dam.head_upstream, "h1 [m]");
  rd->add_option("--downstream", dam.head_downstream, "h2 [m]");
  rd->add_option("--base-x", base_x, "cells along L on the coarsest grid");
  rd->add_option("--base-y", base_y, "cells along h1 on the coarsest grid");
  rd->add_option("--levels", dam_levels, "grids, each refined by 2");
  CLI11_PARSE(app, argc, argv);
  try {
    if (*sp) {
      const int cols = static_cast<int>(std::lround(rows * pile.width / pile.layer_depth));
      const double mid = 0.5 * pile.width, tip = pile.layer_depth - pile.pile_depth;
      const std::vector<std::array<double, 2>> probes = {{mid - 0.1, 0.05},
                                                         {mid + 0.1, 0.05},
                                                         {mid - 1e-9, tip + 0.5 * pile.pile_depth},
                                                         {mid + 1e-9, tip + 0.5 * pile.pile_depth}};
      const auto s = v::sheet_pile_series(pile, cols, rows, pile_levels, probes, 0.005);
      std::printf("%s\n", v::markdown_table(s, [&](int r) {
                            return std::to_string(r * cols) + " x " + std::to_string(r * rows);
                          }).c_str());
      const double t = pile.layer_depth, s_ = pile.pile_depth, dh = pile.head_drop();
      std::printf(
          "Harr (infinite extent): q/(K dh) = %.6f, i(0) = %.6f, mean i over 5 mm = %.6f, "
          "h on the pile faces at mid-depth = %.6f / %.6f; infinite depth i = %.6f\n",
          v::harr_discharge_factor(t, s_), v::harr_exit_gradient(t, s_, dh, 0.0),
          v::harr_mean_exit_gradient(t, s_, dh, 0.005),
          v::harr_pile_face_head(pile, tip + 0.5 * s_, false),
          v::harr_pile_face_head(pile, tip + 0.5 * s_, true),
          v::harr_infinite_depth_exit_gradient(s_, dh));
    } else {
      const auto s =
          v::rectangular_dam_series(dam, base_x, base_y, dam_levels, {0.25, 0.5, 0.75, 0.9});
      std::printf("%s\n", v::markdown_table(s, [&](int r) {
                            return std::to_string(r * base_x) + " x " + std::to_string(r * base_y);
                          }).c_str());
      std::printf(
          "Dupuit-Charnyi q / K = %.6f m; Dupuit's parabola at x/L 0.25 0.5 0.75 0.9: %.5f "
          "%.5f %.5f %.5f\n",
          dam.charnyi_discharge() / dam.conductivity, dam.dupuit_height(0.25 * dam.length),
          dam.dupuit_height(0.5 * dam.length), dam.dupuit_height(0.75 * dam.length),
          dam.dupuit_height(0.9 * dam.length));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "porosph_seepage_reference: %s\n", e.what());
    return 2;
  }
  return 0;
}
