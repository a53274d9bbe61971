#include "fluid_solver/open_reservoirs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/geometry.h"

namespace porosph::water {

template <int D>
OpenReservoirs<D>::OpenReservoirs(const scene::WaterPhase& water,
                                  const OpenBoundaryPhysics<D>& physics, double dp,
                                  double hold_until, int first_zone)
    : first_zone_(first_zone),
      g_(physics.gravity.norm()),
      dp_(dp),
      h_(physics.h),
      hold_until_(hold_until),
      eos_(physics.eos) {
  std::size_t cells = 0;
  for (std::size_t i = 0; i < water.reservoirs.size(); ++i) {
    const scene::ReservoirZone& r = water.reservoirs[i];
    if (r.boundary != "open") continue;
    const std::string what = "water.reservoir[" + std::to_string(i) + "]";
    int nonzero = 0;
    for (int k = 0; k < D; ++k)
      if (physics.gravity[k] != 0.0) {
        ++nonzero;
        up_axis_ = k;
      }
    if (nonzero != 1) throw std::invalid_argument(what + ": needs gravity along one axis");
    up_sign_ = physics.gravity[up_axis_] < 0.0 ? 1.0 : -1.0;
    Zone z;
    z.min = sph::to_vec<D>(r.min, what + ".min");
    z.max = sph::to_vec<D>(r.max, what + ".max");
    if (!(z.max.array() > z.min.array()).all())
      throw std::invalid_argument(what + ": max must exceed min in every component");
    z.normal = sph::to_vec<D>(r.direction, what + ".direction");
    nonzero = 0;
    for (int k = 0; k < D; ++k)
      if (z.normal[k] != 0.0) {
        ++nonzero;
        z.axis = k;
      }
    if (nonzero != 1 || z.axis == up_axis_)
      throw std::invalid_argument(what + ".direction: must point along one axis across gravity");
    z.normal[z.axis] = z.normal[z.axis] > 0.0 ? 1.0 : -1.0;
    z.face = z.normal[z.axis] > 0.0 ? z.max[z.axis] : z.min[z.axis];
    const long rows = sph::lattice_count(z.min[z.axis], z.max[z.axis], dp);
    z.length = static_cast<double>(rows) * dp;
    if (z.length < 2.0 * h_ - 1e-12 * dp)
      throw std::invalid_argument(what + ": the buffer is " + std::to_string(z.length) +
                                  " m thick along its direction; it needs at least the kernel "
                                  "support 2h = " +
                                  std::to_string(2.0 * h_) + " m");
    z.level = up_sign_ * r.level;
    z.bottom = std::min(up_sign_ * z.min[up_axis_], up_sign_ * z.max[up_axis_]);
    z.pressure_level = z.level;
    if (r.absorbing) {
      const double depth = z.level - z.bottom;
      z.impedance = depth / std::sqrt(g_ * depth);  // H / c, c = sqrt(g H)
    }
    if (!(r.level > z.min[up_axis_] && r.level < z.max[up_axis_]))
      throw std::invalid_argument(what + ".level: must lie inside the box along the gravity axis");
    z.first_cell = cells;
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) {
      if (k == z.axis)
        z.cells[k] = 1;
      else if (k == up_axis_)
        z.cells[k] = std::max(1L, static_cast<long>(std::ceil((z.level - z.bottom) / dp - 1e-9)));
      else
        z.cells[k] = std::max(1L, sph::lattice_count(z.min[k], z.max[k], dp));
      total *= static_cast<std::size_t>(z.cells[k]);
    }
    cells += total;
    zones_.push_back(z);
  }
  cell_sum_.assign(cells, 0.0);
  cell_n_.assign(cells, 0);
  cell_speed_.assign(cells, 0.0);
  cell_back_.assign(cells, 0.0);
  find_cell_centres();
  born_.reserve(cells);
}

template <int D>
long OpenReservoirs<D>::cell_of(const Zone& z, const Vec& x) const {
  long c = 0;
  for (int k = D - 1; k >= 0; --k) {
    if (k == z.axis) continue;
    long i;
    if (k == up_axis_) {
      const double s = height(x);
      if (s > z.level) return -1;
      i = static_cast<long>(std::floor((s - z.bottom) / dp_));
      if (i < 0 || i >= z.cells[k]) return -1;
    } else {
      i = std::clamp(static_cast<long>(std::floor((x[k] - z.min[k]) / dp_)), 0L, z.cells[k] - 1);
    }
    c = c * z.cells[k] + i;
  }
  return static_cast<long>(z.first_cell) + c;
}

