// The pair sums of the soil-water interaction (the formulas are in soil_water_interaction.h),
// for one dimension and kernel. One distance pass: each water overlap particle visits its soil
// neighbours (cross_neighbours.h, a cell list with a Verlet skin) and sums its own acceleration;
// the soil side of each pair (the force sum F_i = sum_a V_a f_ia W_ia and the saturation s_i =
// sum_a V_a W_ia) goes into a per-thread buffer, reduced per soil particle afterwards, where a_i =
// F_i / rho_i^s once s_i is known. Static OpenMP scheduling: the result does not depend on timing
// (only on the thread count). Every buffer is reused: no allocation in steady state.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "coupler/interaction/cross_neighbours.h"
#include "coupler/interaction/drag_step_weights.h"
#include "coupler/interaction/soil_water_interaction.h"
#include "coupler/interaction/wall_kernel_share.h"
#include "porous/seepage_law.h"
#include "porous/submerged_density.h"
#include "proto/coupling_client.h"
#include "sph/domain_box.h"
#include "sph/neighbour_list.h"
#include "sph/vector.h"
#include "sph/wall_occluders.h"

namespace porosph::coupler {

/// Per soil material: its seepage law, r_m of the submerged density and whether it is a fixed bed.
struct SoilMaterialTerms {
  porous::SeepageLaw law;
  double submerged_ratio = 1.0;
  bool fixed = false;
};

struct InteractionParameters {
  double h = 0.0;
  double c_a = 0.25;                  ///< eq. 21
  double unit_weight_water = 0.0;     ///< gamma_w = rho0_w |g| [N/m^3]
  double submerged_saturation = 0.8;  ///< coupling.submerged_saturation
  int threads = 0;                    ///< OpenMP threads of the sums; 0: OpenMP's default
  bool implicit_drag = true;          ///< also the drag rates (InteractionOutputs)
  DragStep drag_step = DragStep::kBackwardEuler;  ///< coupling.drag_step (drag_step_weights.h)
  std::vector<SoilMaterialTerms> materials;
  /// coupling.drag_at_walls = "renormalised": the fixed wall particles of the walls that hold
  /// neither water nor soil (n x D, flattened) and their volume dp^D (wall_kernel_share.h); empty:
  /// off.
  std::vector<double> soil_wall_points;
  double soil_wall_volume = 0.0;
};

class InteractionEngine {
 public:
  virtual ~InteractionEngine() = default;
  /// The sums for sets whose sizes the caller checked (both non-empty); `forces` false: the
  /// saturation only.
  virtual InteractionSummary compute(const coupling::StepState& water,
                                     const coupling::StepState& soil, bool forces,
                                     InteractionOutputs& out) = 0;
  /// After compute() with forces and rates: replaces the accelerations and forces in `out` by
  /// the pairwise implicit drag over the step dt (soil_water_interaction.h).
  virtual void implicit_drag(const coupling::StepState& water, const coupling::StepState& soil,
                             double dt, InteractionOutputs& out) = 0;
};

template <int D, class Kernel>
class SoilWaterSums final : public InteractionEngine {
 public:
  using Vec = sph::Vec<D>;
  /// Below this many particles a loop runs on one thread: a parallel region costs a few
  /// microseconds, far more on cores shared with the solver processes, and small sets (the first
  /// contact, the test dummies) do not need it.
  static constexpr std::int64_t kParallelFrom = 2048;
  /// Values per soil particle in the per-thread sums: F_i (D components), s_i, lambda_i rho_i^s.
  static constexpr int kStride = D + 2;

  /// `occluders`: the thin walls no pair crosses (sph/wall_occluders.h); `wall_tags`: the side
  /// tags of p.soil_wall_points (empty: all 0).
  SoilWaterSums(InteractionParameters parameters, const sph::DomainBox<D>& box,
                sph::WallOccluders<D> occluders = {}, std::vector<std::int32_t> wall_tags = {})
      : p_(std::move(parameters)),
        kernel_(p_.h),
        box_(box),
        occluders_(std::move(occluders)),
        walls_(std::move(p_.soil_wall_points), p_.soil_wall_volume, kernel_, box,
               sph::kSolverSkinFraction * kernel_.support(), std::move(wall_tags), occluders_) {
    grid_.set_skin(sph::kSolverSkinFraction * kernel_.support());
  }

