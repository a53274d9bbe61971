// WaterSolver's read-only reports: the non-finite check (with the Mach limit) and the snapshot
// fields.
#include <algorithm>
#include <cmath>

#include "fluid_solver/water_solver.h"
#include "sph/mach_watch.h"
#include "sph/non_finite_report.h"

namespace porosph::water {

template <int D>
std::optional<std::string> WaterSolver<D>::find_non_finite(std::int64_t* particle_id) const {
  const WaterParticles<D>& P = particles_;
  const std::int64_t n = static_cast<std::int64_t>(P.size());
  const std::size_t values = P.size() * D;
  if (values == 0 || (sph::all_finite(P.position.data()->data(), values) &&
                      sph::all_finite(P.velocity.data()->data(), values) &&
                      sph::all_finite(P.density.data(), P.size()))) {
    // A finite state may still leave the weakly compressible model (sph/mach_watch.h).
    return sph::find_mach_violation<D>(P.position, P.velocity, P.fixed, P.id, params_.eos.c0(),
                                       step_, time_, particle_id);
  }
  std::int64_t first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
  for (std::int64_t a = 0; a < n; ++a) {
    if (!P.position[a].allFinite() || !P.velocity[a].allFinite() || !std::isfinite(P.density[a]))
      first = std::min(first, a);
  }
  if (first == n) return std::nullopt;
  const char* what = !P.position[first].allFinite()   ? "position"
                     : !P.velocity[first].allFinite() ? "velocity"
                                                      : "density";
  if (particle_id != nullptr) *particle_id = P.id[first];
  return sph::non_finite_message<D>(what, P.fixed[first] ? "wall" : "water", P.id[first],
                                    P.position[first], P.velocity[first], P.density[first], step_,
                                    time_);
}

template <int D>
std::vector<io::FieldView> WaterSolver<D>::snapshot_fields() const {
  const WaterParticles<D>& P = particles_;
  const std::size_t n = P.size();
  auto f64 = [n](const char* name, std::size_t cols, const double* data, const char* unit) {
    io::FieldView f;
    f.name = name;
    f.unit = unit;
    f.rows = n;
    f.cols = cols;
    f.f64 = data;
    f.type = io::FieldType::F64;
    return f;
  };
  std::vector<io::FieldView> fields;
  fields.push_back(f64("position", D, n ? P.position[0].data() : nullptr, "m"));
  fields.push_back(f64("velocity", D, n ? P.velocity[0].data() : nullptr, "m/s"));
  fields.push_back(f64("density", 1, P.density.data(), "kg/m^3"));
  fields.push_back(f64("pressure", 1, P.pressure.data(), "Pa"));
  fields.push_back(f64("mass", 1, P.mass.data(), "kg"));  // varies: rho(t = 0) dp^D
  io::FieldView id;
  id.name = "id";
  id.rows = n;
  id.i64 = P.id.data();
  id.type = io::FieldType::I64;
  fields.push_back(id);
  io::FieldView fixed;
  fixed.name = "fixed";
  fixed.rows = n;
  fixed.u8 = P.fixed.data();
  fixed.type = io::FieldType::U8;
  fields.push_back(fixed);
  pore_fields_.append_fields(fields, P.velocity);  // scenes with soil: porosity, pore_velocity
  return fields;
}

template <int D>
void WaterSolver<D>::set_porosity(const std::vector<double>& porosity) {
  pore_fields_.update(porosity, overlap_index_, particles_.velocity);
}

template std::optional<std::string> WaterSolver<2>::find_non_finite(std::int64_t*) const;
template std::optional<std::string> WaterSolver<3>::find_non_finite(std::int64_t*) const;
template std::vector<io::FieldView> WaterSolver<2>::snapshot_fields() const;
template std::vector<io::FieldView> WaterSolver<3>::snapshot_fields() const;
template void WaterSolver<2>::set_porosity(const std::vector<double>&);
template void WaterSolver<3>::set_porosity(const std::vector<double>&);

}  // namespace porosph::water
