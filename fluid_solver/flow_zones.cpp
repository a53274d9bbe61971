#include "fluid_solver/flow_zones.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/geometry.h"

namespace porosph::water {
namespace {

template <int D>
void check_box(const sph::Vec<D>& lo, const sph::Vec<D>& hi, const std::string& what) {
  if (!(hi.array() > lo.array()).all())
    throw std::invalid_argument(what + ": max must exceed min in every component");
}

}  // namespace

template <int D>
FlowZones<D>::FlowZones(const scene::WaterPhase& water, double dp, double h, const Vec& gravity,
                        double hold_until)
    : hold_until_(hold_until) {
  for (std::size_t i = 0; i < water.inflows.size(); ++i) {
    const scene::InflowZone& zone = water.inflows[i];
    const std::string what = "water.inflow[" + std::to_string(i) + "]";
    Inflow f;
    f.box.min = sph::to_vec<D>(zone.min, what + ".min");
    f.box.max = sph::to_vec<D>(zone.max, what + ".max");
    check_box<D>(f.box.min, f.box.max, what);
    if (zone.direction.size() != static_cast<std::size_t>(D))
      throw std::invalid_argument(what + ".direction: expected " + std::to_string(D) +
                                  " components");
    f.direction = sph::to_vec<D>(zone.direction, what + ".direction");
    int nonzero = 0;
    for (int k = 0; k < D; ++k) {
      if (f.direction[k] != 0.0) {
        ++nonzero;
        f.axis = k;
      }
    }
    if (nonzero != 1 || std::abs(std::abs(f.direction[f.axis]) - 1.0) > 1e-12)
      throw std::invalid_argument(what + ".direction: must be a unit vector along one axis");
    f.direction[f.axis] = f.direction[f.axis] > 0.0 ? 1.0 : -1.0;
    const long rows = sph::lattice_count(f.box.min[f.axis], f.box.max[f.axis], dp);
    if (rows < 1) throw std::invalid_argument(what + ": shorter than one particle spacing");
    f.lattice_length = static_cast<double>(rows) * dp;
    // The box's downstream face, or the lattice's downstream end where the rows reach past it
    // (up to dp / 2: a 0.1 m box at dp 0.0283 holds four rows, 0.113 m), so that a particle born
    // lattice_length upstream lands inside the box, not beyond its upstream face (and the
    // domain, where the zone starts at the domain's face).
    f.downstream = f.direction[f.axis] > 0.0
                       ? std::max(f.box.max[f.axis], f.box.min[f.axis] + f.lattice_length)
                       : std::min(f.box.min[f.axis], f.box.max[f.axis] - f.lattice_length);
    if (f.box.max[f.axis] - f.box.min[f.axis] < 2.0 * h - 1e-12 * dp)
      throw std::invalid_argument(
          what + ": the zone is " + std::to_string(f.box.max[f.axis] - f.box.min[f.axis]) +
          " m long along its direction; it needs at least the kernel support 2h = " +
          std::to_string(2.0 * h) +
          " m (the water leaving it must see zone particles across "
          "its whole kernel)");
    f.ramp = zone;
    inflows_.push_back(f);
  }
  for (std::size_t i = 0; i < water.outflows.size(); ++i) {
    const std::string what = "water.outflow[" + std::to_string(i) + "]";
    Box b;
    b.min = sph::to_vec<D>(water.outflows[i].min, what + ".min");
    b.max = sph::to_vec<D>(water.outflows[i].max, what + ".max");
    check_box<D>(b.min, b.max, what);
    outflows_.push_back(b);
    outflow_start_.push_back(water.outflows[i].start_time);
    Stagger st;
    if (water.outflows[i].stagger > 0.0) {
      int axes = 0;
      for (int k = 0; k < D; ++k)
        if (gravity[k] != 0.0) ++axes, st.axis = k;
      if (axes != 1) throw std::invalid_argument(what + ".stagger: needs gravity along one axis");
      st.up = gravity[st.axis] < 0.0 ? 1.0 : -1.0;
      st.face = st.up > 0.0 ? b.min[st.axis] : -b.max[st.axis];
      st.depth = water.outflows[i].stagger * dp;
    }
    outflow_stagger_.push_back(st);
  }
  step_.resize(inflows_.size());
  begin_step(0.0, 0.0);
}

template <int D>
scene::Shape FlowZones<D>::inflow_box(int z) const {
  scene::Shape s;
  s.kind = scene::Shape::Kind::Box;
  const Box& b = inflows_[z].box;
  s.min.assign(b.min.data(), b.min.data() + D);
  s.max.assign(b.max.data(), b.max.data() + D);
  s.label = "water.inflow[" + std::to_string(z) + "]";
  return s;
}

template <int D>
double FlowZones<D>::speed(int z, double time) const {
  if (time < hold_until_) return 0.0;
  return inflows_[z].ramp.speed_at(time);
}

template <int D>
void FlowZones<D>::begin_step(double time, double dt) {
  for (int z = 0; z < static_cast<int>(inflows_.size()); ++z) {
    step_[z].start = velocity(z, time);
    step_[z].middle = velocity(z, time + 0.5 * dt);
    step_[z].end = velocity(z, time + dt);
  }
}

template <int D>
std::size_t FlowZones<D>::renew(WaterParticles<D>& P, double volume, std::int64_t& next_id,
                                double& born_mass) {
  born_.for_each_array([](auto& array) { array.clear(); });
  std::size_t zone_particles = 0;
  for (std::size_t a = 0; a < P.n_free; ++a) {
    const int z = P.zone[a];
    if (z < 0 || z >= static_cast<int>(inflows_.size())) continue;  // free, or an open buffer's
    ++zone_particles;
    if (!past_downstream(z, P.position[a])) continue;
    born_.append_copy(P, a);  // same zone, transverse position, velocities, density, pressure
    const std::size_t b = born_.size() - 1;
    born_.position[b] -= inflows_[z].lattice_length * inflows_[z].direction;
    born_.mass[b] = born_.density[b] * volume;
    born_mass += born_.mass[b];
    born_.id[b] = next_id++;
    born_.acceleration[b].setZero();
    born_.interaction[b].setZero();
    born_.density_rate[b] = 0.0;
    P.zone[a] = -1;  // handed over: a free particle from now on
  }
  const std::size_t born = born_.size();
  if (born == 0) return 0;
  if (P.size() + born > P.position.capacity())
    P.reserve(P.size() + born + std::max(born, zone_particles));
  P.insert_free(born_);
  return born;
}

template class FlowZones<2>;
template class FlowZones<3>;

}  // namespace porosph::water