  InteractionSummary compute(const coupling::StepState& water, const coupling::StepState& soil,
                             bool forces, InteractionOutputs& out) override {
    grid_.update(
        OverlapPoints{soil.overlap_id.data(), soil.overlap_position.data(), soil.overlap_id.size()},
        OverlapPoints{water.overlap_id.data(), water.overlap_position.data(),
                      water.overlap_id.size()},
        kernel_.support(), box_);
    gather_soil(soil, forces);
    walls_.compute(water, wall_scale_);  // 1 everywhere without renormalisation
    InteractionSummary summary;
    summary.evaluated = true;
    summary.forces = forces;
    double max_a2 = 0.0;
    summary.pair_count = water_pass(water, forces, out, max_a2);
    soil_pass(soil, forces, out, max_a2);
    summary.max_acceleration = std::sqrt(max_a2);
    if (forces && summary.max_acceleration > 0.0) {
      summary.dt_limit = p_.c_a * std::sqrt(p_.h / summary.max_acceleration);
    }
    return summary;
  }

 private:
  /// What the pair loop reads of one soil particle, in one cache line (2D): the random access
  /// per pair then touches one line instead of one per array.
  struct SoilPairData {
    Vec position;
    Vec velocity;
    double volume = 0.0;
    double a = 0.0, b = 0.0;    ///< gamma_w a, gamma_w b of eq. 13: 0 where no seepage acts (the
                                ///< law is "none", or only the saturation is asked)
    double solid_volume = 0.0;  ///< V_i (1 - n_i): its grains' volume (the water's porosity)
  };

  /// Copies what the pair loop needs of each soil particle (in the soil set's order).
  void gather_soil(const coupling::StepState& soil, bool forces) {
    const std::size_t n = grid_.soil_size();
    soil_.resize(n);
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) if (count >= kParallelFrom) num_threads(threads())
    for (std::int64_t s = 0; s < count; ++s) {
      const std::size_t i = static_cast<std::size_t>(s);
      SoilPairData& d = soil_[i];
      d.position = Eigen::Map<const Vec>(soil.overlap_position.data() + i * D);
      d.velocity = Eigen::Map<const Vec>(soil.overlap_velocity.data() + i * D);
      d.volume = soil.overlap_mass[i] / soil.overlap_density[i];
      d.solid_volume = d.volume * (1.0 - soil.overlap_porosity[i]);
      const porous::SeepageLaw& law = p_.materials[soil.overlap_material[i]].law;
      const porous::SeepageCoefficients c = forces && law.active()
                                                ? law.coefficients(soil.overlap_porosity[i])
                                                : porous::SeepageCoefficients{};
      d.a = p_.unit_weight_water * c.a;
      d.b = p_.unit_weight_water * c.b;
    }
  }

