#include "coupler/interaction/soil_water_interaction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "coupler/interaction/soil_water_sums.h"
#include "scene/choice.h"
#include "scene/term_registry.h"
#include "sph/geometry.h"
#include "sph/kernel_choice.h"
#include "sph/wall_occluders.h"

namespace porosph::coupler {

namespace {

/// Standard gravity [m/s^2], used for the seepage coefficients of a scene without gravity: with
/// Kozeny-Carman and Den Adel the products gamma_w a and gamma_w b do not depend on g, so any
/// g > 0 gives the same force; a hydraulic conductivity is by convention measured under it.
constexpr double kStandardGravity = 9.80665;

InteractionParameters parameters_from_scene(const scene::Scene& s) {
  const scene::WaterPhase& water = *s.water;
  double g2 = 0.0;
  for (double g : s.run.gravity) g2 += g * g;
  const double gravity = g2 > 0.0 ? std::sqrt(g2) : kStandardGravity;
  const double nu = water.viscosity / water.rho0;
  InteractionParameters p;
  p.h = s.h();
  p.c_a = s.run.c_a;
  p.unit_weight_water = water.rho0 * gravity;
  p.submerged_saturation = s.coupling.submerged_saturation;
  p.implicit_drag = s.coupling.implicit_drag;
  p.drag_step = scene::checked_choice("coupling.drag_step", s.coupling.drag_step,
                                      {"backward_euler", "exponential"}) == "exponential"
                    ? DragStep::kExponential
                    : DragStep::kBackwardEuler;
  if (s.coupling.drag_at_walls != "truncated" && s.coupling.drag_at_walls != "renormalised") {
    throw std::invalid_argument(
        "coupling.drag_at_walls: expected \"truncated\" or "
        "\"renormalised\", got \"" +
        s.coupling.drag_at_walls + "\"");
  }
  for (const scene::SoilMaterial& m : s.soil->materials) {
    SoilMaterialTerms terms;
    terms.law = porous::SeepageLaw::from_material(m, gravity, nu);
    if (!(m.density > 0.0)) {
      throw std::invalid_argument("soil material '" + m.name + "': density must be > 0");
    }
    terms.submerged_ratio = porous::submerged_density_ratio(m, water.rho0);
    terms.fixed = m.fixed;
    p.materials.push_back(terms);
  }
  return p;
}

/// The fixed wall particles (n x D, flattened) of the walls that hold neither water nor soil:
/// those acting on water, less the particles of a wall the soil passes through that lie in a soil
/// block (there is soil there); moving walls are left out (wall_kernel_share.h). A thin wall of
/// `thin` is filled on both sides as in the water solver, `tags` its side tags (0: other walls).
template <int D>
std::vector<double> wall_points_without_soil(const scene::Scene& s, const sph::ThinWallSet<D>& thin,
                                             std::vector<std::int32_t>& tags) {
  std::vector<double> points;
  const std::vector<scene::Shape> walls = s.walls_acting_on("water");
  std::vector<sph::Vec<D>> fill;
  std::vector<std::int32_t> side;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    const scene::Shape& wall = walls[j];
    if (!wall.moves_with.empty()) continue;
    const bool cuts_soil = wall.phases.empty() || std::find(wall.phases.begin(), wall.phases.end(),
                                                            "soil") != wall.phases.end();
    thin.fill(j, wall, s.h(), s.run.dp, fill, side);
    for (std::size_t i = 0; i < fill.size(); ++i) {
      const sph::Vec<D>& x = fill[i];
      bool soil_there = false;
      for (std::size_t b = 0; b < s.soil->blocks.size() && !cuts_soil && !soil_there; ++b)
        soil_there = sph::inside_shape<D>(s.soil->blocks[b], x, s.run.dp);
      if (soil_there) continue;
      points.insert(points.end(), x.data(), x.data() + D);
      tags.push_back(side[i]);
    }
  }
  return points;
}

template <int D>
std::unique_ptr<InteractionEngine> make_engine(const scene::Scene& s, int threads) {
  InteractionParameters p = parameters_from_scene(s);
  p.threads = threads;
  // The water solver's thin walls (sph/wall_occluders.h): no soil-water pair across them.
  sph::ThinWallSet<D> thin = sph::thin_walls_of<D>(s, s.walls_acting_on("water"), "water",
                                                   s.water->thin_walls == "separating");
  std::vector<std::int32_t> wall_tags;
  if (s.coupling.drag_at_walls == "renormalised") {  // wall_kernel_share.h
    p.soil_wall_points = wall_points_without_soil<D>(s, thin, wall_tags);
    p.soil_wall_volume = std::pow(s.run.dp, D);
  }
  const sph::DomainBox<D> box = sph::DomainBox<D>::from_scene(s, 2.0 * s.h());
  const sph::KernelChoice<D> choice(s.run.kernel, s.h(), s.run.dp,
                                    s.run.kernel_gradient != "plain");
  return choice.visit([&](const auto& kernel) -> std::unique_ptr<InteractionEngine> {
    using Kernel = std::decay_t<decltype(kernel)>;
    return std::make_unique<SoilWaterSums<D, Kernel>>(std::move(p), box, thin.occluders,
                                                      std::move(wall_tags));
  });
}

}  // namespace

