// The water phase's terms (scene/term_registry.h): one registration per term, with the keys it
// owns and its switch. The solver's code for each term is named in its summary.
#include <algorithm>

#include "scene/scene_schema_builder.h"
#include "scene/term_registry.h"
#include "scene/thin_walls.h"

namespace porosph::scene::term_detail {
namespace {

using schema_detail::Key;
using schema_detail::T;

const WaterPhase& water(const Scene& s) { return *s.water; }
bool has_water_walls(const Scene& s) { return !s.walls_acting_on("water").empty(); }
bool artificial_on(const Scene& s) { return water(s).alpha > 0.0 || water(s).beta > 0.0; }
bool no_slip(const Scene& s) { return water(s).wall_condition == "no_slip"; }
/// The Monaghan term acts at no-slip walls in this mode (fluid_solver/wall_normal_damping.h).
bool wall_artificial_viscosity_is(const Scene& s, const char* mode) {
  return artificial_on(s) && has_water_walls(s) && no_slip(s) &&
         water(s).artificial_viscosity_at_walls == mode;
}
bool any_reservoir(const Scene& s, bool open) {
  const auto& r = water(s).reservoirs;
  return std::any_of(r.begin(), r.end(),
                     [open](const ReservoirZone& z) { return (z.boundary == "open") == open; });
}

TermSpec term(std::string name, std::string summary, std::string runs_when,
              std::function<bool(const Scene&)> active, std::vector<KeySpec> keys = {}) {
  return {std::move(name),      "water",         std::move(summary),
          std::move(runs_when), std::move(keys), std::move(active)};
}

bool always(const Scene&) { return true; }

/// One law of the laminar viscosity family: term `<law>_viscosity`, on where water.viscosity > 0
/// and water.laminar_viscosity = law (its code: fluid_solver/laminar_viscosity.h).
TermSpec laminar_viscosity_law(const std::string& law, std::string summary,
                               std::vector<KeySpec> keys = {}) {
  TermSpec spec = term(
      law + "_viscosity", std::move(summary),
      "water.viscosity > 0 and water.laminar_viscosity = \"" + law + "\"",
      [law](const Scene& s) {
        return water(s).viscosity > 0.0 && water(s).laminar_viscosity == law;
      },
      std::move(keys));
  spec.choice = TermChoice{"water.laminar_viscosity", law};
  return spec;
}

}  // namespace

bool any_periodic(const Scene& s) {
  return std::find(s.run.periodic.begin(), s.run.periodic.end(), true) != s.run.periodic.end();
}

namespace {}  // namespace

void add_water_terms(std::vector<TermSpec>& t) {
  t.push_back(term("continuity",
                   "Continuity equation of weakly compressible water (seed paper eq. 2); "
                   "fluid_solver/continuity.h.",
                   "always", always));
  t.push_back(term("pressure_gradient",
                   "Symmetric pressure gradient of the momentum equation (eq. 3) with the Tait "
                   "equation of state (eq. 4); fluid_solver/pressure_force.h, "
                   "equation_of_state.h.",
                   "always", always));
  t.push_back(term("gravity", "Body force run.gravity.", "always", always));
  // The laminar viscosity laws (fluid_solver/laminar_viscosity.h): the first owns the keys, each
  // is one value of water.laminar_viscosity.
  t.push_back(laminar_viscosity_law(
      "morris",
      "Laminar viscous term of Morris, Fox & Zhu (1997), J. Comput. Phys. 136, eq. 8: "
      "m_b (mu_a + mu_b) / (rho_a rho_b) x_ab.grad W / (r^2 + eta^2) v_ab; "
      "fluid_solver/laminar_viscosity.h, viscosity_morris.h.",
      {Key("water.viscosity", T::Float)
           .unit("Pa s")
           .fallback("0.001")
           .at_least(0)
           .doc("Dynamic viscosity mu of the laminar term (water.laminar_viscosity); 0 switches "
                "it off."),
       Key("water.laminar_viscosity", T::String)
           .fallback("\"morris\"")
           .doc("The laminar viscosity law (docs/terms.md): \"morris\" (Morris et al. 1997) or "
                "another registered law.")}));
  t.push_back(laminar_viscosity_law(
      "lo_shao",
      "Laminar viscous term of Lo & Shao (2002), Appl. Ocean Res. 24, 275-286: m_b 4 nu0 / "
      "(rho_a + rho_b) x_ab.grad W / (r^2 + eta^2) v_ab, nu0 = mu / rho0 (DualSPHysics' "
      "laminar term); fluid_solver/laminar_viscosity.h."));
  t.push_back(term("artificial_viscosity",
                   "Monaghan (1992) artificial viscosity between water particles; "
                   "fluid_solver/artificial_viscosity.h.",
                   "water.alpha > 0 or water.beta > 0", artificial_on,
                   {Key("water.alpha", T::Float)
                        .fallback("0.05")
                        .at_least(0)
                        .doc("Monaghan artificial viscosity alpha; 0 switches it off."),
                    Key("water.beta", T::Float)
                        .fallback("0.0")
                        .at_least(0)
                        .doc("Monaghan artificial viscosity beta.")}));
  t.push_back(term(
      "artificial_viscosity_drag_limited",
      "The artificial viscosity yields to the seepage drag inside soil, by the "
      "share min(1, lambda / r_av); fluid_solver/artificial_viscosity.h.",
      "water.alpha > 0 and water.artificial_viscosity_in_soil = \"drag_limited\"",
      [](const Scene& s) {
        return water(s).alpha > 0.0 && water(s).artificial_viscosity_in_soil == "drag_limited";
      },
      {Key("water.artificial_viscosity_in_soil", T::String)
           .fallback("\"drag_limited\"")
           .one_of({"drag_limited", "drag_replaced", "full"})
           .doc("The artificial viscosity inside soil. \"drag_limited\": the share "
                "min(1, lambda / r_av) of it is removed at a water particle whose seepage drag "
                "rate lambda (from the coupler) approaches the rate r_av = alpha c pi^2 / "
                "(2 (D + 2) h) at which it damps kernel-scale noise, so the noise is damped at "
                "least as fast as without soil and a Darcy flow feels no artificial viscosity "
                "(fluid_solver/artificial_viscosity.h); since r_av grows as h falls, more of it "
                "stays on at finer dp. \"drag_replaced\": the drag replaces it wherever it "
                "holds the water, with the weight min(1, lambda / (0.5 lambda_max)) over the "
                "neighbours (fluid_solver/drag_weight.h): off inside soil at every dp, for "
                "Darcy flows in sand, where lambda is well above r_av; \"full\": everywhere as "
                "in free water (the discharge under the seepage weir 2 % lower at dp 10 mm).")}));
  t.push_back(term(
      "artificial_viscosity_drag_replaced",
      "The artificial viscosity yields to the seepage drag inside soil by the drag weight "
      "min(1, lambda / (0.5 lambda_max)): off inside soil; fluid_solver/drag_weight.h.",
      "water.alpha > 0 and water.artificial_viscosity_in_soil = \"drag_replaced\"",
      [](const Scene& s) {
        return water(s).alpha > 0.0 && water(s).artificial_viscosity_in_soil == "drag_replaced";
      },
      {}));
  t.push_back(term(
      "artificial_viscosity_at_walls",
      "The artificial viscosity between water and no-slip wall particles on the whole mirrored "
      "velocity difference: also a wall friction that shrinks with h; "
      "fluid_solver/wall_normal_damping.h.",
      "artificial_viscosity, walls acting on water, water.wall_condition = \"no_slip\" and "
      "water.artificial_viscosity_at_walls = \"full\"",
      [](const Scene& s) { return wall_artificial_viscosity_is(s, "full"); },
      {Key("water.artificial_viscosity_at_walls", T::String)
           .fallback("\"normal\"")
           .one_of({"normal", "full", "none"})
           .doc("The Monaghan artificial viscosity between water and no-slip wall particles "
                "(fluid_solver/wall_normal_damping.h). \"normal\": on the wall-normal part of "
                "the velocity difference only, so it keeps water off a wall it approaches but "
                "does not brake a flow along it; the no-slip shear comes from the physical "
                "viscous term (water.viscosity, Adami et al. 2012). \"full\" (the default "
                "until 2026-12-07): on the whole mirrored velocity difference, which is also a "
                "wall friction of kinematic viscosity about alpha h c / 8, hundreds of times "
                "water's, that shrinks with h, so a flow along a wall does not converge under "
                "refinement (docs/validation-studies.md, dam break). \"none\": not at walls "
                "(a particle in the corner of a one-layer wall can then cross it).")}));
  t.push_back(
      term("artificial_viscosity_at_walls_normal",
           "The artificial viscosity between water and no-slip wall particles on the wall-normal "
           "approach only; fluid_solver/wall_normal_damping.h.",
           "artificial_viscosity, walls acting on water, water.wall_condition = \"no_slip\" and "
           "water.artificial_viscosity_at_walls = \"normal\"",
           [](const Scene& s) { return wall_artificial_viscosity_is(s, "normal"); }, {}));
  t.push_back(term(
      "pressure_gradient_hydrostatic_difference_in_soil",
      "Inside soil, the difference form of the departure from still water plus "
      "rho0 g where the drag holds the particles; "
      "fluid_solver/hydrostatic_difference.h.",
      "water.pressure_gradient_in_soil = \"hydrostatic_difference\"",
      [](const Scene& s) { return water(s).pressure_gradient_in_soil == "hydrostatic_difference"; },
      {Key("water.pressure_gradient_in_soil", T::String)
           .fallback("\"symmetric\"")
           .one_of({"symmetric", "hydrostatic_difference"})
           .doc("The pressure gradient of the water inside soil. \"symmetric\": the seed paper's "
                "form everywhere; \"hydrostatic_difference\": where the seepage drag holds the "
                "particles (inside soil, blended in over the soil's surface layer, where the drag "
                "rises to half the largest among a particle's neighbours) and the kernel "
                "support is full, the difference form of the departure from still water plus "
                "rho0 g, exact for still water at any particle arrangement, so that the Darcy flow "
                "does not pay for the lattice's strain (the vertical seepage is ~30 times as "
                "sensitive to the operator as the pressure) and the sand's water lattice does not "
                "collapse; water momentum is then not conserved pair by pair inside soil "
                "(fluid_solver/hydrostatic_difference.h, docs/coupling.md).")}));
  t.push_back(term(
      "density_diffusion",
      "Density diffusion of the continuity equation (Molteni & Colagrossi 2009; "
      "Antuono et al. 2010); fluid_solver/density_diffusion.h.",
      "water.density_diffusion > 0",
      [](const Scene& s) { return water(s).density_diffusion > 0.0; },
      {Key("water.density_diffusion", T::Float)
           .fallback("0.1")
           .at_least(0)
           .at_most(1)
           .doc("delta of the density diffusion term added to the continuity equation "
                "(Molteni & Colagrossi 2009), between water particles; 0 switches it "
                "off. 0.1 is the standard value."),

       Key("water.density_diffusion_correction", T::String)
           .fallback("\"linear\"")
           .one_of({"linear", "hydrostatic"})
           .doc("What the density diffusion leaves alone. \"hydrostatic\": still weakly "
                "compressible water (the departure of the EOS enthalpy from the gravity "
                "potential is diffused; fluid_solver/density_diffusion.h); \"linear\": any "
                "linear departure as well, a steady seepage flow included (Antuono et al. 2010, "
                "with a renormalised gradient; one more neighbour pass). With \"hydrostatic\" "
                "the diffusion carries part of a seepage discharge: the water in a fluidised bed "
                "moved 2.5 % slower than Q / A.")}));
  t.push_back(
      term("particle_shifting",
           "Fickian particle shifting (Lind et al. 2012; Sun et al. 2017); "
           "fluid_solver/particle_shifting.h.",
           "water.particle_shifting > 0",
           [](const Scene& s) { return water(s).particle_shifting > 0.0; },
           {Key("water.particle_shifting", T::Float)
                .fallback("0.0")
                .at_least(0)
                .doc("A of the Fickian particle shifting of Lind et al. (2012) with the "
                     "speed scale of Sun et al. (2017): after each step a water particle "
                     "moves by -A h U_max dt grad C (C the particle concentration, with "
                     "Monaghan's tensile term, U_max the largest water speed), velocity "
                     "unchanged; the continuity equation sees the shift, so the density follows "
                     "the particles' volume (fluid_solver/particle_shifting.h); keeps the "
                     "particles uniform in strained flows; 0 switches it off. No "
                     "free-surface treatment: confined or periodic water only.")}));
  t.push_back(term("walls_no_slip",
                   "Wall particles (Adami, Hu & Adams 2012): extrapolated pressure, mirrored "
                   "velocity in the viscous terms; fluid_solver/wall_boundary.h.",
                   "walls acting on water and water.wall_condition = \"no_slip\"",
                   [](const Scene& s) { return has_water_walls(s) && no_slip(s); },
                   {Key("water.wall_condition", T::String)
                        .fallback("\"no_slip\"")
                        .one_of({"no_slip", "free_slip"})
                        .doc("Velocity condition at wall particles.")}));
  t.push_back(term("walls_free_slip",
                   "Wall particles with extrapolated pressure, left out of the viscous terms; "
                   "fluid_solver/wall_boundary.h.",
                   "walls acting on water and water.wall_condition = \"free_slip\"",
                   [](const Scene& s) { return has_water_walls(s) && !no_slip(s); }));
  t.push_back(term(
      "thin_walls_two_sided",
      "Box walls too thin to part two bodies of water (fewer than 2 (ceil(2h / dp) - 1) "
      "layers, water within 2h of both faces) are filled once per side and hide every pair "
      "across their mid-plane; sph/wall_occluders.h.",
      "a thin wall (scene/thin_walls.h) acting on water and water.thin_walls = \"separating\"",
      [](const Scene& s) {
        return water(s).thin_walls == "separating" && has_thin_walls(s, "water");
      },
      {Key("water.thin_walls", T::String)
           .fallback("\"separating\"")
           .one_of({"separating", "shared"})
           .doc("Box walls acting on water that are thinner than 2m layers (m = ceil(2h / dp) "
                "- 1; 4 at h = 1.2 dp) with water within 2h of both faces. \"separating\": "
                "each side gets max(L, m) wall layers of its own from its face inwards, seen "
                "only from that side, and no pair of particles interacts across the wall's "
                "mid-plane, so the wall parts the water at any thickness (sph/wall_occluders.h); "
                "\"shared\": the wall's L layers, neighbours of the water on both sides, carry "
                "one side's pressure to the other and let water through under a head "
                "difference (coupler check warns).")}));
  t.push_back(term("shepard_density_filter",
                   "Shepard re-initialisation of the density; fluid_solver/density_filter.h.",
                   "water.density_filter_every > 0",
                   [](const Scene& s) { return water(s).density_filter_every > 0; },
                   {Key("water.density_filter_every", T::Int)
                        .fallback("0")
                        .at_least(0)
                        .doc("Shepard density re-initialisation every this many steps; 0: off.")}));
  t.push_back(term("inflow", "Inflow zones ([[water.inflow]]); fluid_solver/flow_zones.h.",
                   "any [[water.inflow]]",
                   [](const Scene& s) { return !water(s).inflows.empty(); }));
  t.push_back(term("outflow", "Outflow zones ([[water.outflow]]); fluid_solver/flow_zones.h.",
                   "any [[water.outflow]]",
                   [](const Scene& s) { return !water(s).outflows.empty(); }));
  t.push_back(term("reservoir",
                   "Constant-head reservoirs refilled at their surface; "
                   "fluid_solver/reservoirs.h.",
                   "any [[water.reservoir]] with boundary = \"surface\"",
                   [](const Scene& s) { return any_reservoir(s, false); }));
  t.push_back(term("open_reservoir",
                   "Constant-head reservoirs open across a face (buffer at the still-water "
                   "pressure of the level; Tafuni et al. 2018); fluid_solver/open_reservoirs.h.",
                   "any [[water.reservoir]] with boundary = \"open\"",
                   [](const Scene& s) { return any_reservoir(s, true); }));
  t.push_back(term("periodic", "Periodic domain axes; sph/domain_box.h.", "any run.periodic axis",
                   any_periodic));
  t.push_back(term("damping_stage_freeze",
                   "The water is frozen while the soil settles; sph/damping_stage.h.",
                   "soil.damping_duration > 0",
                   [](const Scene& s) { return s.soil && s.soil->damping_duration > 0.0; }));
}

}  // namespace porosph::scene::term_detail
