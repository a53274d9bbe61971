#include "sph/neighbour_list.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace porosph::sph {

namespace {
/// Particles per work chunk of the list passes (handed out dynamically: robust to the uneven work
/// of free-surface cells and to a core shared with another process).
constexpr std::size_t kChunk = 256;
}  // namespace

template <int D>
void NeighbourList<D>::build(const Vec<D>* x, std::size_t n, std::size_t n_free, double support,
                             const DomainBox<D>& box, const std::int32_t* wall_tag) {
  const bool search = needs_search(x, n, n_free, support, box);
  n_ = n;
  n_free_ = std::min(n_free, n);
  support_ = support;
  box_ = box;
  begin_.resize(n);
  mid_.resize(n);
  end_.resize(n);
  pair_count_ = 0;
  if (n == 0) return;
  if (search) {
    setup_grid(x);
    sort_into_cells(x);
    if (box.any_periodic()) {
      search_candidates<true>(x);
    } else {
      search_candidates<false>(x);
    }
    searched_position_.assign(x, x + n);
    searched_ = true;
    ++search_count_;
  }
  if (box.any_periodic()) {
    refresh_pairs<true>(x, wall_tag);
  } else {
    refresh_pairs<false>(x, wall_tag);
  }
}

template <int D>
void NeighbourList<D>::cell_sorted_permutation(bool sort_fixed,
                                               std::vector<std::int32_t>& out) const {
  const auto is_free = [this](std::int32_t i) { return static_cast<std::size_t>(i) < n_free_; };
  out.clear();
  for (std::int32_t i : sorted_index_)
    if (is_free(i)) out.push_back(i);
  if (sort_fixed) {
    for (std::int32_t i : sorted_index_)
      if (!is_free(i)) out.push_back(i);
  } else {
    for (std::size_t i = n_free_; i < n_; ++i) out.push_back(static_cast<std::int32_t>(i));
  }
}

template <int D>
bool NeighbourList<D>::needs_search(const Vec<D>* x, std::size_t n, std::size_t n_free,
                                    double support, const DomainBox<D>& box) const {
  if (!searched_ || n != n_ || std::min(n_free, n) != n_free_ || support != support_) return true;
  if (!box.same_as(box_)) return true;
  // Any particle farther than skin/2 from where it was searched (a NaN counts as moved). With
  // skin 0 every motion triggers a search. Periodic axes: the wrapped position jumps by a box
  // length when a particle crosses, which counts as moved (a search, never a missed pair).
  const double limit2 = 0.25 * skin_ * skin_;
  const std::int64_t count = static_cast<std::int64_t>(n);
  bool moved = false;
#pragma omp parallel for schedule(static) reduction(|| : moved)
  for (std::int64_t a = 0; a < count; ++a) {
    const double d2 = (x[a] - searched_position_[a]).squaredNorm();
    moved = moved || !(d2 <= limit2);
  }
  return moved;
}

template <int D>
void NeighbourList<D>::setup_grid(const Vec<D>* x) {
  // Bounding box of the finite coordinates (non-periodic axes only matter).
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> hi = -lo;
  const std::int64_t n = static_cast<std::int64_t>(n_);
#pragma omp parallel
  {
    Vec<D> tlo = lo, thi = hi;
#pragma omp for schedule(static) nowait
    for (std::int64_t a = 0; a < n; ++a) {
      for (int k = 0; k < D; ++k) {
        const double v = x[a][k];
        if (!std::isfinite(v)) continue;
        tlo[k] = std::min(tlo[k], v);
        thi[k] = std::max(thi[k], v);
      }
    }
#pragma omp critical(porosph_sph_bbox)
    {
      lo = lo.cwiseMin(tlo);
      hi = hi.cwiseMax(thi);
    }
  }
  grid_.lay_out(lo, hi, support_ + skin_, box_, n_);
}

