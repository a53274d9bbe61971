#include "fluid_solver/water_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fluid_solver/density_filter.h"
#include "fluid_solver/initial_particles.h"
#include "fluid_solver/wall_boundary.h"
#include "fluid_solver/water_rates.h"
#include "sph/free_particle_totals.h"
#include "sph/integrator.h"
#include "sph/lattice_gradient.h"
#include "sph/overlap_scatter.h"
#include "sph/particle_removal.h"

namespace porosph::water {
namespace {

/// Water particles are re-sorted by cell this often (steps), for memory locality of the pair loops
/// (each re-sort forces a neighbour search: 100 measured faster than 20 on the dam break).

class StopWatch {
 public:
  explicit StopWatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~StopWatch() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

template <int D>
WaterSolver<D>::WaterSolver(const scene::Scene& s)
    : Core(scene::active_terms(s, "water")),
      params_(WaterParams<D>::from_scene(s)),
      box_(sph::DomainBox<D>::from_scene(s, 2.0 * params_.h)),
      kernel_(s.run.kernel, params_.h, s.run.dp, s.run.kernel_gradient != "plain"),
      damping_(sph::DampingStage::from_scene(s)),
      zones_(*s.water, params_.dp, params_.h, params_.gravity, damping_.duration()),
      reservoirs_(*s.water, params_.gravity, params_.dp, params_.h, params_.eos),
      open_(*s.water, {params_.gravity, params_.h, params_.eos}, params_.dp, damping_.duration(),
            static_cast<int>(zones_.inflow_count())),
      moving_walls_(s),
      pore_fields_(s.has_soil()) {
  for (const auto& o : s.observables)
    if (o.phase == "water") observables_.push_back(sph::prepare_observable<D>(o));

  InitialParticles<D> initial = initial_particles<D>(s, params_, box_, zones_, open_);
  particles_ = std::move(initial.particles);
  scalars_.next_wall_removal = initial.next_wall_removal;
  // Thin walls filled on both sides (water.thin_walls): the list leaves out the pairs they hide.
  neighbours_.set_occluders(std::move(initial.occluders));
  next_id_ = static_cast<std::int64_t>(particles_.size());
  if (reservoirs_.count() > 0)  // room for a few refills before the arrays must grow
    particles_.reserve(particles_.position.capacity() + 4 * reservoirs_.column_count());
  cell_order_.reorder(neighbours_, particles_, box_, /*sort_fixed=*/true, overlap_index_);
}

template <int D>
void WaterSolver<D>::compute_rates() {
  StopWatch watch(physics_seconds_);
  cell_order_.refresh(neighbours_, particles_, box_, scalars_.step, overlap_index_);
  scalars_.neighbours_per_particle = neighbours_.neighbours_per_free_particle();
  kernel_.visit([this](const auto& kernel) { compute_rates_with(kernel); });
}

template <int D>
template <class Kernel>
void WaterSolver<D>::compute_rates_with(const Kernel& kernel) {
  const bool filtered = density_filter_due();  // an Euler step (next_step_is_euler)
  // Viscous terms at v^{n-1} on a Verlet step (viscous_level.h).
  const ViscousLevel level = next_step_is_euler() ? ViscousLevel::Current : ViscousLevel::Previous;
  update_water_pressure(params_, particles_);
  update_wall_state(neighbours_, kernel, params_, particles_, level);
  if (filtered) {  // the filter uses the wall densities; then walls follow the water
    shepard_density_filter(neighbours_, kernel, particles_, filter_scratch_);
    update_water_pressure(params_, particles_);
    update_wall_state(neighbours_, kernel, params_, particles_, level);
  }
  const RateSummary r = compute_water_rates(neighbours_, kernel, params_, particles_, level);
  moving_walls_.measure_forces(neighbours_, kernel, particles_, params_.shifting_on() ? -1.0 : 1.0);
  if (params_.shifting_on()) {
    shifting_.compute(neighbours_, kernel, params_.dp, r.max_speed, particles_);
    shifting_.add_to_continuity(neighbours_, kernel, params_.particle_shifting, params_.h,
                                particles_);
  }
  scalars_.limits = sph::time_step_limits(params_.h, params_.eos.c0(), r.max_speed,
                                          params_.mu / params_.eos.rho0(), r.max_total_acceleration,
                                          params_.cfl, params_.viscous_coefficient, params_.c_a);
}

template <int D>
double WaterSolver<D>::evaluate(const sph::PreparedObservable<D>& o,
                                const sph::ParticleView<D>& view) const {
  if (o.kind == sph::PreparedObservable<D>::Kind::WallForce) {  // moving_walls.h
    const int k = moving_walls_.index_of(o.wall);
    return k < 0 ? std::numeric_limits<double>::quiet_NaN()
                 : moving_walls_.force(static_cast<std::size_t>(k)).dot(o.direction);
  }
  return kernel_.visit(
      [&o, &view](const auto& kernel) { return sph::evaluate_observable(o, view, kernel); });
}

template <int D>
void WaterSolver<D>::fill_state(coupling::StepState& out, const std::vector<double>& overlap_min,
                                const std::vector<double>& overlap_max) {
  using Vec = sph::Vec<D>;
  StopWatch watch(physics_seconds_);
  const WaterParticles<D>& P = particles_;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  out.step = scalars_.step;
  out.time = scalars_.time;

  // Overlap set.
  overlap_index_.clear();
  out.clear_overlap();
  if (!overlap_min.empty() && !overlap_max.empty()) {
    const Vec lo = sph::to_vec<D>(overlap_min, "overlap_min");
    const Vec hi = sph::to_vec<D>(overlap_max, "overlap_max");
    const bool euler = next_step_is_euler();
    for (std::int64_t a = 0; a < n; ++a) {
      const Vec& x = P.position[a];
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
      overlap_index_.push_back(static_cast<std::int32_t>(a));
      out.overlap_id.push_back(P.id[a]);
      for (int k = 0; k < D; ++k) out.overlap_position.push_back(x[k]);
      for (int k = 0; k < D; ++k) out.overlap_velocity.push_back(P.velocity[a][k]);
      out.overlap_density.push_back(P.density[a]);
      out.overlap_mass.push_back(P.mass[a]);
      // The next update without the interaction (verlet_step_coupled): v^n + dt a on an Euler
      // step, q^n + (dt_previous + dt) a on a Verlet step, a the latest rates' own
      // acceleration; a zone particle keeps its prescribed velocity.
      const bool zone = P.zone[a] >= 0;
      const Vec& v = P.velocity[a];
      const Vec& a_own = P.acceleration[a];
      const Vec base = zone || euler ? v : Vec(P.velocity_previous[a] + dt_previous_ * a_own);
      for (int k = 0; k < D; ++k) out.overlap_update_base.push_back(base[k]);
      for (int k = 0; k < D; ++k) out.overlap_update_rate.push_back(zone ? 0.0 : a_own[k]);
    }
  }

  // Diagnostics of the water particles: one parallel pass.
  const sph::FreeParticleTotals<D> t =
      sph::free_particle_totals<D>(P.position.data(), P.velocity.data(), P.mass.data(), P.n_free);
  out.region_min.assign(t.lo.data(), t.lo.data() + D);
  out.region_max.assign(t.hi.data(), t.hi.data() + D);
  coupling::Diagnostics& d = out.diagnostics;
  d.particle_count = P.size();
  d.free_count = P.n_free;
  d.removed_count = scalars_.removed_count;
  d.inflow_mass = inflow_mass_;
  d.neighbours_per_particle = scalars_.neighbours_per_particle;
  d.outflow_mass = scalars_.outflow_mass;
  d.mass = t.mass;
  d.kinetic_energy = t.kinetic_energy;
  d.max_speed = t.max_speed;
  // The state is reported before its rates are computed (solver_runtime.h): the CFL limit of the
  // current speeds, eq. 21 and the viscous limit of the latest rates.
  scalars_.limits.cfl = sph::cfl_limit(params_.cfl, params_.h, params_.eos.c0(), d.max_speed);
  out.dt_cfl = scalars_.limits.cfl;
  out.dt_viscous = scalars_.limits.viscous;
  out.dt_force = scalars_.limits.force;
  out.dt_limit = scalars_.limits.min();
  d.momentum.assign(t.momentum, t.momentum + D);
  book_.flatten(d.external_impulse);  // what the last advance did (water_impulse_book.h)
  const sph::ParticleView<D> view{P.position.data(), P.velocity.data(), P.mass.data(),
                                  P.pressure.data(), P.n_free,          P.density.data()};
  for (const auto& o : observables_) d.observables[o.name] = evaluate(o, view);
  d.physics_seconds = physics_seconds_;
}

template <int D>
void WaterSolver<D>::add_interaction(const std::vector<double>& acceleration) {
  // Every overlap particle takes its share (the water's overlap set holds free water only).
  this->scatter_interaction(acceleration, particles_.size(),
                            [](std::int32_t, const sph::Vec<D>&) {});
}

template <int D>
void WaterSolver<D>::set_drag_rate(const std::vector<double>& rate) {
  if (rate.empty() && !viscosity_cut_nonzero_) return;
  if (!rate.empty() && rate.size() != overlap_index_.size()) {
    throw std::invalid_argument("set_drag_rate: expected " + std::to_string(overlap_index_.size()) +
                                " values, got " + std::to_string(rate.size()));
  }
  std::vector<double>& cut = particles_.viscosity_cut;
  std::vector<double>& lambda = particles_.drag_rate;
  std::fill(cut.begin(), cut.end(), 0.0);
  std::fill(lambda.begin(), lambda.end(), 0.0);
  viscosity_cut_nonzero_ = false;
  if (!params_.drag_share_on()) return;  // no term uses the drag rate
  for (std::size_t i = 0; i < rate.size(); ++i) {
    cut[overlap_index_[i]] = params_.drag_share(rate[i]);
    lambda[overlap_index_[i]] = std::max(0.0, rate[i]);
    viscosity_cut_nonzero_ = viscosity_cut_nonzero_ || cut[overlap_index_[i]] > 0.0;
  }
}

template <int D>
void WaterSolver<D>::advance(double dt) {
  StopWatch watch(physics_seconds_);
  this->drop_stale_interaction();  // none this step, nor in the next step's eq. 21
  book_.clear();
  if (!damping_.active(scalars_.time)) integrate(dt);  // else the water waits (sph/damping_stage.h)
  moving_walls_.move(particles_, dt);
  scalars_.time += dt;
  ++scalars_.step;
  this->remove_expired_walls();
}

template <int D>
bool WaterSolver<D>::density_filter_due() const {
  const int every = params_.density_filter_every;
  return every > 0 && scalars_.step > 0 && scalars_.step % static_cast<std::uint64_t>(every) == 0 &&
         !damping_.active(scalars_.time);
}

template <int D>
bool WaterSolver<D>::next_step_is_euler() const {
  const bool release =
      damping_.duration() > 0.0 && !damping_.released() && !damping_.active(scalars_.time);
  return sph::is_euler_step(scalars_.step, params_.euler_every) || density_filter_due() || release;
}

template <int D>
void WaterSolver<D>::integrate(double dt) {
  WaterParticles<D>& P = particles_;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
  // An Euler step also where dt jumps (the short last step of a run): the two Verlet time levels
  // hold the odd and even chains, and a step much shorter than the last one would hand the
  // reported velocity over to the other chain. Decided before release() marks the stage over.
  const bool dt_jump = std::abs(dt - dt_previous_) > 0.01 * dt_previous_;
  const bool euler = next_step_is_euler() || dt_jump;
  if (damping_.release(
          scalars_.time)) {  // end of the damping stage: every water velocity zeroed once
    book_[kWaterDamping] -= momentum_of(P, 0, P.n_free);
    std::fill(P.velocity.begin(), P.velocity.begin() + n, sph::Vec<D>::Zero());
    std::fill(P.velocity_previous.begin(), P.velocity_previous.begin() + n, sph::Vec<D>::Zero());
  }
  const std::uint64_t born_before = born_count_, removed_before = scalars_.removed_count;
  zones_.begin_step(scalars_.time, dt);
  open_.begin_step(P, scalars_.time);
  book_water_integration(P, params_.gravity, dt, dt_previous_, euler, zones_, open_, book_);
  std::int64_t past_zone = 0;  // zone particles past their downstream face
  const bool shifting = params_.shifting_on() && shifting_.concentration.size() == P.n_free;
  sph::FirstCrossing<D> crossing;  // a free particle carried across a thin wall
#pragma omp parallel for schedule(static) reduction(+ : past_zone)
  for (std::int64_t a = 0; a < n; ++a) {
    const sph::Vec<D> before = P.position[a];
    if (P.zone[a] >= 0) {  // prescribed velocity (flow_zones.h, open_reservoirs.h)
      const int z = P.zone[a];
      past_zone += open_.owns(z)
                       ? open_.move(z, P.position[a], P.velocity[a], P.velocity_previous[a], dt)
                       : zones_.move(z, P.position[a], P.velocity[a], P.velocity_previous[a], dt);
    } else {
      sph::verlet_step_coupled<D>(P.position[a], P.velocity[a], P.velocity_previous[a],
                                  P.acceleration[a], P.interaction[a], dt, dt_previous_, euler);
    }
    sph::verlet_step_scalar(P.density[a], P.density_previous[a], P.density_rate[a], dt, euler);
    if (shifting) shifting_.shift(params_.particle_shifting, params_.h, dt, a, P);
    if (const int wall = this->crossed_occluder_by(a, before); wall >= 0)
      crossing.offer(a, wall, before, P.position[a]);
    box_.wrap(P.position[a]);
  }
  this->record_crossing("water", crossing);
  // The particles born are inserted at the end of the free range: their momentum is booked.
  std::size_t free_before = P.n_free;
  if (past_zone > 0) born_count_ += zones_.renew(P, params_.volume, next_id_, inflow_mass_);
  born_count_ += open_.renew(P, params_.volume, next_id_, inflow_mass_);
  book_[kWaterInflow] += momentum_of(P, free_before, P.n_free);
  dt_previous_ = dt;
  remove_leaving_particles();
  open_.capture_and_impose(P);
  free_before = P.n_free;
  if (reservoirs_.count() > 0)
    born_count_ += reservoirs_.refill(P, scalars_.time, next_id_, inflow_mass_);
  book_[kWaterReservoir] += momentum_of(P, free_before, P.n_free);
  // Births and removals shift the indices: a new search even where they leave the count as it was
  // (the list would otherwise survive as long as no particle moved more than half the skin).
  if (born_count_ != born_before || scalars_.removed_count != removed_before)
    neighbours_.invalidate();
}

template <int D>
bool WaterSolver<D>::leaves(std::size_t a) const {
  const WaterParticles<D>& P = particles_;
  if (box_.outside(P.position[a])) return true;
  if (open_.owns(P.zone[a])) return open_.past_far_face(P.zone[a], P.position[a]);
  return P.zone[a] < 0 && (zones_.in_outflow(P.position[a], P.id[a], scalars_.time) ||
                           reservoirs_.above_level(P.position[a], scalars_.time) ||
                           open_.above_level(P.position[a]));
}

template <int D>
void WaterSolver<D>::remove_leaving_particles() {
  const WaterParticles<D>& P = particles_;
  const auto leaving = [this](std::size_t a) { return leaves(a); };
  const auto removing = [this, &P](std::size_t a) {  // its momentum leaves with it
    const bool outflow = box_.outside(P.position[a]) ||
                         zones_.in_outflow(P.position[a], P.id[a], scalars_.time) ||
                         open_.owns(P.zone[a]) || open_.above_level(P.position[a]);
    book_[outflow ? kWaterOutflow : kWaterReservoir] -= P.mass[a] * P.velocity[a];
  };
  this->remove_free_particles_where(leaving, removing);
}

template class WaterSolver<2>;
template class WaterSolver<3>;

}  // namespace porosph::water
