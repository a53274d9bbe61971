#include "rigid_soil_solver/rigid_soil_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "porous/submerged_density.h"
#include "sph/checkpoint_arrays.h"
#include "sph/non_finite_report.h"

namespace porosph::rigid_soil {
namespace {

/// A double field of `rows` particles x `cols` values.
io::FieldView f64_field(const char* name, std::size_t rows, std::size_t cols, const double* data,
                        const char* unit = "") {
  io::FieldView f;
  f.name = name;
  f.unit = unit;
  f.rows = rows;
  f.cols = cols;
  f.f64 = data;
  f.type = io::FieldType::F64;
  return f;
}

}  // namespace

template <int D>
RigidSoilSolver<D>::RigidSoilSolver(const scene::Scene& scene)
    : skeleton_(build_rigid_skeleton<D>(scene)),
      submerged_saturation_(scene.coupling.submerged_saturation),
      kernel_(scene.h()) {
  // The submerged mass of the bookkeeping follows the coupler's rule (eq. 16): without water
  // nothing is submerged.
  for (const scene::SoilMaterial& m : scene.soil->materials) {
    submerged_ratio_.push_back(
        scene.has_water() ? porous::submerged_density_ratio(m, scene.water->rho0) : 1.0);
  }
  zeros_.assign(9 * skeleton_.size(), 0.0);  // the widest always-zero field: stress, N x 9
  for (const auto& o : scene.observables)
    if (o.phase == "soil") observables_.push_back(sph::prepare_observable<D>(o));
}

template <int D>
void RigidSoilSolver<D>::fill_state(coupling::StepState& out, const std::vector<double>& lo,
                                    const std::vector<double>& hi) {
  const RigidSkeleton<D>& S = skeleton_;
  out.step = step_;
  out.time = time_;
  out.dt_limit = out.dt_cfl = out.dt_viscous = out.dt_force =
      std::numeric_limits<double>::infinity();
  overlap_index_.clear();
  out.clear_overlap();
  const bool zone = lo.size() == D && hi.size() == D;
  sph::Vec<D> box_min = sph::Vec<D>::Constant(std::numeric_limits<double>::max());
  sph::Vec<D> box_max = sph::Vec<D>::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < S.size(); ++i) {
    const sph::Vec<D>& x = S.position[i];
    box_min = box_min.cwiseMin(x);
    box_max = box_max.cwiseMax(x);
    bool inside = zone;
    for (int k = 0; k < D && inside; ++k) inside = x[k] >= lo[k] && x[k] <= hi[k];
    if (!inside) continue;
    overlap_index_.push_back(static_cast<std::int32_t>(i));
    out.overlap_id.push_back(S.id[i]);
    for (int k = 0; k < D; ++k) out.overlap_position.push_back(x[k]);
    for (int k = 0; k < D; ++k) out.overlap_velocity.push_back(0.0);
    out.overlap_density.push_back(S.density[i]);
    out.overlap_mass.push_back(S.mass[i]);
    out.overlap_porosity.push_back(S.porosity[i]);
    out.overlap_material.push_back(static_cast<std::int32_t>(S.material[i]));
  }
  out.region_min.assign(box_min.data(), box_min.data() + D);
  out.region_max.assign(box_max.data(), box_max.data() + D);

  coupling::Diagnostics& d = out.diagnostics;
  d.particle_count = S.size();
  d.free_count = 0;
  d.removed_count = 0;
  d.mass = d.kinetic_energy = d.max_speed = 0.0;
  d.momentum.assign(D, 0.0);
  d.inflow_mass = d.outflow_mass = 0.0;
  d.neighbours_per_particle = 0.0;
  const sph::ParticleView<D> no_free_particle{};  // observables measure the free particles
  for (const auto& o : observables_)
    d.observables[o.name] = sph::evaluate_observable(o, no_free_particle, kernel_);
}

template <int D>
void RigidSoilSolver<D>::add_interaction(const std::vector<double>& acceleration) {
  if (acceleration.size() != overlap_index_.size() * D) {
    throw std::invalid_argument("interaction: " + std::to_string(acceleration.size()) +
                                " values for " + std::to_string(overlap_index_.size()) +
                                " overlap particles in " + std::to_string(D) + "D");
  }
  interaction_ = acceleration;
}

