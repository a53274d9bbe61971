// The second pass of the soil-water interaction (SoilWaterSums, soil_water_sums.h), once the
// step's dt is known: the pairwise implicit drag of soil_water_interaction.h,
//   F_ia = V_a V_i W_ia f(v*_a - v*_i) / (1 + dt (lambda_a + lambda_i))      (force on soil i),
// over the pairs the first pass kept (soil index and W), with the rates lambda it summed
// (coupling.drag_step = "backward_euler"), or with the exponential step's weights of
// drag_step_weights.h on f(v^n) and f(v*) - f(v^n) ("exponential").
#pragma once

#include "coupler/interaction/soil_water_sums.h"

namespace porosph::coupler {

template <int D, class Kernel>
void SoilWaterSums<D, Kernel>::implicit_drag(const coupling::StepState& water,
                                             const coupling::StepState& soil, double dt,
                                             InteractionOutputs& out) {
  const std::int64_t n_water = static_cast<std::int64_t>(water.overlap_id.size());
  const std::size_t n_soil = grid_.soil_size();
  predict(water, dt, water_predicted_);
  predict(soil, dt, soil_predicted_);
  const double* water_velocity = water.overlap_velocity.data();  // v^n, for "exponential"
  const double* soil_velocity = soil.overlap_velocity.data();
  const int max_threads = threads();
  double water_force[D] = {};
  threads_used_ = 1;
#pragma omp parallel reduction(+ : water_force[:D]) if (n_water >= kParallelFrom) \
    num_threads(max_threads)
  {
    const int t = omp_get_thread_num();
#pragma omp single
    threads_used_ = omp_get_num_threads();
    std::vector<double>& acc = partial_[t];
    acc.assign(n_soil * D, 0.0);
#pragma omp for schedule(static)
    for (std::int64_t a = 0; a < n_water; ++a) {
      // The pairs within the support that compute() found (same order, same kernel values).
      const std::size_t count = near_count_[a];
      const std::int32_t* soil_index = near_soil_[near_thread_[a]].data() + near_begin_[a];
      const double* w = near_w_[near_thread_[a]].data() + near_begin_[a];
      const double volume_a = water.overlap_mass[a] / water.overlap_density[a];
      const double rate_a = out.water_rate[a];
      Vec on_water = Vec::Zero();
      for (std::size_t c = 0; c < count; ++c) {
        const std::int32_t i = soil_index[c];
        const SoilPairData& soil_i = soil_[i];
        // Force on the soil of the pair [N / m^(3-D)]: eq. 13 at the predicted relative
        // velocity, over 1 + dt (lambda_a + lambda_i) (one backward-Euler step of the pair's
        // relative velocity, linearised; soil_water_interaction.h).
        const Vec v_r = water_predicted_[a] - soil_predicted_[i];
        const double scale = volume_a * soil_i.volume * w[c];
        const double x = dt * (rate_a + out.soil_rate[i]);
        Vec f;
        if (p_.drag_step == DragStep::kBackwardEuler) {
          f = porous::seepage_force<D>(soil_i.a, soil_i.b, v_r) * (scale / (1.0 + x));
        } else {  // the exact mean over the step of the linearised pair (drag_step_weights.h)
          const Vec v_r0 = Eigen::Map<const Vec>(water_velocity + a * D) -
                           Eigen::Map<const Vec>(soil_velocity + i * D);
          const Vec f0 = porous::seepage_force<D>(soil_i.a, soil_i.b, v_r0);
          const DragStepWeights weight = drag_step_weights(DragStep::kExponential, x);
          f = (weight.start * f0 +
               weight.change * (porous::seepage_force<D>(soil_i.a, soil_i.b, v_r) - f0)) *
              scale;
        }
        double* soil_sums = acc.data() + static_cast<std::size_t>(i) * D;
        for (int k = 0; k < D; ++k) soil_sums[k] += f[k];
        on_water -= f;
      }
      for (int k = 0; k < D; ++k) {
        out.water_acceleration[a * D + k] = on_water[k] / water.overlap_mass[a];
        water_force[k] += on_water[k];
      }
    }
  }
  double soil_force[D] = {}, magnitude = 0.0;
  for (std::int64_t a = 0; a < n_water; ++a) {
    magnitude +=
        water.overlap_mass[a] * Eigen::Map<const Vec>(out.water_acceleration.data() + a * D).norm();
  }
  for (std::size_t i = 0; i < n_soil; ++i) {
    Vec force = Vec::Zero();
    for (int t = 0; t < threads_used_; ++t)
      force += Eigen::Map<const Vec>(partial_[t].data() + i * D);
    for (int k = 0; k < D; ++k) {
      out.soil_acceleration[i * D + k] = force[k] / effective_mass_[i];
      soil_force[k] += force[k];
    }
    magnitude += force.norm();
  }
  out.force_on_water.assign(water_force, water_force + D);
  out.force_on_soil.assign(soil_force, soil_force + D);
  out.force_magnitude_sum = magnitude;
}

}  // namespace porosph::coupler
