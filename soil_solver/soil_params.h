// Parameters of the soil phase, resolved once from the scene and passed to every term (the solver's
// context: no globals). Per-material constants sit in `materials`, indexed by a particle's
// material.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "porous/submerged_density.h"
#include "scene/choice.h"
#include "scene/scene.h"
#include "scene/term_registry.h"
#include "soil_solver/artificial_stress.h"
#include "soil_solver/elastic_constants.h"
#include "soil_solver/geostatic_stress.h"
#include "soil_solver/soil_artificial_viscosity.h"
#include "soil_solver/soil_material.h"
#include "sph/particle_spacing.h"
#include "sph/vector.h"

namespace porosph::soil {

/// One soil material as the solver uses it.
struct SoilMaterialConstants {
  std::string name;
  Material model;         ///< K, G and the Drucker-Prager constants (eq. 6, 9-12)
  Material wet_model;     ///< the same without cohesion (wet_cohesion_loss), else = model
  double density = 0.0;   ///< bulk density at t = 0 (weight when dry) [kg/m^3]
  double porosity = 0.4;  ///< n0 (eq. 20)
  double young = 0.0;     ///< E [Pa] (damping coefficient)
  double k0 = 0.5;        ///< at-rest coefficient of the geostatic initial stress
  bool artificial_stress = false;
  bool fixed = false;  ///< rigid porous bed: never moves (held with the wall particles)
  bool wet_cohesion_loss = false;
  /// rho^s / rho when submerged: (rho_sat - rho_w) / rho_dry, rho_sat = saturated_density or, when
  /// not given, rho_dry + n0 rho_w (pores full of water). 1 in a scene without water.
  double submerged_ratio = 1.0;

  /// The constitutive model a particle uses now: without cohesion once wet (wet_cohesion_loss).
  const Material& current_model(bool wet) const { return wet ? wet_model : model; }
};

/// Weights of the periodic stress filter (stress_filter.h).
enum class StressFilterKind { Shepard, Mls };

template <int D>
struct SoilParams : sph::ParticleSpacing {  // dp, h, volume
  sph::Vec<D> gravity = sph::Vec<D>::Zero();
  double sound_speed = 0.0;  ///< c_s of the CFL limit and the artificial viscosity [m/s]
  SoilArtificialViscosity viscosity;
  ArtificialStressParameters artificial_stress;
  bool no_slip = true;             ///< default wall condition of the soil phase
  bool geostatic_initial = false;  ///< initial_stress = "geostatic"
  /// soil.thin_walls = "separating": thin walls in the soil are filled once per side and hide the
  /// pairs across them (sph/wall_occluders.h).
  bool two_sided_thin_walls = false;
  /// soil.wall_stress = "images": eq. 5 against a straight wall from mirror images of the soil
  /// (wall_mirror.h).
  bool wall_images = false;
  /// soil.wall_stress_continuation = "linear": wall particles continue each soil neighbour's stress
  /// with its gradient (wall_stress_continuation.h); false: with the weight, isotropically.
  bool linear_wall_stress = false;
  /// soil.stress_integration = "modified_euler": update_stress_modified_euler() (stress_update.h);
  /// false: update_stress(), forward Euler.
  bool modified_euler_stress = false;
  double damping_duration = 0.0;      ///< [s]; 0: no damping stage
  double damping_coefficient = 0.02;  ///< D = coefficient sqrt(E / (rho h^2))
  double cfl = 0.2, c_a = 0.25;
  int stress_filter_every = 0;  ///< stress filter period in steps (0: off)
  StressFilterKind stress_filter = StressFilterKind::Mls;
  double submerged_saturation = 0.8;  ///< water fraction from which a particle is submerged
  double wet_saturation = 0.1;        ///< water fraction from which a particle is wet
  std::vector<SoilMaterialConstants> materials;

  bool viscosity_on() const { return viscosity.alpha > 0.0 || viscosity.beta > 0.0; }
  bool any_wet_cohesion_loss() const {
    for (const auto& m : materials)
      if (m.wet_cohesion_loss) return true;
    return false;
  }
  bool any_artificial_stress() const {
    for (const auto& m : materials)
      if (m.artificial_stress) return true;
    return false;
  }

  /// Throws std::invalid_argument on a scene without soil, a dimension mismatch or a bad material.
  static SoilParams from_scene(const scene::Scene& s) {
    SoilParams p;
    p.take_from_scene<D>(s, "soil");
    const scene::SoilPhase& soil = *s.soil;
    const scene::TermSwitches on(s, "soil");  // the registry decides what runs
    p.gravity = sph::to_vec<D>(s.run.gravity, "run.gravity");
    p.sound_speed = soil.effective_sound_speed();
    p.viscosity = on("artificial_viscosity") ? SoilArtificialViscosity{soil.alpha, soil.beta, p.h}
                                             : SoilArtificialViscosity{0.0, 0.0, p.h};
    p.artificial_stress = {soil.artificial_stress_epsilon, soil.artificial_stress_exponent};
    p.no_slip = scene::checked_choice("soil.wall_condition", soil.wall_condition,
                                      {"no_slip", "free_slip"}) == "no_slip";
    p.geostatic_initial = on("geostatic_initial_stress");
    p.two_sided_thin_walls = on("thin_walls_two_sided");
    p.wall_images = on("wall_images");
    p.linear_wall_stress = on("wall_stress_linear_continuation");
    p.modified_euler_stress =
        scene::checked_choice("soil.stress_integration", soil.stress_integration,
                              {"euler", "modified_euler"}) == "modified_euler";
    p.damping_duration = on("damping_stage") ? soil.damping_duration : 0.0;
    p.damping_coefficient = soil.damping_coefficient;
    p.cfl = s.run.cfl;
    p.c_a = s.run.c_a;
    p.stress_filter_every =
        on("mls_stress_filter") || on("shepard_stress_filter") ? soil.stress_filter_every : 0;
    p.stress_filter =
        soil.stress_filter == "shepard" ? StressFilterKind::Shepard : StressFilterKind::Mls;
    p.submerged_saturation = s.coupling.submerged_saturation;
    p.wet_saturation = s.coupling.wet_saturation;
    const double rho_water = s.water ? s.water->rho0 : 0.0;
    for (const scene::SoilMaterial& m : soil.materials) {
      SoilMaterialConstants c;
      c.name = m.name;
      MaterialParameters mp;
      mp.young = m.young_modulus;
      mp.poisson = m.poisson_ratio;
      mp.friction_angle_deg = m.friction_angle_deg;
      mp.cohesion = m.cohesion;
      mp.dilatancy_angle_deg = m.dilatancy_angle_deg;
      mp.yield_fit = m.yield_fit == "flow_rule" ? YieldFit::kFlowRule : YieldFit::kSeedPaperEq10;
      try {
        c.model = make_material(mp);
        mp.cohesion = 0.0;
        c.wet_model = m.wet_cohesion_loss ? make_material(mp) : c.model;
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("soil material '" + m.name + "': " + e.what());
      }
      c.density = m.density;
      c.porosity = m.porosity;
      c.young = m.young_modulus;
      c.k0 = soil.k0 == "elastic" ? k0_elastic(m.poisson_ratio)
                                  : k0_jaky(degrees_to_radians(m.friction_angle_deg));
      c.artificial_stress = m.artificial_stress;
      c.fixed = m.fixed;
      c.wet_cohesion_loss = m.wet_cohesion_loss;
      if (rho_water > 0.0) c.submerged_ratio = porous::submerged_density_ratio(m, rho_water);
      p.materials.push_back(c);
    }
    return p;
  }
};

}  // namespace porosph::soil
