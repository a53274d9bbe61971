// fluid_solver: the water phase (WCSPH, seed eq. 2-4, 17) as a process driven by the coupler.
// Started by `coupler run`; connects to POROSPH_ENDPOINT (or --endpoint) and follows the protocol
// of proto/porosph.proto. Writes OUT/water.h5.
#include "fluid_solver/water_solver.h"
#include "proto/solver_main.h"

int main(int argc, char** argv) {
  return porosph::coupling::solver_process_main<porosph::water::WaterSolver>(
      argc, argv,
      {"fluid_solver", "PoroSPH water solver (started by `coupler run`)", "water", "porosph-water",
       "0.1.0", "water.h5"});
}
