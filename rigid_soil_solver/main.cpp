// rigid_soil_solver: the soil phase as a rigid porous skeleton (rigid_soil_solver.h), a process
// driven by the coupler. Select it with `soil.solver = "path/to/rigid_soil_solver"` in a scene,
// `--set soil.solver=PATH` or `--soil-solver PATH` (docs/solver-protocol.md). Writes OUT/soil.h5.
#include "proto/solver_main.h"
#include "rigid_soil_solver/rigid_soil_solver.h"

int main(int argc, char** argv) {
  return porosph::coupling::solver_process_main<porosph::rigid_soil::RigidSoilSolver>(
      argc, argv,
      {"rigid_soil_solver", "PoroSPH rigid porous skeleton soil solver (started by `coupler run`)",
       "soil", "porosph-rigid-soil", "0.1.0", "soil.h5"});
}