SoilWaterInteraction::SoilWaterInteraction(const scene::Scene& scene, int threads)
    : dimension_(scene.run.dimension) {
  if (!scene.has_water() || !scene.has_soil()) {
    throw std::invalid_argument("soil-water interaction: the scene needs both water and soil");
  }
  if (dimension_ == 2) {
    engine_ = make_engine<2>(scene, threads);
  } else if (dimension_ == 3) {
    engine_ = make_engine<3>(scene, threads);
  } else {
    throw std::invalid_argument("soil-water interaction: run.dimension must be 2 or 3");
  }
  damping_ = sph::DampingStage::from_scene(scene);
  implicit_drag_ = scene.coupling.implicit_drag;
  material_count_ = scene.soil->materials.size();
  terms_ = scene::active_terms(scene, "interaction");
  out_.force_on_water.assign(dimension_, 0.0);
  out_.force_on_soil.assign(dimension_, 0.0);
}

SoilWaterInteraction::~SoilWaterInteraction() = default;

void SoilWaterInteraction::check_sizes(const coupling::StepState& state, const char* phase,
                                       bool soil) const {
  const std::size_t n = state.overlap_id.size(), d = static_cast<std::size_t>(dimension_);
  auto expect = [&](std::size_t size, std::size_t expected, const char* what) {
    if (size == expected) return;
    throw std::runtime_error(std::string("the ") + phase + " solver sent " + std::to_string(size) +
                             " " + what + " values for " + std::to_string(n) +
                             " overlap particles (expected " + std::to_string(expected) + ")");
  };
  expect(state.overlap_position.size(), n * d, "overlap_position");
  expect(state.overlap_velocity.size(), n * d, "overlap_velocity");
  expect(state.overlap_density.size(), n, "overlap_density");
  expect(state.overlap_mass.size(), n, "overlap_mass");
  if (!soil) return;
  expect(state.overlap_porosity.size(), n, "overlap_porosity");
  expect(state.overlap_material.size(), n, "overlap_material");
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t m = state.overlap_material[i];
    if (m < 0 || static_cast<std::size_t>(m) >= material_count_) {
      throw std::runtime_error("the soil solver sent material index " + std::to_string(m) +
                               " for overlap particle " + std::to_string(state.overlap_id[i]) +
                               "; the scene has " + std::to_string(material_count_) +
                               " soil materials");
    }
  }
}

InteractionSummary SoilWaterInteraction::compute(const coupling::StepState& water,
                                                 const coupling::StepState& soil, double time) {
  check_sizes(water, "water", false);
  check_sizes(soil, "soil", true);
  out_.force_on_water.assign(dimension_, 0.0);
  out_.force_on_soil.assign(dimension_, 0.0);
  out_.force_magnitude_sum = 0.0;
  forces_ = false;
  if (water.overlap_id.empty() || soil.overlap_id.empty()) {
    out_.water_acceleration.clear();
    out_.soil_acceleration.clear();
    out_.saturation.clear();
    out_.water_porosity.clear();
    out_.water_rate.clear();
    out_.soil_rate.clear();
    return {};
  }
  forces_ = !damping_.active(time);  // sph/damping_stage.h
  return engine_->compute(water, soil, forces_, out_);
}

void SoilWaterInteraction::finish_step(const coupling::StepState& water,
                                       const coupling::StepState& soil, double dt) {
  out_.explicit_force_on_water = out_.force_on_water;
  out_.explicit_force_on_soil = out_.force_on_soil;
  if (!forces_ || !implicit_drag_ || !(dt > 0.0)) return;
  engine_->implicit_drag(water, soil, dt, out_);
}

}  // namespace porosph::coupler
