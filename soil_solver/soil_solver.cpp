#include "soil_solver/soil_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "porous/porosity.h"
#include "soil_solver/initial_stress.h"
#include "soil_solver/soil_output.h"
#include "soil_solver/soil_rates.h"
#include "soil_solver/soil_walls.h"
#include "soil_solver/straight_walls.h"
#include "soil_solver/stress_filter.h"
#include "soil_solver/stress_update.h"
#include "soil_solver/wall_normals.h"
#include "sph/geometry.h"
#include "sph/lattice_gradient.h"
#include "sph/overlap_scatter.h"
#include "sph/particle_removal.h"
#include "sph/wall_occluders.h"

namespace porosph::soil {
namespace {

/// Free soil particles are re-sorted by cell this often (steps), for memory locality.

}  // namespace

template <int D>
SoilSolver<D>::SoilSolver(const scene::Scene& s)
    : Core(scene::active_terms(s, "soil")),
      params_(SoilParams<D>::from_scene(s)),
      damping_(params_.damping_duration),
      box_(sph::DomainBox<D>::from_scene(s, 2.0 * params_.h)),
      kernel_(s.run.kernel, params_.h, s.run.dp, s.run.kernel_gradient != "plain"),
      loads_(*s.soil) {
  using Vec = sph::Vec<D>;
  for (const auto& o : s.observables)
    if (o.phase == "soil") observables_.push_back(sph::prepare_observable<D>(o));

  struct NewParticle {
    Vec x;
    std::int64_t material;
    double remove_at;
    bool no_slip;
    Vec normal;
    std::int32_t side = 0;  ///< thin walls: sph::wall_side_tag
  };
  std::vector<NewParticle> free, fixed;
  const double dp = params_.dp;
  const std::vector<scene::Shape> walls = s.walls_acting_on("soil");
  const std::vector<scene::Shape>& blocks = s.soil->blocks;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const int material = s.soil->material_index(blocks[b].material);
    if (material < 0) {
      throw std::invalid_argument("soil block '" + blocks[b].label + "': unknown material '" +
                                  blocks[b].material + "'");
    }
    for (const Vec& x : sph::fill_block_outside_walls<D>(blocks[b], walls, dp)) {
      Vec wrapped = x;
      box_.wrap(wrapped);
      if (box_.outside(x) || wrapped != x) continue;
      bool taken = false;  // an earlier block holds this lattice point
      for (std::size_t e = 0; e < b && !taken; ++e) taken = sph::inside_shape<D>(blocks[e], x, dp);
      if (taken) continue;
      const bool rigid = params_.materials[material].fixed;
      const Vec unknown = Vec::Constant(std::nan(""));  // fixed soil: normal from the soil around
      (rigid ? fixed : free).push_back({x, material, -1.0, params_.no_slip, unknown});
    }
  }
  int wall_reach = 2;  // probe past the thickest wall
  for (const auto& wall : walls) wall_reach = std::max(wall_reach, wall.layers + 2);
  sph::ThinWallSet<D> thin = sph::thin_walls_of<D>(s, walls, "soil", params_.two_sided_thin_walls);
  std::vector<Vec> points;
  std::vector<std::int32_t> sides;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    const scene::Shape& wall = walls[j];
    const bool no_slip =
        wall.condition == "default" ? params_.no_slip : wall.condition == "no_slip";
    thin.fill(j, wall, params_.h, dp, points, sides);
    const int axis = thin.axis_of_wall[j];
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec& x = points[i];
      Vec wrapped = x;
      box_.wrap(wrapped);
      if (wrapped != x) continue;
      Vec normal = Vec::Zero();  // a thin wall's side: out of the wall into that side
      if (sides[i] != 0) {
        normal[axis] = sides[i] > 0 ? 1.0 : -1.0;
      } else {
        normal = wall_normal_from_geometry<D>(x, walls, dp, wall_reach);
      }
      fixed.push_back({x, -1, wall.remove_at, no_slip, normal, sides[i]});
      if (wall.remove_at >= 0.0 &&
          (scalars_.next_wall_removal < 0.0 || wall.remove_at < scalars_.next_wall_removal))
        scalars_.next_wall_removal = wall.remove_at;
    }
  }
  SoilParticles<D>& P = particles_;
  const std::size_t n = free.size() + fixed.size();
  P.n_free = free.size();
  P.for_each_array([n](auto& array) { array.resize(n); });
  // Walls take the density of the first material until free soil reaches them.
  const double wall_density = params_.materials.empty() ? 1000.0 : params_.materials[0].density;
  for (std::size_t i = 0; i < n; ++i) {
    const NewParticle& q = i < P.n_free ? free[i] : fixed[i - P.n_free];
    P.position[i] = q.x;
    P.velocity[i] = P.acceleration[i] = P.interaction[i] = Vec::Zero();
    P.wall_velocity[i] = P.displacement[i] = Vec::Zero();
    P.wall_normal[i] = q.normal;
    P.stress[i] = P.velocity_gradient[i] = P.artificial_stress[i] = Eigen::Matrix3d::Zero();
    const double rho = q.material >= 0 ? params_.materials[q.material].density : wall_density;
    P.density[i] = P.reference_density[i] = rho;
    P.density_rate[i] = 0.0;
    P.mass[i] = rho * params_.volume;
    P.porosity[i] = q.material >= 0 ? params_.materials[q.material].porosity : 0.0;
    P.plastic_strain[i] = 0.0;
    P.saturation[i] = 0.0;
    P.weight_ratio[i] = 1.0;
    P.wet[i] = 0;
    P.remove_at[i] = q.remove_at;
    P.id[i] = static_cast<std::int64_t>(i);
    P.material[i] = q.material;
    P.fixed[i] = i < P.n_free ? 0 : 1;
    P.no_slip[i] = q.no_slip ? 1 : 0;
    P.wall_side[i] = q.side;
  }
  const int kernel_reach = static_cast<int>(std::ceil(2.0 * params_.h / dp - 1e-9));
  P.straight_wall = straight_wall_interior<D>(P.position, P.wall_normal, P.remove_at, P.n_free, dp,
                                              kernel_reach, box_);
  // Thin walls filled on both sides (soil.thin_walls): the list leaves out the pairs they hide.
  neighbours_.set_occluders(std::move(thin.occluders));
  if (s.water) mark_initially_submerged<D>(s.water->blocks, params_, P);
  if (params_.geostatic_initial) apply_geostatic_stress<D>(params_, P);
  loads_.tag(P, params_.dp, params_.materials);
  cell_order_.reorder(neighbours_, particles_, box_, /*sort_fixed=*/false, overlap_index_);
}