template <int D>
std::vector<typename OpenReservoirs<D>::Vec> OpenReservoirs<D>::buffer_lattice(int r) const {
  const Zone& z = zones_[r];
  std::vector<Vec> out;
  const long rows = static_cast<long>(std::lround(z.length / dp_));
  for (Vec x : cell_centres_[r]) {
    for (long j = 0; j < rows; ++j) {
      x[z.axis] = z.face - z.normal[z.axis] * (static_cast<double>(j) + 0.5) * dp_;
      out.push_back(x);
    }
  }
  return out;
}

template <int D>
void OpenReservoirs<D>::find_cell_centres() {
  cell_centres_.assign(zones_.size(), {});
  for (std::size_t r = 0; r < zones_.size(); ++r) {
    const Zone& z = zones_[r];
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) total *= static_cast<std::size_t>(z.cells[k]);
    for (std::size_t c = 0; c < total; ++c) {
      Vec x;
      x[z.axis] = z.face;
      std::size_t rest = c;
      for (int k = 0; k < D; ++k) {
        if (k == z.axis) continue;
        const std::size_t i = rest % static_cast<std::size_t>(z.cells[k]);
        rest /= static_cast<std::size_t>(z.cells[k]);
        if (k == up_axis_)
          x[k] = up_sign_ * (z.bottom + (static_cast<double>(i) + 0.5) * dp_);
        else
          x[k] = z.min[k] + (static_cast<double>(i) + 0.5) * dp_;
      }
      if (height(x) < z.level) cell_centres_[r].push_back(x);  // the rows below the level
    }
  }
}

template <int D>
int OpenReservoirs<D>::zone_below_level(const Vec& x) const {
  for (std::size_t r = 0; r < zones_.size(); ++r)
    if (inside(zones_[r], x) && height(x) <= zones_[r].level)
      return first_zone_ + static_cast<int>(r);
  return -1;
}

template <int D>
bool OpenReservoirs<D>::above_level(const Vec& x) const {
  for (const Zone& z : zones_)
    if (inside(z, x) && height(x) > z.level) return true;
  return false;
}

template <int D>
bool OpenReservoirs<D>::past_far_face(int zone, const Vec& x) const {
  const Zone& z = zones_[zone - first_zone_];
  return along(z, x) < -z.length;
}

template <int D>
void OpenReservoirs<D>::begin_step(const WaterParticles<D>& P, double time) {
  held_ = time < hold_until_;
  if (zones_.empty() || held_) return;
  std::fill(cell_sum_.begin(), cell_sum_.end(), 0.0);
  std::fill(cell_n_.begin(), cell_n_.end(), 0u);
  const double band = 2.0 * h_;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    if (P.zone[a] >= 0) continue;
    const Vec& x = P.position[a];
    for (const Zone& z : zones_) {
      const double d = along(z, x);
      if (d < 0.0 || d > band) continue;
      bool across = true;  // within the box across the normal
      for (int k = 0; k < D; ++k)
        if (k != z.axis && k != up_axis_ && (x[k] < z.min[k] || x[k] > z.max[k])) across = false;
      if (!across) continue;
      const long c = cell_of(z, x);
      if (c < 0) continue;
      cell_sum_[c] += P.velocity[a].dot(z.normal);
      ++cell_n_[c];
      break;
    }
  }
  for (std::size_t c = 0; c < cell_speed_.size(); ++c)
    cell_speed_[c] = cell_n_[c] > 0 ? cell_sum_[c] / cell_n_[c] : 0.0;
  for (Zone& z : zones_) {  // Flather: s_L - (H / c) u_m (absorbing), else s_L
    if (!(z.impedance > 0.0)) continue;
    std::size_t total = 1, sampled = 0;
    for (int k = 0; k < D; ++k) total *= static_cast<std::size_t>(z.cells[k]);
    double sum = 0.0;
    for (std::size_t c = z.first_cell; c < z.first_cell + total; ++c)
      if (cell_n_[c] > 0) sum += cell_speed_[c], ++sampled;
    z.pressure_level = z.level - z.impedance * (sampled > 0 ? sum / sampled : 0.0);
  }
}