template <int D>
void NeighbourList<D>::sort_into_cells(const Vec<D>* x) {
  // Parallel counting sort, stable: thread t owns particles [a0_t, a1_t) and, within every cell,
  // the slots after those of threads < t; free particles (the lower indices) come first in a cell.
  cell_of_.resize(n_);
  sorted_index_.resize(n_);
  sorted_position_.resize(n_);
  cell_start_.resize(grid_.cell_count + 1);
  cell_free_end_.resize(grid_.cell_count);
  const int max_threads = omp_get_max_threads();
  if (static_cast<int>(thread_counts_.size()) < max_threads) thread_counts_.resize(max_threads);
  const std::int64_t cells = grid_.cell_count;
#pragma omp parallel
  {
    const std::size_t t = omp_get_thread_num(), threads = omp_get_num_threads();
    const std::size_t a0 = n_ * t / threads, a1 = n_ * (t + 1) / threads;
    std::vector<std::int32_t>& count = thread_counts_[t];
    count.assign(2 * cells, 0);  // [0, cells): all particles, [cells, 2 cells): free ones
    for (std::size_t a = a0; a < a1; ++a) {
      const std::int64_t c = grid_.cell_of(x[a]);
      cell_of_[a] = c;
      ++count[c];
      if (a < n_free_) ++count[cells + c];
    }
#pragma omp barrier
#pragma omp single
    {
      std::int32_t offset = 0;
      for (std::int64_t c = 0; c < cells; ++c) {
        cell_start_[c] = offset;
        std::int32_t free_in_cell = 0;
        for (std::size_t u = 0; u < threads; ++u) {
          const std::int32_t k = thread_counts_[u][c];
          free_in_cell += thread_counts_[u][cells + c];
          thread_counts_[u][c] = offset;  // becomes thread u's cursor in cell c
          offset += k;
        }
        cell_free_end_[c] = cell_start_[c] + free_in_cell;
      }
      cell_start_[cells] = offset;
    }  // implicit barrier
    for (std::size_t a = a0; a < a1; ++a) {
      const std::int32_t slot = count[cell_of_[a]]++;
      sorted_index_[slot] = static_cast<std::int32_t>(a);
      sorted_position_[slot] = x[a];
    }
  }
}

template <int D>
int NeighbourList<D>::stencil_of(std::int64_t cell, std::int64_t* out) const {
  // Per axis the distinct neighbouring cell coordinates (1 to 3 of them).
  std::int64_t axis_cells[D][3];
  int axis_count[D];
  std::int64_t rest = cell;
  for (int k = 0; k < D; ++k) {
    const std::int64_t nk = grid_.cells_per_axis[k];
    const std::int64_t c = rest % nk;
    rest /= nk;
    int m = 0;
    if (box_.periodic[k]) {
      if (nk >= 3) {
        axis_cells[k][m++] = (c + nk - 1) % nk;
        axis_cells[k][m++] = c;
        axis_cells[k][m++] = (c + 1) % nk;
      } else {
        for (std::int64_t j = 0; j < nk; ++j) axis_cells[k][m++] = j;
      }
    } else {
      for (std::int64_t j = std::max<std::int64_t>(0, c - 1); j <= std::min(nk - 1, c + 1); ++j) {
        axis_cells[k][m++] = j;
      }
    }
    axis_count[k] = m;
  }
  int count = 0;
  int idx[D] = {};
  while (true) {
    std::int64_t linear = 0, stride = 1;
    for (int k = 0; k < D; ++k) {
      linear += axis_cells[k][idx[k]] * stride;
      stride *= grid_.cells_per_axis[k];
    }
    out[count++] = linear;
    int k = 0;
    while (k < D && ++idx[k] == axis_count[k]) idx[k++] = 0;
    if (k == D) break;
  }
  return count;
}