template <int D>
void SoilSolver<D>::compute_rates() {
  cell_order_.refresh(neighbours_, particles_, box_, scalars_.step, overlap_index_);
  scalars_.neighbours_per_particle = neighbours_.neighbours_per_free_particle();
  kernel_.visit([this](const auto& kernel) { compute_rates_with(kernel); });
}

template <int D>
template <class Kernel>
void SoilSolver<D>::compute_rates_with(const Kernel& kernel) {
  const int every = params_.stress_filter_every;
  if (every > 0 && scalars_.step > 0 && scalars_.step % static_cast<std::uint64_t>(every) == 0)
    filter_soil_stress(params_.stress_filter, neighbours_, kernel, params_, particles_,
                       filter_scratch_);
  update_soil_wall_state(neighbours_, kernel, params_, particles_, wall_gradient_scratch_);
  if (params_.any_artificial_stress()) update_artificial_stress(params_, particles_);
  const SoilRateSummary r = compute_soil_rates(neighbours_, kernel, params_, particles_);
  const double max_acceleration =
      std::max(r.max_total_acceleration, loads_.apply(scalars_.time, particles_, &load_force_));
  // The weight ratios these rates used (the books' inertia_switch, soil_impulse_book.h).
  rates_weight_ratio_.assign(particles_.weight_ratio.begin(),
                             particles_.weight_ratio.begin() + particles_.n_free);
  scalars_.limits = sph::time_step_limits(params_.h, params_.sound_speed, r.max_speed, 0.0,
                                          max_acceleration, params_.cfl, 0.125, params_.c_a);
}