template <int D>
void RigidSoilSolver<D>::set_saturation(const std::vector<double>& saturation) {
  if (!saturation.empty() && saturation.size() != overlap_index_.size()) {
    throw std::invalid_argument("saturation: " + std::to_string(saturation.size()) +
                                " values for " + std::to_string(overlap_index_.size()) +
                                " overlap particles");
  }
  std::fill(skeleton_.saturation.begin(), skeleton_.saturation.end(), 0.0);
  for (std::size_t k = 0; k < saturation.size(); ++k)
    skeleton_.saturation[overlap_index_[k]] = saturation[k];
}

template <int D>
void RigidSoilSolver<D>::advance(double dt) {
  RigidSkeleton<D>& S = skeleton_;
  for (std::size_t k = 0; k < interaction_.size() / D; ++k) {
    const std::size_t i = static_cast<std::size_t>(overlap_index_[k]);
    const double ratio = porous::submerged_density(1.0, S.saturation[i], submerged_saturation_,
                                                   submerged_ratio_[S.material[i]]);
    const double submerged_mass = S.mass[i] * ratio;  // m^s = m rho^s / rho
    for (int c = 0; c < D; ++c)
      S.absorbed_impulse[i][c] += submerged_mass * interaction_[k * D + c] * dt;
  }
  interaction_.clear();  // a command without accelerations books nothing
  time_ += dt;
  ++step_;
}

template <int D>
std::optional<std::string> RigidSoilSolver<D>::find_non_finite(std::int64_t* particle_id) const {
  const RigidSkeleton<D>& S = skeleton_;
  for (std::size_t i = 0; i < S.size(); ++i) {
    if (S.absorbed_impulse[i].allFinite()) continue;
    if (particle_id != nullptr) *particle_id = S.id[i];
    return sph::non_finite_message<D>("absorbed impulse", "rigid soil", S.id[i], S.position[i],
                                      sph::Vec<D>::Zero(), S.density[i], step_, time_);
  }
  return std::nullopt;
}

template <int D>
std::vector<io::FieldView> RigidSoilSolver<D>::snapshot_fields() const {
  const RigidSkeleton<D>& S = skeleton_;
  const std::size_t n = S.size();
  const double* zero = zeros_.data();
  std::vector<io::FieldView> fields;
  fields.push_back(f64_field("position", n, D, n ? S.position[0].data() : nullptr, "m"));
  fields.push_back(f64_field("velocity", n, D, zero, "m/s"));
  fields.push_back(f64_field("density", n, 1, S.density.data(), "kg/m^3"));
  fields.push_back(f64_field("stress", n, 9, zero, "Pa"));
  fields.push_back(f64_field("porosity", n, 1, S.porosity.data()));
  fields.push_back(f64_field("plastic_strain", n, 1, zero));
  fields.push_back(f64_field("displacement", n, D, zero, "m"));
  fields.push_back(io::field_view("id", S.id));
  fields.push_back(io::field_view("material", S.material));
  fields.push_back(io::field_view("fixed", S.fixed));
  // Everything above is the same at every output: soil.h5 stores it once, in /static, and links
  // it from each snapshot (io/snapshot_writer.h). Only the two fields below change.
  for (io::FieldView& f : fields) f.unchanging = true;
  fields.push_back(f64_field("saturation", n, 1, S.saturation.data()));
  fields.push_back(
      f64_field("absorbed_impulse", n, D, n ? S.absorbed_impulse[0].data() : nullptr, "N s"));
  return fields;
}

template <int D>
void RigidSoilSolver<D>::write_checkpoint(io::CheckpointWriter& out) {
  sph::write_particle_arrays(out, skeleton_);
  out.set("dimension", static_cast<std::int64_t>(D));
  out.set("time", time_);
  out.set("step", static_cast<std::int64_t>(step_));
}

template <int D>
void RigidSoilSolver<D>::restore_checkpoint(const io::CheckpointReader& in) {
  if (in.get_i64("dimension") != D) {
    throw std::runtime_error(in.path() + ": a checkpoint of a run in another dimension");
  }
  sph::read_particle_arrays(in, skeleton_);
  zeros_.assign(9 * skeleton_.size(), 0.0);
  time_ = in.get_f64("time");
  step_ = static_cast<std::uint64_t>(in.get_i64("step"));
  interaction_.clear();  // a checkpoint is taken after advance()
}

template <int D>
sph::Vec<D> RigidSoilSolver<D>::total_absorbed_impulse() const {
  sph::Vec<D> total = sph::Vec<D>::Zero();
  for (const sph::Vec<D>& p : skeleton_.absorbed_impulse) total += p;
  return total;
}

template class RigidSoilSolver<2>;
template class RigidSoilSolver<3>;

}  // namespace porosph::rigid_soil
