// WaterSolver's read-only reports: the non-finite check (with the Mach limit) and the snapshot
// fields.
#include <algorithm>
#include <cmath>

#include "fluid_solver/water_solver.h"
#include "sph/mach_watch.h"
#include "sph/non_finite_report.h"
#include "sph/particle_fields.h"

namespace porosph::water {

template <int D>
std::optional<std::string> WaterSolver<D>::find_non_finite(std::int64_t* particle_id) const {
  if (auto crossing = this->crossing_problem(particle_id)) return crossing;
  const WaterParticles<D>& P = particles_;
  const std::int64_t n = static_cast<std::int64_t>(P.size());
  const std::size_t values = P.size() * D;
  if (values == 0 || (sph::all_finite(P.position.data()->data(), values) &&
                      sph::all_finite(P.velocity.data()->data(), values) &&
                      sph::all_finite(P.density.data(), P.size()))) {
    // A finite state may still leave the weakly compressible model (sph/mach_watch.h).
    return sph::find_mach_violation<D>(P.position, P.velocity, P.fixed, P.id, params_.eos.c0(),
                                       scalars_.step, scalars_.time, particle_id);
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
                                    P.position[first], P.velocity[first], P.density[first],
                                    scalars_.step, scalars_.time);
}

template <int D>
std::vector<io::FieldView> WaterSolver<D>::snapshot_fields() const {
  const WaterParticles<D>& P = particles_;
  std::vector<io::FieldView> fields = {
      sph::packed_field("position", P.position, "m"),
      sph::packed_field("velocity", P.velocity, "m/s"),
      sph::scalar_field("density", P.density, "kg/m^3"),
      sph::scalar_field("pressure", P.pressure, "Pa"),
      sph::scalar_field("mass", P.mass, "kg"),  // varies: rho(t = 0) dp^D
      sph::scalar_field("id", P.id),
      sph::scalar_field("fixed", P.fixed)};
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