template <int D>
double SoilSolver<D>::evaluate(const sph::PreparedObservable<D>& o,
                               const sph::ParticleView<D>& view) const {
  if (o.kind == sph::PreparedObservable<D>::Kind::LoadVelocity)
    return loads_.velocity(o.load, particles_);
  return kernel_.visit(
      [&o, &view](const auto& kernel) { return sph::evaluate_observable(o, view, kernel); });
}

template <int D>
void SoilSolver<D>::fill_state(coupling::StepState& out, const std::vector<double>& overlap_min,
                               const std::vector<double>& overlap_max) {
  const SoilParticles<D>& P = particles_;
  out.step = scalars_.step;
  out.time = scalars_.time;
  fill_soil_overlap(P, params_.volume, overlap_min, overlap_max, overlap_index_, out);
  fill_soil_diagnostics(P, out.region_min, out.region_max, out.diagnostics);
  // Reported before its rates are computed (solver_runtime.h): the CFL limit of the current
  // speeds, eq. 21 of the latest rates.
  scalars_.limits.cfl =
      sph::cfl_limit(params_.cfl, params_.h, params_.sound_speed, out.diagnostics.max_speed);
  out.dt_cfl = scalars_.limits.cfl;
  out.dt_viscous = scalars_.limits.viscous;
  out.dt_force = scalars_.limits.force;
  out.dt_limit = scalars_.limits.min();
  out.diagnostics.removed_count = scalars_.removed_count;
  out.diagnostics.outflow_mass = scalars_.outflow_mass;
  out.diagnostics.neighbours_per_particle = scalars_.neighbours_per_particle;
  book_.flatten(out.diagnostics.external_impulse);  // of the last advance (soil_impulse_book.h)
  const sph::Vec<D> pi = effective_momentum(P, 0, P.n_free);
  out.diagnostics.balance_momentum.assign(pi.data(), pi.data() + D);
  sph::ParticleView<D> view{P.position.data(), P.velocity.data(), P.mass.data(), nullptr, P.n_free};
  view.density = P.density.data();
  view.porosity = P.porosity.data();
  view.stress = P.stress.data();
  view.displacement = P.displacement.data();
  for (const auto& o : observables_) out.diagnostics.observables[o.name] = evaluate(o, view);
}

template <int D>
void SoilSolver<D>::add_interaction(const std::vector<double>& acceleration) {
  fixed_interaction_.clear();
  // Fixed soil exchanges drag but never moves: its share is only booked.
  this->scatter_interaction(acceleration, particles_.n_free,
                            [this](std::int32_t index, const sph::Vec<D>& a) {
                              fixed_interaction_.emplace_back(index, a);
                            });
}

template <int D>
void SoilSolver<D>::set_saturation(const std::vector<double>& saturation) {
  SoilParticles<D>& P = particles_;
  if (!saturation.empty() && saturation.size() != overlap_index_.size()) {
    throw std::invalid_argument("set_saturation: expected " +
                                std::to_string(overlap_index_.size()) + " values, got " +
                                std::to_string(saturation.size()));
  }
  if (saturation.empty() && !saturation_set_) return;  // never near water: nothing to reset
  saturation_set_ = !saturation.empty();
  std::fill(P.saturation.begin(), P.saturation.end(), 0.0);  // far from the water: dry
  std::fill(P.weight_ratio.begin(), P.weight_ratio.end(), 1.0);
  for (std::size_t k = 0; k < saturation.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(overlap_index_[k]);
    const SoilMaterialConstants& m = params_.materials[P.material[i]];
    P.saturation[i] = saturation[k];
    if (saturation[k] >= params_.submerged_saturation) P.weight_ratio[i] = m.submerged_ratio;
    if (saturation[k] >= params_.wet_saturation) P.wet[i] = 1;
  }
}