  /// Water accelerations, the soil partial sums per thread and the force on the water. Returns
  /// the number of pairs.
  std::size_t water_pass(const coupling::StepState& water, bool forces, InteractionOutputs& out,
                         double& max_a2) {
    const bool rates = forces && p_.implicit_drag;
    const std::int64_t n_water = static_cast<std::int64_t>(water.overlap_id.size());
    const std::size_t soil_values = grid_.soil_size() * kStride;
    const int max_threads = threads();
    if (static_cast<int>(partial_.size()) < max_threads) {
      partial_.resize(max_threads);
      pair_r_.resize(max_threads);
      pair_w_.resize(max_threads);
      near_soil_.resize(max_threads);
      near_w_.resize(max_threads);
    }
    const std::size_t max_candidates = grid_.max_candidate_count();
    if (forces) {
      out.water_acceleration.resize(water.overlap_id.size() * D);
    } else {
      out.water_acceleration.clear();
    }
    out.water_porosity.resize(water.overlap_id.size());
    if (rates) {
      out.water_rate.resize(water.overlap_id.size());
      near_thread_.resize(water.overlap_id.size());
      near_begin_.resize(water.overlap_id.size());
      near_count_.resize(water.overlap_id.size());
    } else {
      out.water_rate.clear();
    }
    std::size_t pairs = 0;
    const double support = kernel_.support();
    double force[D] = {}, magnitude = 0.0, a2_max = 0.0;
    threads_used_ = 1;
#pragma omp parallel reduction(+ : pairs, force[:D], magnitude) reduction(max : a2_max) \
    if (n_water >= kParallelFrom) num_threads(threads())
    {
      const int t = omp_get_thread_num();
#pragma omp single
      threads_used_ = omp_get_num_threads();
      std::vector<double>& acc = partial_[t];
      acc.assign(soil_values, 0.0);
      // One water particle's candidates at a time: distances, kernel values, then the sums.
      std::vector<double>& r = pair_r_[t];
      std::vector<double>& w = pair_w_[t];
      r.resize(max_candidates);
      w.resize(max_candidates);
      near_soil_[t].clear();
      near_w_[t].clear();
#pragma omp for schedule(static)
      for (std::int64_t a = 0; a < n_water; ++a) {
        const std::size_t count = grid_.candidate_count(a);
        const std::int32_t* soil_index = grid_.candidates(a);
        candidate_kernel_values(water, a, r.data(), w.data());
        std::size_t near = 0;
        for (std::size_t c = 0; c < count; ++c) near += r[c] < support;
        pairs += near;
        // The wall's share of the support renormalises the drag and porosity sums (not the
        // saturation): wall_kernel_share.h.
        const double wall_scale = wall_scale_[a];
        if (rates) remember_pairs(a, t, count, soil_index, w.data(), wall_scale);
        const Vec v_a = Eigen::Map<const Vec>(water.overlap_velocity.data() + a * D);
        const double rho_a = water.overlap_density[a];
        const double volume_a = water.overlap_mass[a] / rho_a;
        Vec sum = Vec::Zero();   // sum_i V_i f_ia W_ia
        double rate_sum = 0.0;   // sum_i V_i c_ia W_ia
        double solid_sum = 0.0;  // sum_i V_i (1 - n_i) W_ia
        // Distinct arrays: the soil rows written here alias neither the pair data nor the
        // kernel values, which lets the compiler keep each pair's values in registers.
        double* __restrict soil_rows = acc.data();
        const SoilPairData* __restrict pair_data = soil_.data();
        const double* __restrict kernel_w = w.data();
        for (std::size_t c = 0; c < count; ++c) {
          // No branch per pair: where no seepage acts a = b = 0, so f and its rate vanish, and
          // the rate column is summed also when no rates are asked (soil_pass ignores it then).
          const SoilPairData& soil_i = pair_data[soil_index[c]];
          const Vec v_r = v_a - soil_i.velocity;
          const Vec f = porous::seepage_force<D>(soil_i.a, soil_i.b, v_r);
          const double rate = porous::seepage_rate_coefficient<D>(soil_i.a, soil_i.b, v_r);
          const double weight = volume_a * kernel_w[c];
          const double w_drag = kernel_w[c] * wall_scale;
          const double weight_drag = volume_a * w_drag;
          double* soil_sums = soil_rows + static_cast<std::size_t>(soil_index[c]) * kStride;
          for (int k = 0; k < D; ++k) soil_sums[k] += weight_drag * f[k];
          soil_sums[D] += weight;
          soil_sums[D + 1] += weight_drag * rate;
          sum += (soil_i.volume * w_drag) * f;
          rate_sum += soil_i.volume * w_drag * rate;
          solid_sum += soil_i.solid_volume * w_drag;
        }
        out.water_porosity[a] = std::clamp(1.0 - solid_sum, 0.0, 1.0);
        if (!forces) continue;
        const Vec acceleration = -sum / rho_a;
        if (rates) out.water_rate[a] = rate_sum / rho_a;
        for (int k = 0; k < D; ++k) {
          out.water_acceleration[a * D + k] = acceleration[k];
          force[k] += water.overlap_mass[a] * acceleration[k];
        }
        magnitude += water.overlap_mass[a] * acceleration.norm();
        a2_max = std::max(a2_max, acceleration.squaredNorm());
      }
    }
    out.force_on_water.assign(force, force + D);
    out.force_magnitude_sum = magnitude;
    max_a2 = std::max(max_a2, a2_max);
    return pairs;
  }

