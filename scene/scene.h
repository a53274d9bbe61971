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
/// inner box [min, max] with the faces named in `open_faces` left open. The same struct serves
/// phase blocks and walls; the last fields apply to one use only.
struct Shape {
  enum class Kind { Box, Polygon, Container };
  Kind kind = Kind::Box;
  std::vector<double> min;                    ///< Box / Container: lower corner [m]
  std::vector<double> max;                    ///< Box / Container: upper corner [m]
  std::vector<std::vector<double>> vertices;  ///< Polygon (2D only): closed polygon [m]
  int layers = 3;                             ///< Container: wall thickness in particle layers
  std::vector<std::string> open_faces;        ///< Container: faces left open, e.g. "y+", "x-"
  std::string label;                          ///< optional name, shown in errors and output
  double remove_at = -1.0;            ///< wall only: time [s] the block is removed (<0: never)
  std::vector<std::string> phases;    ///< wall only: phases it acts on (the loader always fills it;
                                      ///< empty, in a Scene built by code: every phase present)
  std::string condition = "default";  ///< wall only: "default" (the phase's wall_condition) |
                                      ///< "no_slip" | "free_slip"
  std::string material;               ///< soil block only: name of its SoilMaterial
  int source_line = 0;  ///< line of its table in the scene file (0: unknown, e.g. built in code)
  /// Wall only: the observable whose value is the wall's speed along move_direction [m/s] (the
  /// wall moves as one body); empty: fixed.
  std::string moves_with;
  std::vector<double> move_direction;  ///< wall only, with moves_with: unit vector
};

/// Global run settings (table [run]); every scene has end_time, output_interval, dp, h_factor.
struct RunSettings {
  int dimension = 2;
  double end_time = 1.0;         ///< [s]
  long max_steps = 0;            ///< stop after this many steps even before end_time; 0: no limit
  double output_interval = 0.1;  ///< [s]
  double timeseries_interval = 0.0;      ///< [s] between timeseries.csv rows; 0: output_interval
  double dp = 0.01;                      ///< particle spacing [m]
  double h_factor = 1.2;                 ///< smoothing length h = h_factor * dp
  double dt0 = 1e-4;                     ///< initial (and largest) time step [s], eq. 21 / Fig. 1
  double cfl = 0.2;                      ///< C_cfl in dt_cfl = C_cfl h / (c + |v|max)
  double c_a = 0.25;                     ///< C_a of eq. 21 (0.005 is the coupled default)
  double viscous_coefficient = 0.125;    ///< dt_visc = coeff h^2 / nu
  bool dt_smoothing = true;              ///< Fig. 1 smoothing on/off (off: dt = min(limits, dt0))
  int euler_every = 40;                  ///< modified Verlet: an Euler step every N steps
  double solver_timeout = 60.0;          ///< [s] a solver silent this long fails the run
  double checkpoint_interval = 0.0;      ///< [s] simulated time between checkpoints; 0: none
  double checkpoint_wall_minutes = 0.0;  ///< [min] wall time between checkpoints; 0: none
  std::vector<double> gravity;           ///< [m/s^2], length = dimension
  std::vector<bool> periodic;            ///< per axis, length = dimension
  std::string kernel = "cubic_spline";   ///< "cubic_spline" | "wendland_c2"
  std::string kernel_gradient =
      "lattice";  ///< "lattice" (normalised, sph/lattice_gradient.h) | "plain"
};

/// The simulation box: periodic axes wrap at its faces; particles leaving it are removed and
/// counted.
struct Domain {
  std::vector<double> min;
  std::vector<double> max;
};

/// A water inflow zone ([[water.inflow]]): particles inside move at speed_at(t) along direction.
struct InflowZone {
  std::vector<double> min, max;   ///< the box [m]
  std::vector<double> direction;  ///< unit flow direction (along one axis)
  double speed = 0.0;             ///< full speed [m/s] (velocity, or flow_rate / cross_section)
  double start_time = 0.0;        ///< [s]
  double ramp_time = 0.0;         ///< [s]; 0: a step
  /// 0 before start_time, then linear up to `speed` over ramp_time.
  double speed_at(double time) const;
};