template <int D>
void SoilSolver<D>::advance(double dt) {
  SoilParticles<D>& P = particles_;
  if (this->drop_stale_interaction()) fixed_interaction_.clear();
  const bool damping = damping_.active(scalars_.time);  // sph/damping_stage.h
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  const double inv_h2 = 1.0 / (params_.h * params_.h);
  // Dynamic relaxation: a -= D v, D = coefficient sqrt(E / (rho h^2)) during the stage.
  const auto damping_rate = [&](std::int64_t i) {
    if (!damping) return 0.0;
    const auto& m = params_.materials[P.material[i]];
    return params_.damping_coefficient * std::sqrt(m.young * inv_h2 / P.density[i]);
  };
  book_.clear();
  book_soil_kick(P, rates_weight_ratio_, params_.gravity, dt, damping_rate, book_);
  book_fixed_soil(P, fixed_interaction_, dt, params_.volume, book_);
  book_[kSoilLoads] += dt * load_force_;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {  // kick
    sph::Vec<D> a = P.acceleration[i] + P.interaction[i];
    if (damping) a -= damping_rate(i) * P.velocity[i];
    // The interaction already holds the coupler's pairwise implicit drag over dt: explicit here.
    P.velocity[i] += dt * a;
  }
  loads_.make_rigid(P);  // rigid plates move as one along their axis (surface_loads.h)
  // Strain rate, spin and drho/dt from the new velocities at the old positions (the neighbour
  // list of this step is still exact), then the stress update.
  kernel_.visit(
      [this, &P](const auto& kernel) { compute_soil_kinematics(neighbours_, kernel, params_, P); });
  update_stresses(dt);
  sph::FirstCrossing<D> crossing;  // a free particle carried across a thin wall
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {  // drift
    const sph::Vec<D> before = P.position[i];
    P.position[i] += dt * P.velocity[i];
    if (const int wall = this->crossed_occluder_by(i, before); wall >= 0)
      crossing.offer(i, wall, before, P.position[i]);
    P.displacement[i] += dt * P.velocity[i];
    P.density[i] += dt * P.density_rate[i];
    const SoilMaterialConstants& m = params_.materials[P.material[i]];
    P.porosity[i] = porous::porosity_from_density(m.porosity, P.reference_density[i], P.density[i]);
    box_.wrap(P.position[i]);
  }
  this->record_crossing("soil", crossing);
  scalars_.time += dt;
  ++scalars_.step;
  if (damping_.release(scalars_.time)) {  // the end of the damping stage
    book_[kSoilDamping] -= effective_momentum(P, 0, P.n_free);
    for (std::int64_t i = 0; i < n; ++i) P.velocity[i].setZero();
  }
  remove_particles_outside();
  this->remove_expired_walls();
}

template <int D>
void SoilSolver<D>::update_stresses(double dt) {
  SoilParticles<D>& P = particles_;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const SoilMaterialConstants& m = params_.materials[P.material[i]];
    const Material& model = m.current_model(P.wet[i] != 0);
    const Eigen::Matrix3d& grad_v = P.velocity_gradient[i];
    PlasticState plastic{P.plastic_strain[i], false};
    const Eigen::Matrix3d d = strain_rate(grad_v), w = spin(grad_v);
    P.stress[i] = params_.modified_euler_stress
                      ? update_stress_modified_euler(model, P.stress[i], d, w, dt, plastic)
                      : update_stress(model, P.stress[i], d, w, dt, plastic);
    P.plastic_strain[i] = plastic.plastic_multiplier;
  }
}

template <int D>
void SoilSolver<D>::remove_particles_outside() {
  const SoilParticles<D>& P = particles_;
  const auto outside = [this](std::size_t i) { return box_.outside(particles_.position[i]); };
  const auto removing = [this, &P](std::size_t i) {  // its momentum leaves with it
    book_[kSoilOutflow] -= (P.weight_ratio[i] * P.mass[i]) * P.velocity[i];
  };
  this->remove_free_particles_where(outside, removing);
}

template <int D>
std::optional<std::string> SoilSolver<D>::find_non_finite(std::int64_t* particle_id) const {
  if (auto crossing = this->crossing_problem(particle_id)) return crossing;
  return find_non_finite_soil(particles_, scalars_.step, scalars_.time, particle_id);
}

template <int D>
std::vector<io::FieldView> SoilSolver<D>::snapshot_fields() const {
  return soil_snapshot_fields(particles_);
}

template class SoilSolver<2>;
template class SoilSolver<3>;

}  // namespace porosph::soil