template <int D>
template <bool kPeriodic>
void NeighbourList<D>::search_candidates(const Vec<D>* x) {
  // Each thread appends the candidate indices of its chunks to its own buffer. Every candidate is
  // written and kept only if in range (the cursor advances by the test's outcome): no
  // data-dependent jump per candidate. Buffer sizes only grow: no allocation in steady state.
  const std::int64_t chunks = static_cast<std::int64_t>((n_ + kChunk - 1) / kChunk);
  const int max_threads = omp_get_max_threads();
  if (static_cast<int>(candidate_buffers_.size()) < max_threads)
    candidate_buffers_.resize(max_threads);
  candidate_offsets_.resize(3 * n_);
  candidate_owner_.resize(chunks);
  const double reach = support_ + skin_, reach2 = reach * reach;
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    std::vector<std::int32_t>& buffer = candidate_buffers_[t];
    std::size_t used = 0;
    std::int64_t stencil[27];
    int stencil_size = 0;
    std::int64_t last_cell = -1;
    auto scan = [&](std::size_t a, const Vec<D>& xa, std::int32_t j0, std::int32_t j1) {
      std::int32_t* out = buffer.data();
      for (std::int32_t j = j0; j < j1; ++j) {
        const std::int32_t b = sorted_index_[j];
        Vec<D> dx = xa - sorted_position_[j];
        if constexpr (kPeriodic) box_.minimum_image(dx);
        out[used] = b;
        used += static_cast<std::size_t>((dx.squaredNorm() < reach2) &
                                         (b != static_cast<std::int32_t>(a)));
      }
    };
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
      candidate_owner_[chunk] = t;
      const std::size_t a1 = std::min(n_, static_cast<std::size_t>(chunk + 1) * kChunk);
      for (std::size_t a = static_cast<std::size_t>(chunk) * kChunk; a < a1; ++a) {
        if (cell_of_[a] != last_cell) {
          last_cell = cell_of_[a];
          stencil_size = stencil_of(last_cell, stencil);
        }
        std::size_t room = 0;
        for (int s = 0; s < stencil_size; ++s)
          room += static_cast<std::size_t>(cell_start_[stencil[s] + 1] - cell_start_[stencil[s]]);
        if (used + room > buffer.size()) buffer.resize(std::max(2 * buffer.size(), used + room));
        const Vec<D> xa = x[a];
        candidate_offsets_[3 * a] = static_cast<std::uint32_t>(used);
        for (int s = 0; s < stencil_size; ++s)
          scan(a, xa, cell_start_[stencil[s]], cell_free_end_[stencil[s]]);
        candidate_offsets_[3 * a + 1] = static_cast<std::uint32_t>(used);
        if (a < n_free_) {
          for (int s = 0; s < stencil_size; ++s)
            scan(a, xa, cell_free_end_[stencil[s]], cell_start_[stencil[s] + 1]);
        }
        candidate_offsets_[3 * a + 2] = static_cast<std::uint32_t>(used);
        // Index order: the lists (and so every sum over them) do not depend on when the search
        // ran, so a resumed run sums in the same order as an uninterrupted one.
        std::int32_t* c = buffer.data();
        std::sort(c + candidate_offsets_[3 * a], c + candidate_offsets_[3 * a + 1]);
        std::sort(c + candidate_offsets_[3 * a + 1], c + used);
      }
    }
  }
}