/// A water outflow zone ([[water.outflow]]): particles entering the box are removed.
struct OutflowZone {
  std::vector<double> min, max;  ///< the box [m]
  double start_time = 0.0;       ///< removes water from this time on [s]
  double stagger = 0.0;          ///< removal spread over this many dp above the lower face
};

/// A constant-head reservoir ([[water.reservoir]]): holds the water surface inside the box at
/// `level` (fluid_solver/reservoirs.h).
struct ReservoirZone {
  std::vector<double> min, max;  ///< the box [m]
  double level = 0.0;            ///< coordinate of the surface along the gravity axis [m]
  double start_time = 0.0;       ///< holds the level from this time on [s]
  /// "surface" (particles added and removed at the surface, fluid_solver/reservoirs.h) | "open"
  /// (a buffer beyond the domain's open side, fluid_solver/open_reservoirs.h)
  std::string boundary = "surface";
  std::vector<double> direction;  ///< "open": unit inward normal of the open side
  /// "open" only: the imposed level falls by (H / sqrt(g H)) times the depth-mean inward velocity
  /// at the face, so that long waves leave the pool (fluid_solver/open_reservoirs.h)
  bool absorbing = false;
};

/// Soil-water interaction settings ([coupling]).
struct CouplingSettings {
  double submerged_saturation = 0.8;  ///< water fraction from which soil is submerged
  double wet_saturation = 0.1;        ///< water fraction from which soil is wet
  bool implicit_drag = true;          ///< the drag's rate goes to the solvers (implicit drag)
  /// "backward_euler" | "exponential": the implicit drag's weights over the step
  /// (coupler/interaction/drag_step_weights.h)
  std::string drag_step = "backward_euler";
  /// "renormalised" (by the wall's share of the support; coupler/interaction/wall_kernel_share.h)
  /// | "truncated" (the soil sums as they are)
  std::string drag_at_walls = "renormalised";
};

/// Water phase (table [water]).
struct WaterPhase {
  double rho0 = 1000.0;                      ///< rest density [kg/m^3]
  double sound_speed = 20.0;                 ///< numerical sound speed c in eq. 4 [m/s]
  double viscosity = 1.0e-3;                 ///< dynamic viscosity mu [Pa s] (laminar term); 0: off
  std::string laminar_viscosity = "morris";  ///< the laminar law (fluid_solver/laminar_viscosity.h)
  double alpha = 0.05;                       ///< Monaghan artificial viscosity alpha; 0: off
  double beta = 0.0;                         ///< Monaghan artificial viscosity beta
  double gamma = 7.0;                        ///< Tait exponent of eq. 4
  int density_filter_every = 0;    ///< Shepard density re-initialisation every N steps; 0: off
  double density_diffusion = 0.1;  ///< delta of the density diffusion term (delta-SPH); 0: off
  std::string density_diffusion_correction = "linear";  ///< "linear" | "hydrostatic"
  /// "drag_limited" (the seepage drag replaces the artificial viscosity where it damps faster;
  /// fluid_solver/artificial_viscosity.h) | "drag_replaced" (wherever it holds the water;
  /// fluid_solver/drag_weight.h) | "full"
  std::string artificial_viscosity_in_soil = "drag_limited";
  std::string pressure_gradient_in_soil = "symmetric";
  double particle_shifting = 0.0;   ///< A of the Fickian particle shifting (Lind 2012); 0: off
  bool hydrostatic_initial = true;  ///< initial density from hydrostatic pressure (inverse eq. 4)
  /// "separating": thin box walls between two bodies of water part them at any thickness
  /// (sph/wall_occluders.h) | "shared": their particles are neighbours of both sides
  std::string thin_walls = "separating";
  std::string initial_velocity = "none";   ///< "none" (at rest) | "taylor_green"
  double taylor_green_speed = 0.0;         ///< amplitude U of the Taylor-Green field [m/s]
  double taylor_green_wavelength = 0.0;    ///< its wavelength L = 2 pi / k [m]
  std::string wall_condition = "no_slip";  ///< "no_slip" | "free_slip"
  /// Monaghan term between water and no-slip wall particles (fluid_solver/wall_normal_damping.h):
  /// "normal" (on the wall-normal approach only) | "full" (also a wall friction) | "none"
  std::string artificial_viscosity_at_walls = "normal";
  std::string solver;         ///< executable; empty: the built-in fluid_solver
  std::vector<Shape> blocks;  ///< regions filled with water at t = 0
  std::vector<InflowZone> inflows;
  std::vector<OutflowZone> outflows;
  std::vector<ReservoirZone> reservoirs;
};

