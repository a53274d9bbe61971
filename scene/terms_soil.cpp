// The soil phase's terms and the soil-water interaction's (scene/term_registry.h): one
// registration per term, with the keys it owns and its switch.
#include <algorithm>

#include "porous/seepage_laws.h"
#include "scene/scene_schema_builder.h"
#include "scene/term_registry.h"
#include "scene/thin_walls.h"

namespace porosph::scene::term_detail {
namespace {

using schema_detail::Key;
using schema_detail::T;

const SoilPhase& soil(const Scene& s) { return *s.soil; }

/// Whether any material satisfies `pick`.
template <class Pick>
bool any_material(const Scene& s, Pick pick) {
  return std::any_of(soil(s).materials.begin(), soil(s).materials.end(), pick);
}

bool seeps(const SoilMaterial& m) { return m.seepage != "none"; }

/// The soil phase has fixed particles that take their stress from the soil around them: walls
/// acting on soil, or a fixed material (soil_solver/soil_walls.h).
bool has_soil_wall_particles(const Scene& s) {
  return !s.walls_acting_on("soil").empty() ||
         any_material(s, [](const SoilMaterial& x) { return x.fixed; });
}

TermSpec term(std::string phase, std::string name, std::string summary, std::string runs_when,
              std::function<bool(const Scene&)> active, std::vector<KeySpec> keys = {}) {
  return {std::move(name),      std::move(phase), std::move(summary),
          std::move(runs_when), std::move(keys),  std::move(active)};
}

TermSpec soil_term(std::string name, std::string summary, std::string runs_when,
                   std::function<bool(const Scene&)> active, std::vector<KeySpec> keys = {}) {
  return term("soil", std::move(name), std::move(summary), std::move(runs_when), std::move(active),
              std::move(keys));
}

bool always(const Scene&) { return true; }

}  // namespace

void add_soil_terms(std::vector<TermSpec>& t) {
  const std::string m = "soil.materials[].";
  t.push_back(soil_term("stress_divergence",
                        "Momentum equation of the skeleton, the divergence of the total stress "
                        "(seed paper eq. 5); soil_solver/stress_divergence.h.",
                        "always", always));
  t.push_back(soil_term("gravity", "Body force run.gravity.", "always", always));
  t.push_back(soil_term("velocity_gradient",
                        "Strain and spin rates from the velocity gradient (eq. 7); "
                        "soil_solver/velocity_gradient.h.",
                        "always", always));
  t.push_back(soil_term("jaumann_stress_rate",
                        "Elastic stress rate with the Jaumann rotation (eq. 6); "
                        "soil_solver/jaumann_rate.h.",
                        "always", always));
  t.push_back(soil_term(
      "drucker_prager_return",
      "Return to the Drucker-Prager cone (eq. 8-12); soil_solver/drucker_prager.h, "
      "stress_update.h.",
      "always", always,
      {Key("soil.stress_integration", T::String)
           .fallback("\"euler\"")
           .one_of({"euler", "modified_euler"})
           .doc("The stress update's step at the step's strain rate and spin. euler: the rate "
                "(eq. 6 + 12a) at the old stress, first order in dt; modified_euler: its mean at "
                "the old and the Euler-predicted stress (Heun; Sloan 1987 without "
                "substeps), second order, one more rate evaluation per particle (docs/soil.md, "
                "Time integration).")}));
  t.push_back(soil_term("artificial_viscosity",
                        "Monaghan (1992) artificial viscosity between soil particles; "
                        "soil_solver/soil_artificial_viscosity.h.",
                        "soil.alpha > 0 or soil.beta > 0",
                        [](const Scene& s) { return soil(s).alpha > 0.0 || soil(s).beta > 0.0; },
                        {Key("soil.alpha", T::Float)
                             .fallback("0.1")
                             .at_least(0)
                             .doc("Monaghan artificial viscosity alpha; 0 switches it off."),
                         Key("soil.beta", T::Float)
                             .fallback("0.1")
                             .at_least(0)
                             .doc("Monaghan artificial viscosity beta.")}));
  t.push_back(
      soil_term("artificial_stress",
                "Gray, Monaghan & Swift (2001) artificial stress against the tensile "
                "instability; soil_solver/artificial_stress.h.",
                "a material with artificial_stress = true",
                [](const Scene& s) {
                  return any_material(s, [](const SoilMaterial& x) { return x.artificial_stress; });
                },
                {Key("soil.artificial_stress_epsilon", T::Float)
                     .fallback("0.5")
                     .at_least(0)
                     .doc("Gray-Monaghan artificial stress coefficient epsilon (materials with "
                          "artificial_stress = true)."),
                 Key("soil.artificial_stress_exponent", T::Float)
                     .fallback("2.55")
                     .above(0)
                     .doc("Exponent n of the artificial stress, f = (W(r) / W(dp))^n."),
                 Key(m + "artificial_stress", T::Bool)
                     .fallback("false")
                     .doc("Gray-Monaghan artificial stress against tensile instability.")}));
  t.push_back(soil_term(
      "mls_stress_filter",
      "Moving-least-squares filter of the stress (Nguyen et al. 2017); "
      "soil_solver/stress_filter.h.",
      "soil.stress_filter_every > 0 and soil.stress_filter = \"mls\"",
      [](const Scene& s) {
        return soil(s).stress_filter_every > 0 && soil(s).stress_filter == "mls";
      },
      {Key("soil.stress_filter_every", T::Int)
           .fallback("0")
           .at_least(0)
           .doc("Filter of the soil stress every N steps (stress regularisation, "
                "Nguyen et al. 2017; weights: soil.stress_filter); removes the "
                "row-to-row stress oscillation the pair form of eq. 5 cannot see; "
                "0: off."),

       Key("soil.stress_filter", T::String)
           .fallback("\"mls\"")
           .one_of({"shepard", "mls"})
           .doc("Weights of that filter (within one material, then back onto the yield cone): "
                "shepard, the kernel average (exact for a constant stress; near a free face it "
                "hands a particle the stress of the deeper rows); mls, a first-order moving "
                "least squares fit (exact for a linearly varying stress, also at free faces).")}));
  t.push_back(soil_term(
      "shepard_stress_filter",
      "Shepard (kernel-average) filter of the stress; "
      "soil_solver/stress_filter.h.",
      "soil.stress_filter_every > 0 and soil.stress_filter = \"shepard\"", [](const Scene& s) {
        return soil(s).stress_filter_every > 0 && soil(s).stress_filter == "shepard";
      }));
  t.push_back(
      soil_term("wet_cohesion_loss",
                "Cohesion lost once a particle is wet, the stress returned to the new "
                "cone (rockfill); soil_solver/drucker_prager.h.",
                "a material with wet_cohesion_loss = true",
                [](const Scene& s) {
                  return any_material(s, [](const SoilMaterial& x) { return x.wet_cohesion_loss; });
                },
                {Key(m + "wet_cohesion_loss", T::Bool)
                     .fallback("false")
                     .doc("Cohesion vanishes once the particle is wet, its stress scaled back "
                          "onto the new yield surface (rockfill).")}));
  t.push_back(soil_term("walls",
                        "Wall particles of the skeleton, and the particles of fixed materials, "
                        "which are held like walls; soil_solver/soil_walls.h.",
                        "walls acting on soil, or a material with fixed = true",
                        has_soil_wall_particles,
                        {Key("soil.wall_condition", T::String)
                             .fallback("\"no_slip\"")
                             .one_of({"no_slip", "free_slip"})
                             .doc("Velocity condition at wall particles.")}));
  t.push_back(soil_term(
      "thin_walls_two_sided",
      "Box walls too thin to part the soil on their two sides (fewer than 2 (ceil(2h / dp) - 1) "
      "layers, soil within 2h of both faces) are filled once per side and hide every pair "
      "across their mid-plane; sph/wall_occluders.h.",
      "a thin wall (scene/thin_walls.h) acting on soil and soil.thin_walls = \"separating\"",
      [](const Scene& s) {
        return soil(s).thin_walls == "separating" && has_thin_walls(s, "soil");
      },
      {Key("soil.thin_walls", T::String)
           .fallback("\"separating\"")
           .one_of({"separating", "shared"})
           .doc("Box walls acting on soil that are thinner than 2m layers (m = ceil(2h / dp) - "
                "1; 4 at h = 1.2 dp) with soil within 2h of both faces (a sheet pile in the "
                "ground). \"separating\": each side gets max(L, m) wall layers of its own, seen "
                "only from that side (normal: out of the wall into that side), and no soil pair "
                "interacts across the wall's mid-plane (sph/wall_occluders.h); \"shared\": the "
                "soil on the two sides are neighbours through the wall and its particles take "
                "the stress of both.")}));
  t.push_back(soil_term(
      "wall_images",
      "Stress divergence (eq. 5), velocity gradient and continuity against a straight wall from "
      "mirror images of the soil, which slide with it (ghost particles, Libersky et al. 1993); "
      "soil_solver/wall_mirror.h.",
      "a free-slip wall acting on soil and soil.wall_stress = \"images\"",
      [](const Scene& s) {
        const auto walls = s.walls_acting_on("soil");
        return soil(s).wall_stress == "images" &&
               std::any_of(walls.begin(), walls.end(), [&](const Shape& w) {
                 return w.condition == "free_slip" ||
                        (w.condition == "default" && soil(s).wall_condition == "free_slip");
               });
      },
      {Key("soil.wall_stress", T::String)
           .fallback("\"images\"")
           .one_of({"images", "wall_particles"})
           .doc(
               "How eq. 5, the velocity gradient and the continuity equation see a straight "
               "free-slip wall (every wall particle within 2h inside a straight stretch, on one "
               "axis and one side; elsewhere, and at no-slip walls, the wall particles always "
               "act). images: the mirror images of the soil across the wall's face (stress "
               "reflected, weight continued, normal velocity mirrored), which slide with the "
               "soil; wall_particles: the "
               "wall particles, whose sums change as the soil's lattice slides along them (a push "
               "off the wall and a density change that grow as dp falls; docs/soil.md, Walls).")}));
  t.push_back(soil_term(
      "wall_stress_linear_continuation",
      "Wall particles take the Shepard mean of their soil neighbours' stress, each continued to "
      "the wall particle with its own corrected gradient, limited by the weight's continuation "
      "(exact for a geostatic state); soil_solver/wall_stress_continuation.h.",
      "walls acting on soil, or a fixed material, and soil.wall_stress_continuation = \"linear\"",
      [](const Scene& s) {
        return soil(s).wall_stress_continuation == "linear" && has_soil_wall_particles(s);
      },
      {Key("soil.wall_stress_continuation", T::String)
           .fallback("\"weight\"")
           .one_of({"linear", "weight"})
           .doc("How a wall particle continues its soil neighbours' stress to its own place. "
                "linear: sigma_f + grad sigma_f . (x_w - x_f) on the diagonal where that change "
                "has the weight's sign and is smaller (minmod), the gradient corrected to first "
                "order over f's soil neighbours (where that support is too thin, the weight "
                "form); weight: sigma_f - rho_f (g . (x_w - x_f)) I, the weight continued "
                "isotropically, so a floor's and a corner's wall particles are compressed "
                "sideways by (1 - K0) rho g dy too much (docs/soil.md, Walls).")}));
  t.push_back(
      soil_term("geostatic_initial_stress",
                "At-rest initial stress from the weight above; "
                "soil_solver/geostatic_stress.h.",
                "soil.initial_stress = \"geostatic\"",
                [](const Scene& s) { return soil(s).initial_stress == "geostatic"; },
                {Key("soil.initial_stress", T::String)
                     .fallback("\"none\"")
                     .one_of({"geostatic", "none"})
                     .doc("geostatic: at-rest stress from the weight of the soil above, "
                          "horizontal = k0 vertical; none: zero stress (use damping to settle)."),
                 Key("soil.k0", T::String)
                     .fallback("\"jaky\"")
                     .one_of({"jaky", "elastic"})
                     .doc("Earth pressure coefficient at rest for geostatic initial stress: "
                          "jaky, K0 = 1 - sin(phi); elastic, K0 = nu / (1 - nu).")}));
  t.push_back(soil_term(
      "damping_stage",
      "Initial damping (dynamic relaxation) stage; sph/damping_stage.h, "
      "soil_solver/soil_solver.cpp.",
      "soil.damping_duration > 0", [](const Scene& s) { return soil(s).damping_duration > 0.0; },
      {Key("soil.damping_duration", T::Float)
           .unit("s")
           .fallback("0.0")
           .at_least(0)
           .doc("Length of the initial damping (dynamic relaxation) stage; 0: none."),
       Key("soil.damping_coefficient", T::Float)
           .fallback("0.02")
           .at_least(0)
           .doc("Damping during that stage: D = coefficient sqrt(E / (density h^2)) "
                "[1/s].")}));
  t.push_back(soil_term("periodic", "Periodic domain axes; sph/domain_box.h.",
                        "any run.periodic axis", any_periodic));
  t.push_back(
      soil_term("surface_loads", "Surface loads ([[soil.loads]]); soil_solver/surface_loads.h.",
                "any [[soil.loads]]", [](const Scene& s) { return !soil(s).loads.empty(); }));
}

void add_interaction_terms(std::vector<TermSpec>& t) {
  const std::string m = "soil.materials[].";
  const auto both = [](const Scene& s) { return s.water.has_value() && s.soil.has_value(); };
  const auto any_seepage = [](const Scene& s) { return any_material(s, seeps); };
  const auto law = [](std::string name) {
    return [name](const Scene& s) {
      return any_material(s, [&name](const SoilMaterial& x) { return x.seepage == name; });
    };
  };
  t.push_back(term("interaction", "saturation",
                   "Overlap of water and soil particles: saturation and porosity at the water "
                   "particles (eq. 17); coupler/interaction/.",
                   "water and soil", both));
  t.push_back(term("interaction", "submerged_density",
                   "Buoyancy: submerged soil weighs rho_sat - rho_w (eq. 16); "
                   "porous/submerged_density.h.",
                   "water and soil", both));
  t.push_back(term("interaction", "seepage_force",
                   "Pairwise seepage force between water and soil (eq. 13); "
                   "coupler/interaction/seepage_force.h.",
                   "a material with seepage != \"none\"", any_seepage));
  std::vector<std::string> law_names;
  for (const porous::SeepageLawSpec& spec : porous::seepage_laws()) {  // one term per law
    law_names.push_back(spec.name);
    t.push_back(term("interaction", "seepage_" + spec.name,
                     spec.summary + " porous/seepage_laws.h.",
                     "a material with seepage = \"" + spec.name + "\"", law(spec.name)));
  }
  t.push_back(term(
      "interaction", "variable_permeability",
      "Seepage coefficients follow each particle's porosity (eq. 18-20); "
      "porous/permeability.h, porosity.h.",
      "a seeping material with variable_permeability = true",
      [](const Scene& s) {
        return any_material(
            s, [](const SoilMaterial& x) { return seeps(x) && x.variable_permeability; });
      },
      {Key(m + "variable_permeability", T::Bool)
           .fallback("true")
           .only_when("seepage", law_names)
           .doc("The seepage coefficients follow the current porosity of each particle (eq. 20); "
                "false: they keep their value at n0.")}));
  t.push_back(term("interaction", "wet_marking",
                   "Marks soil particles the water has reached (for wet_cohesion_loss).",
                   "a material with wet_cohesion_loss = true", [](const Scene& s) {
                     return any_material(s,
                                         [](const SoilMaterial& x) { return x.wet_cohesion_loss; });
                   }));
  t.push_back(term(
      "interaction", "fixed_bed",
      "A rigid porous bed whose particles never move; water still seeps through.",
      "a material with fixed = true",
      [](const Scene& s) { return any_material(s, [](const SoilMaterial& x) { return x.fixed; }); },
      {Key(m + "fixed", T::Bool)
           .fallback("false")
           .doc("A rigid porous bed: its particles never move (water still seeps "
                "through).")}));
  t.push_back(term("interaction", "wall_renormalised_drag",
                   "The drag and porosity sums of a water particle in soil beside a wall, "
                   "divided by the share of its support outside the walls; "
                   "coupler/interaction/wall_kernel_share.h.",
                   "seepage and coupling.drag_at_walls = \"renormalised\"", [](const Scene& s) {
                     return any_material(s, seeps) && s.coupling.drag_at_walls == "renormalised";
                   }));
  t.push_back(term("interaction", "implicit_drag",
                   "The drag's rate goes to the solvers, which integrate it implicitly "
                   "(docs/coupling.md).",
                   "seepage and coupling.implicit_drag = true", [](const Scene& s) {
                     return any_material(s, seeps) && s.coupling.implicit_drag;
                   }));
}

}  // namespace porosph::scene::term_detail