template <int D>
template <bool kPeriodic>
void NeighbourList<D>::refresh_pairs(const Vec<D>* x, const std::int32_t* wall_tag) {
  // The pair lists from the candidates at the current positions; same chunks as the search, each
  // thread writes its chunks' lists to its own buffer (branch-free keep, square roots of the kept
  // pairs only).
  const std::int64_t chunks = static_cast<std::int64_t>((n_ + kChunk - 1) / kChunk);
  const int max_threads = omp_get_max_threads();
  if (static_cast<int>(buffers_.size()) < max_threads) buffers_.resize(max_threads);
  offsets_.resize(3 * n_);
  chunk_owner_.resize(chunks);
  const double support2 = support_ * support_;
  std::size_t total = 0;
#pragma omp parallel reduction(+ : total)
  {
    const int t = omp_get_thread_num();
    std::vector<Pair>& buffer = buffers_[t];
    std::size_t used = 0;
    auto keep_in_range = [&](const Vec<D>& xa, const std::int32_t* c0, const std::int32_t* c1) {
      Pair* out = buffer.data();
      for (const std::int32_t* c = c0; c != c1; ++c) {
        Vec<D> dx = xa - x[*c];
        if constexpr (kPeriodic) box_.minimum_image(dx);
        const double r2 = dx.squaredNorm();
        out[used] = Pair{dx, r2, *c};  // r2 for now: the square root only for the kept pairs
        used += static_cast<std::size_t>(r2 < support2);
      }
    };
    // With occluders, for a particle near one: the same, less the pairs a thin wall hides (x_b =
    // x_a - x_ab, the pair's own segment also across a periodic boundary). A particle far from
    // every occluder has no hidden pair (WallOccluder::near) and keeps the branch-free loop.
    auto keep_visible = [&](std::size_t a, const Vec<D>& xa, const std::int32_t* c0,
                            const std::int32_t* c1) {
      const std::int32_t tag_a = wall_tag != nullptr ? wall_tag[a] : 0;
      for (const std::int32_t* c = c0; c != c1; ++c) {
        Vec<D> dx = xa - x[*c];
        if constexpr (kPeriodic) box_.minimum_image(dx);
        const double r2 = dx.squaredNorm();
        if (!(r2 < support2)) continue;
        const std::int32_t tag_b = wall_tag != nullptr ? wall_tag[*c] : 0;
        if (occluders_.hides(xa, tag_a, xa - dx, tag_b)) continue;
        buffer[used++] = Pair{dx, r2, *c};
      }
    };
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
      chunk_owner_[chunk] = t;
      const std::int32_t* candidates = candidate_buffers_[candidate_owner_[chunk]].data();
      const std::size_t a0 = static_cast<std::size_t>(chunk) * kChunk;
      const std::size_t a1 = std::min(n_, a0 + kChunk);
      const std::size_t room = candidate_offsets_[3 * (a1 - 1) + 2] - candidate_offsets_[3 * a0];
      if (used + room > buffer.size()) buffer.resize(std::max(2 * buffer.size(), used + room));
      for (std::size_t a = a0; a < a1; ++a) {
        const std::uint32_t* o = &candidate_offsets_[3 * a];
        const Vec<D> xa = x[a];
        offsets_[3 * a] = static_cast<std::uint32_t>(used);
        if (!occluders_.empty() && occluders_.near(xa, support_)) {
          keep_visible(a, xa, candidates + o[0], candidates + o[1]);
          offsets_[3 * a + 1] = static_cast<std::uint32_t>(used);
          keep_visible(a, xa, candidates + o[1], candidates + o[2]);
        } else {
          keep_in_range(xa, candidates + o[0], candidates + o[1]);
          offsets_[3 * a + 1] = static_cast<std::uint32_t>(used);
          keep_in_range(xa, candidates + o[1], candidates + o[2]);
        }
        offsets_[3 * a + 2] = static_cast<std::uint32_t>(used);
        for (std::size_t k = offsets_[3 * a]; k < used; ++k) buffer[k].r = std::sqrt(buffer[k].r);
      }
    }  // implicit barrier: every buffer is final, offsets become pointers
    const std::int64_t n = static_cast<std::int64_t>(n_);
#pragma omp for schedule(static)
    for (std::int64_t a = 0; a < n; ++a) {
      const Pair* base = buffers_[chunk_owner_[a / kChunk]].data();
      begin_[a] = base + offsets_[3 * a];
      mid_[a] = base + offsets_[3 * a + 1];
      end_[a] = base + offsets_[3 * a + 2];
    }
    total += used;
  }
  pair_count_ = total;
}

template class NeighbourList<2>;
template class NeighbourList<3>;

}  // namespace porosph::sph