  /// Reduces the per-thread soil sums: saturation, rho^s, soil accelerations, force on the soil.
  void soil_pass(const coupling::StepState& soil, bool forces, InteractionOutputs& out,
                 double& max_a2) {
    const bool rates = forces && p_.implicit_drag;
    const std::int64_t n = static_cast<std::int64_t>(grid_.soil_size());
    out.saturation.resize(n);
    if (forces) {
      out.soil_acceleration.resize(n * D);
    } else {
      out.soil_acceleration.clear();
    }
    if (rates) {
      out.soil_rate.resize(n);
    } else {
      out.soil_rate.clear();
    }
    effective_mass_.resize(n);
    const int partials = threads_used_;  // per-thread buffers the water pass filled
    double force[D] = {}, magnitude = 0.0, a2_max = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : force[:D], magnitude) \
    reduction(max : a2_max) if (n >= kParallelFrom) num_threads(threads())
    for (std::int64_t s = 0; s < n; ++s) {
      double sums[kStride] = {};
      for (int t = 0; t < partials; ++t) {
        const double* part = partial_[t].data() + s * kStride;
        for (int k = 0; k < kStride; ++k) sums[k] += part[k];
      }
      const std::size_t i = static_cast<std::size_t>(s);
      out.saturation[i] = sums[D];
      if (!forces) continue;
      const SoilMaterialTerms& material = p_.materials[soil.overlap_material[i]];
      const double rho = soil.overlap_density[i];
      const double rho_s = porous::submerged_density(rho, sums[D], p_.submerged_saturation,
                                                     material.submerged_ratio);
      const double effective_mass = soil.overlap_mass[i] * rho_s / rho;  // m_i^s
      effective_mass_[i] = effective_mass;
      Vec acceleration;
      for (int k = 0; k < D; ++k) acceleration[k] = sums[k] / rho_s;
      // A fixed bed never moves: no rate of its own (infinite inertia) in the pair's implicit
      // denominator.
      if (rates) out.soil_rate[i] = material.fixed ? 0.0 : sums[D + 1] / rho_s;
      for (int k = 0; k < D; ++k) {
        out.soil_acceleration[i * D + k] = acceleration[k];
        force[k] += effective_mass * acceleration[k];
      }
      magnitude += effective_mass * acceleration.norm();
      if (!material.fixed) a2_max = std::max(a2_max, acceleration.squaredNorm());
    }
    out.force_on_soil.assign(force, force + D);
    out.force_magnitude_sum += magnitude;
    max_a2 = std::max(max_a2, a2_max);
  }

 public:
  void implicit_drag(const coupling::StepState& water, const coupling::StepState& soil, double dt,
                     InteractionOutputs& out) override;  // soil_water_implicit.h

 private:
  /// Keeps water particle a's pairs within the support (soil index, W times the wall scale) in
  /// thread t's lists, for implicit_drag() after dt is known.
  void remember_pairs(std::int64_t a, int t, std::size_t count, const std::int32_t* soil_index,
                      const double* w, double scale) {
    near_thread_[a] = t;
    near_begin_[a] = near_soil_[t].size();
    for (std::size_t c = 0; c < count; ++c) {
      if (!(w[c] > 0.0)) continue;
      near_soil_[t].push_back(soil_index[c]);
      near_w_[t].push_back(w[c] * scale);
    }
    near_count_[a] = near_soil_[t].size() - near_begin_[a];
  }

  /// Distances r and kernel values w (0 beyond the support) of water particle a's soil
  /// candidates, in the grid's candidate order.
  void candidate_kernel_values(const coupling::StepState& water, std::int64_t a, double* r,
                               double* w) const {
    const std::size_t count = grid_.candidate_count(a);
    const std::int32_t* soil_index = grid_.candidates(a);
    const Vec x_a = Eigen::Map<const Vec>(water.overlap_position.data() + a * D);
    for (std::size_t c = 0; c < count; ++c) {
      Vec dx = x_a - soil_[soil_index[c]].position;
      box_.minimum_image(dx);
      r[c] = dx.squaredNorm();
    }
    if (!occluders_.empty()) {  // a pair across a thin wall: out of reach (W = 0, not near)
      for (std::size_t c = 0; c < count; ++c) {
        Vec dx = x_a - soil_[soil_index[c]].position;
        box_.minimum_image(dx);
        if (occluders_.hides(x_a, 0, x_a - dx, 0)) r[c] = std::numeric_limits<double>::infinity();
      }
    }
    for (std::size_t c = 0; c < count; ++c) {  // vectorises: no data-dependent branch
      r[c] = std::sqrt(r[c]);
      w[c] = kernel_.w(r[c]);
    }
  }

  /// The velocity of each overlap particle at the end of the step without the interaction:
  /// update_base + dt update_rate as the solver sent them, else its velocity (a solver that sends
  /// neither: the drag at v^n).
  static void predict(const coupling::StepState& s, double dt, std::vector<Vec>& out) {
    const std::size_t n = s.overlap_id.size();
    out.resize(n);
    const bool sent =
        s.overlap_update_base.size() == n * D && s.overlap_update_rate.size() == n * D;
    for (std::size_t i = 0; i < n; ++i) {
      out[i] = sent ? Vec(Eigen::Map<const Vec>(s.overlap_update_base.data() + i * D) +
                          dt * Eigen::Map<const Vec>(s.overlap_update_rate.data() + i * D))
                    : Vec(Eigen::Map<const Vec>(s.overlap_velocity.data() + i * D));
    }
  }

  /// The thread count of the parallel loops: InteractionParameters::threads, or OpenMP's default.
  int threads() const { return p_.threads > 0 ? p_.threads : omp_get_max_threads(); }

  InteractionParameters p_;
  Kernel kernel_;
  sph::DomainBox<D> box_;
  CrossNeighbours<D> grid_;
  sph::WallOccluders<D> occluders_;   ///< thin walls: no pair across them
  WallKernelShare<D, Kernel> walls_;  ///< coupling.drag_at_walls (no points: scale 1)
  std::vector<double> wall_scale_;    ///< per water overlap particle: 1 / (1 - S_wall)
  std::vector<SoilPairData> soil_;
  std::vector<double> effective_mass_;                 ///< m_i^s per soil overlap particle
  std::vector<Vec> water_predicted_, soil_predicted_;  ///< implicit_drag(): v* per particle
  std::vector<std::vector<double>> partial_;  ///< per thread: kStride sums per soil particle
  std::vector<std::vector<double>> pair_r_, pair_w_;  ///< per thread: r, W of one particle's pairs
  /// compute()'s pairs within the support, for implicit_drag(): per thread the soil index and W of
  /// its water particles' pairs; per water particle the thread, the first pair and the count.
  std::vector<std::vector<std::int32_t>> near_soil_;
  std::vector<std::vector<double>> near_w_;
  std::vector<int> near_thread_;
  std::vector<std::size_t> near_begin_, near_count_;
  int threads_used_ = 1;
};

}  // namespace porosph::coupler

#include "coupler/interaction/soil_water_implicit.h"  // IWYU pragma: keep