/// One soil material ([[soil.materials]]): Drucker-Prager skeleton (eq. 6-12) and the seepage
/// law the coupler applies between it and the water (eq. 13-15, 20).
struct SoilMaterial {
  std::string name;
  double density = 0.0;            ///< bulk density, weight when dry [kg/m^3]
  double saturated_density = 0.0;  ///< bulk density with water-filled pores [kg/m^3]; 0: not given
  double porosity = 0.4;           ///< initial porosity n0
  /// Both elastic pairs are filled by the loader from whichever the scene gave:
  /// K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)); E = 9 K G / (3 K + G),
  /// nu = (3 K - 2 G) / (2 (3 K + G)).
  double young_modulus = 0.0;        ///< E [Pa]
  double poisson_ratio = 0.0;        ///< nu
  double bulk_modulus = 0.0;         ///< K [Pa]
  double shear_modulus = 0.0;        ///< G [Pa]
  double cohesion = 0.0;             ///< c [Pa]
  double friction_angle_deg = 0.0;   ///< phi [deg]
  double dilatancy_angle_deg = 0.0;  ///< psi [deg], <= phi
  std::string yield_fit = "eq10";    ///< "eq10" | "flow_rule" (drucker_prager_constants.h)
  bool artificial_stress = false;    ///< Gray-Monaghan artificial stress on
  bool fixed = false;                ///< rigid porous bed: never moves
  std::string seepage = "none";      ///< "none" or a law of porous/seepage_laws.h
  /// The keys of that law (effective_diameter, hydraulic_conductivity, d15, den_adel_alpha, ...),
  /// by name, with their defaults filled in; empty for "none".
  std::map<std::string, double> seepage_parameters;
  /// A law key's value, 0 when the material's law has no such key.
  double seepage_parameter(const std::string& key) const {
    const auto it = seepage_parameters.find(key);
    return it == seepage_parameters.end() ? 0.0 : it->second;
  }
  bool variable_permeability = true;  ///< coefficients follow the current porosity (eq. 20)
  bool wet_cohesion_loss = false;     ///< cohesion vanishes once the particle is wet
};

/// A surface load on the soil ([[soil.loads]]): the free soil particles inside [min, max] at t = 0
/// carry `traction` times the box's extent across the traction's axis, shared equally.
struct SoilLoad {
  std::vector<double> min, max;  ///< the box selecting the loaded particles at t = 0 [m]
  std::vector<double> traction;  ///< force per unit area once ramped up, along one axis [Pa]
  double start_time = 0.0;       ///< [s]
  double ramp_time = 0.0;        ///< [s]; 0: a step
  std::string label;
  /// The loaded particles move as one along the traction's axis (a rigid, frictionless plate):
  /// their velocities along it are set to their mass-weighted mean after every kick.
  bool rigid = false;
  /// Name of an observable whose latest value [N/m^(3-D)] is added to the load's force along the
  /// +axis of its traction's axis (e.g. the wall_force of the lid moving with a rigid plate);
  /// empty: none.
  std::string plus_force_from;
  /// Material the loaded particles take from t = 0 (same density and porosity; e.g. an
  /// impermeable one that seals the plate); empty: they keep their own.
  std::string material;
  /// 0 before start_time, then linear up to 1 over ramp_time.
  double factor_at(double time) const;
  /// The loaded face's size: the product of the box's extents along the axes the traction does
  /// not act on [m^(D-1)] (2D: a length, the force per unit thickness).
  double face_extent() const;
};

