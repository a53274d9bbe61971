#include "fluid_solver/reservoirs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sph/geometry.h"

namespace porosph::water {

template <int D>
Reservoirs<D>::Reservoirs(const scene::WaterPhase& water, const Vec& gravity, double dp, double h,
                          const TaitEos& eos)
    : g_(gravity.norm()), dp_(dp), eos_(eos), kernel_(h) {
  if (std::none_of(water.reservoirs.begin(), water.reservoirs.end(),
                   [](const scene::ReservoirZone& r) { return r.boundary != "open"; }))
    return;
  int nonzero = 0;
  for (int k = 0; k < D; ++k)
    if (gravity[k] != 0.0) {
      ++nonzero;
      axis_ = k;
    }
  if (nonzero != 1) throw std::invalid_argument("water.reservoir: needs gravity along one axis");
  sign_ = gravity[axis_] < 0.0 ? 1.0 : -1.0;
  std::size_t columns = 0;
  for (std::size_t i = 0; i < water.reservoirs.size(); ++i) {
    const scene::ReservoirZone& r = water.reservoirs[i];
    if (r.boundary == "open") continue;  // open_reservoirs.h
    const std::string what = "water.reservoir[" + std::to_string(i) + "]";
    Zone z;
    z.min = sph::to_vec<D>(r.min, what + ".min");
    z.max = sph::to_vec<D>(r.max, what + ".max");
    if (!(z.max.array() > z.min.array()).all())
      throw std::invalid_argument(what + ": max must exceed min in every component");
    z.level = sign_ * r.level;
    z.bottom = std::min(sign_ * z.min[axis_], sign_ * z.max[axis_]);
    if (!(r.level > z.min[axis_] && r.level < z.max[axis_]))
      throw std::invalid_argument(what + ".level: must lie inside the box along the gravity axis");
    z.start_time = r.start_time;
    z.first_column = columns;
    for (int k = 0; k < D; ++k) {
      z.columns[k] = k == axis_ ? 1 : std::max(1L, sph::lattice_count(z.min[k], z.max[k], dp));
      z.column_total *= static_cast<std::size_t>(z.columns[k]);
    }
    columns += z.column_total;
    zones_.push_back(z);
  }
  top_index_.assign(columns, -1);
  top_height_.assign(columns, 0.0);
  candidates_.reserve(columns);
  clear_.reserve(columns);
  fill_.reserve(columns);
  born_.reserve(columns);
}

template <int D>
std::size_t Reservoirs<D>::column_of(const Zone& z, const Vec& x) const {
  std::size_t c = 0;
  for (int k = D - 1; k >= 0; --k) {
    if (k == axis_) continue;
    const long i = static_cast<long>(std::floor((x[k] - z.min[k]) / dp_));
    c = c * static_cast<std::size_t>(z.columns[k]) +
        static_cast<std::size_t>(std::clamp(i, 0L, z.columns[k] - 1));
  }
  return z.first_column + c;
}

template <int D>
typename Reservoirs<D>::Vec Reservoirs<D>::column_point(const Zone& z, std::size_t c,
                                                        double s) const {
  Vec x;
  c -= z.first_column;
  for (int k = 0; k < D; ++k) {
    if (k == axis_) continue;
    const std::size_t i = c % static_cast<std::size_t>(z.columns[k]);
    c /= static_cast<std::size_t>(z.columns[k]);
    x[k] = z.min[k] + (static_cast<double>(i) + 0.5) * dp_;
  }
  x[axis_] = sign_ * s;
  return x;
}

template <int D>
void Reservoirs<D>::find_column_tops(const WaterParticles<D>& P, double time) {
  std::fill(top_index_.begin(), top_index_.end(), -1);
  for (std::size_t a = 0; a < P.n_free; ++a) {
    if (P.zone[a] >= 0) continue;
    const Vec& x = P.position[a];
    for (const Zone& z : zones_) {
      if (time < z.start_time || !inside(z, x)) continue;
      const std::size_t c = column_of(z, x);
      const double s = height(x);
      if (top_index_[c] < 0 || s > top_height_[c]) {
        top_index_[c] = static_cast<std::int64_t>(a);
        top_height_[c] = s;
      }
      break;  // overlapping zones: the first one counts
    }
  }
}

template <int D>
void Reservoirs<D>::keep_clear_candidates(const WaterParticles<D>& P) {
  const double clearance2 = kClearance * kClearance * dp_ * dp_;
  const double support = kernel_.support(), volume = std::pow(dp_, D);
  clear_.assign(candidates_.size(), 1);
  fill_.assign(candidates_.size(), 0.0);
  Vec lo = candidates_[0].x, hi = candidates_[0].x;
  for (const Candidate& c : candidates_) {
    lo = lo.cwiseMin(c.x);
    hi = hi.cwiseMax(c.x);
  }
  lo.array() -= support;
  hi.array() += support;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec& x = P.position[i];
    if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      const double r2 = (candidates_[k].x - x).squaredNorm();
      if (r2 >= support * support) continue;
      if (r2 < clearance2) clear_[k] = 0;
      fill_[k] += volume * kernel_.w(std::sqrt(r2));
    }
  }
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (!clear_[j]) continue;
      const double r2 = (candidates_[k].x - candidates_[j].x).squaredNorm();
      if (r2 >= support * support) continue;
      if (r2 < clearance2) clear_[k] = 0;
      fill_[k] += volume * kernel_.w(std::sqrt(r2));
    }
    if (fill_[k] > kMaxFill) clear_[k] = 0;
  }
}

