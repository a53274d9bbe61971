// Parameters of the water phase, resolved once from the scene and passed to every term (the
// solver's context: no globals).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "fluid_solver/artificial_viscosity.h"
#include "fluid_solver/equation_of_state.h"
#include "fluid_solver/wall_normal_damping.h"
#include "scene/choice.h"
#include "scene/scene.h"
#include "scene/term_registry.h"
#include "sph/particle_spacing.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
struct WaterParams : sph::ParticleSpacing {  // dp, h, volume
  TaitEos eos;                               ///< eq. 4
  double mu = 0.0;                           ///< dynamic viscosity [Pa s] (laminar term; 0: off)
  std::string laminar_viscosity = "morris";  ///< its law (laminar_viscosity.h)
  ArtificialViscosity artificial;            ///< Monaghan 1992 (alpha = beta = 0: off)
  double eta2 = 0.0;                         ///< 0.01 h^2, regularisation of 1/r terms
  sph::Vec<D> gravity = sph::Vec<D>::Zero();
  bool no_slip = true;  ///< walls: mirrored velocity in viscous terms; false: excluded
  /// the Monaghan term at no-slip walls (wall_normal_damping.h)
  WallArtificialViscosity artificial_at_walls = WallArtificialViscosity::normal;
  int density_filter_every = 0;    ///< Shepard filter period in steps (0: off)
  double density_diffusion = 0.0;  ///< delta of the density diffusion term (0: off)
  /// The diffusion leaves any linear departure potential alone (density_diffusion_gradient.h);
  /// false: only still water (water.density_diffusion_correction = "hydrostatic").
  bool diffusion_linear = true;
  double particle_shifting = 0.0;  ///< A of the particle shifting (particle_shifting.h; 0: off)
  int euler_every = 40;            ///< modified Verlet: Euler step period
  double cfl = 0.2, c_a = 0.25, viscous_coefficient = 0.125;
  bool hydrostatic_initial = true;
  /// water.thin_walls = "separating": thin walls between two bodies of water are filled once per
  /// side and hide the pairs across them (sph/wall_occluders.h).
  bool two_sided_thin_walls = false;
  /// run.kernel_gradient = "particle": per-particle gradient renormalisation (particle_gradient.h).
  bool particle_gradient = false;
  /// run.kernel_gradient = "particle_matrix": the matrix form of it (particle_gradient.h).
  bool particle_gradient_matrix = false;
  /// water.pressure_gradient_in_soil = "hydrostatic_difference" (hydrostatic_difference.h).
  bool hydrostatic_difference_in_soil = false;
  /// r_av of the drag share s_a = min(1, lambda_a / r_av) (artificial_viscosity.h), which the
  /// drag-limited artificial viscosity uses; 0 with alpha = 0 (then s_a = 1 wherever
  /// lambda_a > 0).
  double drag_share_rate = 0.0;
  /// water.artificial_viscosity_in_soil = "drag_replaced": the artificial viscosity keeps 1 - s_a
  /// of the drag weight of drag_weight.h (0 inside soil), which the rates recompute each step.
  bool artificial_replaced_by_drag = false;

  bool laminar_on() const { return mu > 0.0; }
  /// The law the rates loop compiles in: "" when the laminar term is off.
  std::string laminar_law() const { return laminar_on() ? laminar_viscosity : std::string(); }
  bool artificial_on() const { return artificial.alpha > 0.0 || artificial.beta > 0.0; }
  bool diffusion_on() const { return density_diffusion > 0.0; }
  bool shifting_on() const { return particle_shifting > 0.0; }
  /// Whether a term uses the drag share (set_drag_rate fills it only then).
  bool drag_share_on() const {
    return artificial.damping_rate > 0.0 || artificial_replaced_by_drag ||
           hydrostatic_difference_in_soil;
  }
  /// Whether the artificial viscosity yields to the drag inside soil (either way).
  bool artificial_yields_to_drag() const {
    return artificial.damping_rate > 0.0 || artificial_replaced_by_drag;
  }
  /// s_a of a drag rate lambda_a >= 0 [1/s].
  double drag_share(double drag_rate) const {
    return ArtificialViscosity::drag_share(drag_rate, drag_share_rate);
  }

  /// Throws std::invalid_argument if the scene has no water or an unknown wall condition.
  static WaterParams from_scene(const scene::Scene& s) {
    WaterParams p;
    p.take_from_scene<D>(s, "water");
    const scene::WaterPhase& w = *s.water;
    const scene::TermSwitches on(s, "water");  // the registry decides what runs
    p.eos = TaitEos(w.rho0, w.sound_speed, w.gamma);
    p.laminar_viscosity = w.laminar_viscosity;
    p.mu = on(w.laminar_viscosity + "_viscosity") ? w.viscosity : 0.0;
    p.eta2 = 0.01 * p.h * p.h;
    p.artificial = on("artificial_viscosity") ? ArtificialViscosity{w.alpha, w.beta, p.h, 0.0}
                                              : ArtificialViscosity{0.0, 0.0, p.h, 0.0};
    if (on("artificial_viscosity_drag_limited")) {
      p.artificial.damping_rate =
          ArtificialViscosity::kernel_damping_rate(w.alpha, w.sound_speed, p.h, D);
    } else {
      scene::checked_choice("water.artificial_viscosity_in_soil", w.artificial_viscosity_in_soil,
                            {"drag_limited", "drag_replaced", "full"});
    }
    p.artificial_replaced_by_drag = on("artificial_viscosity_drag_replaced");
    p.gravity = sph::to_vec<D>(s.run.gravity, "run.gravity");
    p.no_slip = scene::checked_choice("water.wall_condition", w.wall_condition,
                                      {"no_slip", "free_slip"}) == "no_slip";
    p.artificial_at_walls =
        on("artificial_viscosity_at_walls")
            ? WallArtificialViscosity::full
            : (on("artificial_viscosity_at_walls_normal") ? WallArtificialViscosity::normal
                                                          : WallArtificialViscosity::none);
    scene::checked_choice("water.artificial_viscosity_at_walls", w.artificial_viscosity_at_walls,
                          {"normal", "full", "none"});
    p.density_filter_every = on("shepard_density_filter") ? w.density_filter_every : 0;
    p.density_diffusion = on("density_diffusion") ? w.density_diffusion : 0.0;
    p.diffusion_linear = w.density_diffusion_correction == "linear";
    p.particle_shifting = on("particle_shifting") ? w.particle_shifting : 0.0;
    p.euler_every = s.run.euler_every;
    p.cfl = s.run.cfl;
    p.c_a = s.run.c_a;
    p.viscous_coefficient = s.run.viscous_coefficient;
    p.hydrostatic_initial = w.hydrostatic_initial;
    p.two_sided_thin_walls = on("thin_walls_two_sided");
    p.particle_gradient = s.run.kernel_gradient == "particle";
    p.particle_gradient_matrix = s.run.kernel_gradient == "particle_matrix";
    scene::checked_choice("water.pressure_gradient_in_soil", w.pressure_gradient_in_soil,
                          {"symmetric", "hydrostatic_difference"});
    p.hydrostatic_difference_in_soil = on("pressure_gradient_hydrostatic_difference_in_soil");
    p.drag_share_rate = ArtificialViscosity::kernel_damping_rate(w.alpha, w.sound_speed, p.h, D);
    return p;
  }
};

}  // namespace porosph::water
