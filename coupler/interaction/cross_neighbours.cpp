#include "coupler/interaction/cross_neighbours.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace porosph::coupler {
namespace {

/// True when the set holds the same ids as `id` and no point moved farther than sqrt(limit2)
/// from `position` (a non-finite coordinate counts as moved).
template <int D>
bool same_and_close(const OverlapPoints& set, const std::vector<std::int64_t>& id,
                    const std::vector<double>& position, double limit2) {
  if (set.size != id.size()) return false;
  if (!std::equal(id.begin(), id.end(), set.id)) return false;
  for (std::size_t i = 0; i < set.size; ++i) {
    double d2 = 0.0;
    for (int k = 0; k < D; ++k) {
      const double d = set.position[i * D + k] - position[i * D + k];
      d2 += d * d;
    }
    if (!(d2 <= limit2)) return false;
  }
  return true;
}

}  // namespace

template <int D>
void CrossNeighbours<D>::update(const OverlapPoints& soil, const OverlapPoints& water,
                                double support, const sph::DomainBox<D>& box) {
  const bool search_now = needs_search(soil, water, support, box);
  support_ = support;
  box_ = box;
  soil_count_ = soil.size;
  if (search_now) search(soil, water);
}

template <int D>
bool CrossNeighbours<D>::needs_search(const OverlapPoints& soil, const OverlapPoints& water,
                                      double support, const sph::DomainBox<D>& box) const {
  if (!searched_ || support != support_) return true;
  if (!box.same_as(box_)) return true;
  const double limit2 = 0.25 * skin_ * skin_;
  return !same_and_close<D>(soil, searched_soil_id_, searched_soil_position_, limit2) ||
         !same_and_close<D>(water, searched_water_id_, searched_water_position_, limit2);
}

template <int D>
void CrossNeighbours<D>::search(const OverlapPoints& soil, const OverlapPoints& water) {
  const std::size_t n = soil.size;
  searched_soil_id_.assign(soil.id, soil.id + n);
  searched_soil_position_.assign(soil.position, soil.position + n * D);
  searched_water_id_.assign(water.id, water.id + water.size);
  searched_water_position_.assign(water.position, water.position + water.size * D);
  searched_ = true;
  ++search_count_;
  order_.resize(n);
  sorted_position_.resize(n);
  cell_of_particle_.resize(n);
  candidate_start_.assign(water.size + 1, 0);
  candidate_.clear();
  max_candidate_count_ = 0;
  if (n == 0) return;
  setup_grid(soil.position, n);
  const std::int64_t cell_count = grid_.cell_count;
  // Counting sort by cell (stable: a cell keeps the input order of its particles).
  cell_start_.assign(static_cast<std::size_t>(cell_count) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    sph::Vec<D> x = Eigen::Map<const sph::Vec<D>>(soil.position + i * D);
    box_.wrap(x);
    cell_of_particle_[i] = grid_.cell_of(x);
    ++cell_start_[cell_of_particle_[i] + 1];
  }
  for (std::int64_t c = 0; c < cell_count; ++c) cell_start_[c + 1] += cell_start_[c];
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t slot = cell_start_[cell_of_particle_[i]]++;
    order_[slot] = static_cast<std::int32_t>(i);
    sorted_position_[slot] = Eigen::Map<const sph::Vec<D>>(soil.position + i * D);
    box_.wrap(sorted_position_[slot]);
  }
  // The cursors advanced each start to the next cell's start: shift back by one cell.
  for (std::int64_t c = cell_count; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
  // Candidates of each water particle, in soil index order.
  for (std::size_t a = 0; a < water.size; ++a) {
    const std::size_t first = candidate_.size();
    scan_cells(Eigen::Map<const sph::Vec<D>>(water.position + a * D),
               [&](std::int32_t i) { candidate_.push_back(i); });
    std::sort(candidate_.begin() + static_cast<std::ptrdiff_t>(first), candidate_.end());
    candidate_start_[a + 1] = static_cast<std::int32_t>(candidate_.size());
    max_candidate_count_ = std::max(max_candidate_count_, candidate_.size() - first);
  }
}

template <int D>
void CrossNeighbours<D>::setup_grid(const double* positions, std::size_t n) {
  sph::Vec<D> lo = sph::Vec<D>::Constant(std::numeric_limits<double>::infinity());
  sph::Vec<D> hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      const double v = positions[i * D + k];
      if (!std::isfinite(v)) continue;
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    }
  }
  grid_.lay_out(lo, hi, support_ + skin_, box_, n);
}

template class CrossNeighbours<2>;
template class CrossNeighbours<3>;

}  // namespace porosph::coupler