template <int D>
typename OpenReservoirs<D>::Vec OpenReservoirs<D>::velocity_at(int zone, const Vec& x) const {
  const Zone& z = zones_[zone - first_zone_];
  if (held_) return Vec::Zero();
  const long c = cell_of(z, x);
  return c < 0 ? Vec::Zero() : Vec(cell_speed_[c] * z.normal);
}

template <int D>
void OpenReservoirs<D>::capture_and_impose(WaterParticles<D>& P) const {
  if (zones_.empty()) return;
  const std::int64_t n = static_cast<std::int64_t>(P.n_free);
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < n; ++a) {
    if (P.zone[a] < 0) {
      const int zone = zone_below_level(P.position[a]);
      if (zone < 0) continue;
      P.zone[a] = zone;
    } else if (!owns(P.zone[a])) {
      continue;
    }
    const Zone& z = zones_[P.zone[a] - first_zone_];
    const double p =
        eos_.still_water_pressure(std::max(0.0, z.pressure_level - height(P.position[a])), g_);
    P.density[a] = P.density_previous[a] = eos_.density(p);
    P.density_rate[a] = 0.0;
  }
}

template <int D>
std::size_t OpenReservoirs<D>::renew(WaterParticles<D>& P, double volume, std::int64_t& next_id,
                                     double& born_mass) {
  if (zones_.empty()) return 0;
  // The buffer particles past the face become water; per cell, the buffer's hindmost particle.
  std::fill(cell_n_.begin(), cell_n_.end(), 0u);
  std::size_t buffer = 0;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    if (!owns(P.zone[a])) continue;
    const Zone& z = zones_[P.zone[a] - first_zone_];
    const double d = along(z, P.position[a]);
    if (d > 0.0) {
      P.zone[a] = -1;  // handed over: a free particle from now on
      continue;
    }
    ++buffer;
    const long c = cell_of(z, P.position[a]);
    if (c < 0) continue;
    if (cell_n_[c] == 0 || d < cell_back_[c]) cell_back_[c] = d;
    ++cell_n_[c];
  }
  // One particle per cell and step behind the hindmost where a whole spacing is free up to the
  // far face (at the front of an empty cell), on the cell's row.
  born_.for_each_array([](auto& array) { array.clear(); });
  for (std::size_t r = 0; r < zones_.size(); ++r) {
    const Zone& z = zones_[r];
    const int zone = first_zone_ + static_cast<int>(r);
    for (const Vec& x0 : cell_centres_[r]) {
      const long c = cell_of(z, x0);
      double d;
      if (cell_n_[c] == 0)
        d = -0.5 * dp_;
      else if (cell_back_[c] - dp_ >= -z.length - 1e-9 * dp_)
        d = cell_back_[c] - dp_;
      else
        continue;
      Vec x = x0;
      x[z.axis] = z.face + z.normal[z.axis] * d;
      const double p = eos_.still_water_pressure(std::max(0.0, z.pressure_level - height(x)), g_);
      const double rho = eos_.density(p);
      const Vec u = velocity_at(zone, x);
      const std::size_t b = born_.size();
      born_.for_each_array([](auto& array) { array.emplace_back(); });
      born_.position[b] = x;
      born_.velocity[b] = born_.velocity_previous[b] = u;
      born_.acceleration[b] = born_.interaction[b] = born_.wall_velocity[b] = Vec::Zero();
      born_.viscosity_cut[b] = born_.drag_rate[b] = 0.0;
      born_.density[b] = born_.density_previous[b] = rho;
      born_.density_rate[b] = 0.0;
      born_.pressure[b] = p;
      born_.sound_speed[b] = eos_.sound_speed(rho);
      born_.mass[b] = rho * volume;
      born_.remove_at[b] = -1.0;
      born_.id[b] = next_id++;
      born_.fixed[b] = 0;
      born_.zone[b] = zone;
      born_.wall_motion[b] = -1;
      born_mass += born_.mass[b];
    }
  }
  const std::size_t born = born_.size();
  if (born == 0) return 0;
  if (P.size() + born > P.position.capacity()) P.reserve(P.size() + born + buffer);
  P.insert_free(born_);
  return born;
}

template class OpenReservoirs<2>;
template class OpenReservoirs<3>;

}  // namespace porosph::water