template <int D>
std::size_t Reservoirs<D>::refill(WaterParticles<D>& P, double time, std::int64_t& next_id,
                                  double& born_mass) {
  if (zones_.empty() || P.size() == 0) return 0;
  if (std::none_of(zones_.begin(), zones_.end(),
                   [time](const Zone& z) { return time >= z.start_time; }))
    return 0;
  find_column_tops(P, time);
  candidates_.clear();
  for (const Zone& z : zones_) {
    if (time < z.start_time) continue;
    for (std::size_t c = z.first_column; c < z.first_column + z.column_total; ++c) {
      const std::int64_t top = top_index_[c];
      if (top < 0) {
        if (z.bottom + 0.5 * dp_ < z.level)
          candidates_.push_back({column_point(z, c, z.bottom + 0.5 * dp_), -1, z.level});
      } else if (top_height_[c] < z.level - dp_) {
        candidates_.push_back({column_point(z, c, top_height_[c] + dp_), top, z.level});
      }
    }
  }
  if (candidates_.empty()) return 0;
  keep_clear_candidates(P);
  const double volume = std::pow(dp_, D);
  born_.for_each_array([](auto& array) { array.clear(); });
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (!clear_[k]) continue;
    const Candidate& c = candidates_[k];
    born_.append_copy(P, c.source >= 0 ? static_cast<std::size_t>(c.source) : 0);
    const std::size_t b = born_.size() - 1;
    const double s = height(c.x);
    born_.position[b] = c.x;
    if (c.source < 0) born_.velocity[b] = born_.velocity_previous[b] = Vec::Zero();
    born_.acceleration[b] = born_.interaction[b] = born_.wall_velocity[b] = Vec::Zero();
    born_.pressure[b] = eos_.still_water_pressure(std::max(0.0, c.level - s), g_);
    born_.density[b] = born_.density_previous[b] = eos_.density(born_.pressure[b]);
    born_.density_rate[b] = 0.0;
    born_.sound_speed[b] = eos_.sound_speed(born_.density[b]);
    born_.mass[b] = born_.density[b] * volume;
    born_.remove_at[b] = -1.0;
    born_.id[b] = next_id++;
    born_.fixed[b] = 0;
    born_.zone[b] = -1;
    born_mass += born_.mass[b];
  }
  const std::size_t born = born_.size();
  if (born == 0) return 0;
  if (P.size() + born > P.position.capacity()) P.reserve(P.size() + born + column_count());
  P.insert_free(born_);
  return born;
}

template <int D>
std::vector<double> Reservoirs<D>::column_surfaces(int zone, const WaterParticles<D>& P) const {
  const Zone& z = zones_[zone];
  std::vector<double> top(z.column_total, -std::numeric_limits<double>::infinity());
  for (std::size_t a = 0; a < P.n_free; ++a) {
    if (P.zone[a] >= 0 || !inside(z, P.position[a])) continue;
    double& t = top[column_of(z, P.position[a]) - z.first_column];
    t = std::max(t, height(P.position[a]));
  }
  for (double& t : top)
    t = std::isfinite(t) ? sign_ * (t + 0.5 * dp_) : std::numeric_limits<double>::quiet_NaN();
  return top;
}

template class Reservoirs<2>;
template class Reservoirs<3>;

}  // namespace porosph::water
