// Typed, validated scene: what the coupler and every solver read after parsing a scene TOML file.
//
// Vectors are stored as std::vector<double> of length `run.dimension` so this header stays free of
// Eigen and of the dimension template; solvers convert to their fixed-size vectors once at set-up.
// Every key, its unit, default and range is declared once in scene_schema.cpp; docs/scene.md is
// generated from that declaration (`coupler schema --markdown`).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace porosph::scene {

/// A geometric region. Filled with particles on a lattice of spacing dp (centres half a spacing
/// inside the region), or, for kind == Container, a wall of `layers` particle layers around the
/// inner box [min, max] with the faces named in `open_faces` left open.
struct Shape {
  enum class Kind { Box, Polygon, Container };
  Kind kind = Kind::Box;
  std::vector<double> min;                    ///< Box / Container: lower corner [m]
  std::vector<double> max;                    ///< Box / Container: upper corner [m]
  std::vector<std::vector<double>> vertices;  ///< Polygon (2D only): closed polygon [m]
  int layers = 3;                             ///< Container: wall thickness in particle layers
  std::vector<std::string> open_faces;        ///< Container: faces left open, e.g. "y+", "x-"
  std::string label;                          ///< optional name, shown in errors and output
  double remove_at = -1.0;                    ///< wall only: time [s] the block is removed (<0: never)
};

/// Global run settings (table [run]); every scene has end_time, output_interval, dp, h_factor.
struct RunSettings {
  int dimension = 2;
  double end_time = 1.0;         ///< [s]
  double output_interval = 0.1;  ///< [s]
  double dp = 0.01;              ///< particle spacing [m]
  double h_factor = 1.2;         ///< smoothing length h = h_factor * dp
  double dt0 = 1e-4;             ///< initial (and largest) time step [s], eq. 21 / Fig. 1
  double cfl = 0.2;              ///< C_cfl in dt_cfl = C_cfl h / (c + |v|max)
  double c_a = 0.25;             ///< C_a of eq. 21 (0.005 is the coupled default)
  double viscous_coefficient = 0.125;  ///< dt_visc = coeff h^2 / nu
  bool dt_smoothing = true;            ///< Fig. 1 smoothing on/off (off: dt = min(limits, dt0))
  int euler_every = 40;                ///< modified Verlet: an Euler step every N steps
  double solver_timeout = 60.0;        ///< [s] a solver silent this long fails the run
  std::vector<double> gravity;         ///< [m/s^2], length = dimension
  std::vector<bool> periodic;          ///< per axis, length = dimension
  std::string kernel = "cubic_spline"; ///< "cubic_spline" | "wendland_c2"
};

/// The simulation box: periodic axes wrap at its faces; particles leaving it are removed and counted.
struct Domain {
  std::vector<double> min;
  std::vector<double> max;
};

/// Water phase (table [water]).
struct WaterPhase {
  double rho0 = 1000.0;          ///< rest density [kg/m^3]
  double sound_speed = 20.0;     ///< numerical sound speed c in eq. 4 [m/s]
  double viscosity = 1.0e-3;     ///< dynamic viscosity mu [Pa s] (Morris 1997 term); 0: off
  double alpha = 0.05;           ///< Monaghan artificial viscosity alpha; 0: off
  double beta = 0.0;             ///< Monaghan artificial viscosity beta
  double gamma = 7.0;            ///< Tait exponent of eq. 4
  int density_filter_every = 0;  ///< Shepard density re-initialisation every N steps; 0: off
  bool hydrostatic_initial = true;  ///< initial density from hydrostatic pressure (inverse eq. 4)
  std::string wall_condition = "no_slip";  ///< "no_slip" | "free_slip"
  std::string solver;            ///< executable; empty: the built-in fluid_solver
  std::vector<Shape> blocks;     ///< regions filled with water at t = 0
};

/// A quantity measured on one phase at every output time and at the end.
struct Observable {
  std::string name;   ///< column name in timeseries.csv and key in run.json
  std::string kind;   ///< "front_position" | "max_speed" | "pressure_at" | "kinetic_energy" |
                      ///< "max_height" | "particle_count"
  std::string phase = "water";
  std::vector<double> direction;  ///< front_position / max_height: unit direction
  std::vector<double> origin;     ///< front_position / max_height: measured from here [m]
  std::vector<double> point;      ///< pressure_at: probe point [m]
};

struct Scene {
  std::string name;
  std::string description;
  std::string source_path;    ///< the file it was read from
  std::string resolved_toml;  ///< the scene after overrides, with defaults filled in
  RunSettings run;
  Domain domain;
  std::optional<WaterPhase> water;
  std::vector<Shape> walls;   ///< fixed wall particles, shared by every phase present
  std::vector<Observable> observables;

  double h() const { return run.h_factor * run.dp; }
  bool has_water() const { return water.has_value(); }
  /// Names of the phases present, in a fixed order ("water", later "soil").
  std::vector<std::string> phases() const;
};

}  // namespace porosph::scene
