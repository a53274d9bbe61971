// soil_solver: the soil phase (Drucker-Prager SPH, seed eq. 5-12, 18-20) as a process driven by the
// coupler. Started by `coupler run`; connects to POROSPH_ENDPOINT (or --endpoint) and follows the
// protocol of proto/porosph.proto. Writes OUT/soil.h5.
#include "proto/solver_main.h"
#include "soil_solver/soil_solver.h"

int main(int argc, char** argv) {
  return porosph::coupling::solver_process_main<porosph::soil::SoilSolver>(
      argc, argv,
      {"soil_solver", "PoroSPH soil solver (started by `coupler run`)", "soil", "porosph-soil",
       "0.1.0", "soil.h5"});
}