/// Soil phase (table [soil]).
struct SoilPhase {
  std::string solver;                        ///< executable; empty: the built-in soil_solver
  std::string wall_condition = "no_slip";    ///< "no_slip" | "free_slip"
  double alpha = 0.1;                        ///< Monaghan artificial viscosity alpha
  double beta = 0.1;                         ///< Monaghan artificial viscosity beta
  double artificial_stress_epsilon = 0.5;    ///< Gray-Monaghan epsilon
  double artificial_stress_exponent = 2.55;  ///< Gray-Monaghan n
  double sound_speed = 0.0;  ///< [m/s]; 0: from the stiffest material (stiffest_sound_speed())
  std::string initial_stress = "none";  ///< "geostatic" | "none"
  std::string k0 = "jaky";              ///< "jaky" (1 - sin phi) | "elastic" (nu / (1 - nu))
  double damping_duration = 0.0;        ///< [s] initial damping stage; 0: none
  /// "separating": thin box walls in the soil part it at any thickness (sph/wall_occluders.h) |
  /// "shared": their particles are neighbours of both sides
  std::string thin_walls = "separating";
  /// "images": eq. 5 against a straight wall from mirror images of the soil (wall_mirror.h) |
  /// "wall_particles": from the wall particles
  std::string wall_stress = "images";
  /// "linear": wall particles continue each soil neighbour's stress with its gradient |
  /// "weight": with the weight, isotropically (soil_solver/wall_stress_continuation.h)
  std::string wall_stress_continuation = "weight";
  /// "euler" or "modified_euler": the stress update's time step (soil_solver/stress_update.h)
  std::string stress_integration = "euler";
  double damping_coefficient = 0.02;  ///< D = coefficient sqrt(E / (rho h^2))
  int stress_filter_every = 0;        ///< stress filter every N steps; 0: off
  std::string stress_filter = "mls";  ///< its weights: "shepard" | "mls"
  std::vector<SoilMaterial> materials;
  std::vector<Shape> blocks;    ///< regions filled with soil at t = 0; `material` names one
  std::vector<SoilLoad> loads;  ///< surface loads

  /// Index into `materials` of the material named `name`, or -1.
  int material_index(const std::string& name) const;
  /// max over the materials of the P-wave speed sqrt((K + 4 G / 3) / density) [m/s] (0 without
  /// materials): the fastest elastic wave, which bounds the explicit time step.
  double stiffest_sound_speed() const;
  /// sound_speed if set (> 0), else stiffest_sound_speed().
  double effective_sound_speed() const;
};

/// A quantity measured on one phase at every output time and at the end.
struct Observable {
  std::string name;  ///< column name in timeseries.csv and key in run.json
  std::string kind;  ///< "front_position" | "max_speed" | "pressure_at" | "kinetic_energy" |
                     ///< "max_height" | "particle_count" | "mean_field" | "max_displacement" |
                     ///< "load_velocity" | "wall_force"
  std::string phase = "water";
  std::vector<double> direction;   ///< front_position / max_height: unit direction
  std::vector<double> origin;      ///< front_position / max_height: measured from here [m]
  std::vector<double> point;       ///< pressure_at: probe point [m]
  std::string field;               ///< mean_field: "porosity", "stress_yy", "velocity_y", ...
  std::vector<double> region_min;  ///< only particles in [region_min, region_max] count [m];
  std::vector<double> region_max;  ///< both empty: every particle of the phase
  std::string load;                ///< load_velocity: label of the [[soil.loads]] entry
  std::string wall;                ///< wall_force: label of the moving wall
};

struct Scene {
  std::string name;
  std::string description;
  std::string source_path;    ///< the file it was read from
  std::string resolved_toml;  ///< the scene after overrides, with defaults filled in
  RunSettings run;
  Domain domain;
  std::optional<WaterPhase> water;
  std::optional<SoilPhase> soil;
  std::vector<Shape> walls;  ///< fixed wall particles; each acts on the phases it lists
  std::vector<Observable> observables;
  CouplingSettings coupling;

  double h() const { return run.h_factor * run.dp; }
  bool has_water() const { return water.has_value(); }
  bool has_soil() const { return soil.has_value(); }
  /// Names of the phases present, in a fixed order: "water", then "soil".
  std::vector<std::string> phases() const;
  /// The walls that act on `phase` (those whose `phases` is empty or names it).
  std::vector<Shape> walls_acting_on(const std::string& phase) const;
};

}  // namespace porosph::scene
