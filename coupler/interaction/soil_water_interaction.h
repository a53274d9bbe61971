// The soil-water interaction the coupler computes each step (docs/design.md section 1 step 3; seed
// eq. 13-17, 20): for every soil-water pair within the kernel support 2h, the seepage force per
// unit soil volume f_ia of eq. 13 (seepage_force.h), and from it
//   soil  i:  a_i =  sum_a V_a f_ia W_ia / rho_i^s          (eq. 16, last term)
//   water a:  a_a = -sum_i V_i f_ia W_ia / rho_a            (eq. 17, last term)
// with V = m / rho and rho_i^s the submerged density of submerged_density.h, decided from the
// saturation s_i = sum_a V_a W_ia (the kernel-weighted water volume fraction, ~1 inside water).
// Eq. 17 of the paper writes the water term with m_i / rho_i^s; PoroSPH uses the soil particle's
// volume V_i = m_i / rho_i, so that the pair impulse is antisymmetric: with the soil particle's
// effective mass m_i^s = m_i rho_i^s / rho_i, m_i^s a_i and m_a a_a cancel pair by pair (the water
// feels exactly the reaction of the drag it exerts on the soil volume V_i).
// Fixed soil (a rigid porous bed) exchanges drag like free soil; the soil solver ignores the
// acceleration it is sent, the bed absorbs that impulse.
//
// Implicit drag (coupling.implicit_drag, default; docs/coupling.md): once dt is known, each pair's
// force is taken at the end of the step, linearised (one backward-Euler step of the pair's
// relative velocity, the other pairs' rates on the diagonal):
//   F_ia = V_a V_i W_ia f(v*_a - v*_i) / (1 + dt (lambda_a + lambda_i))     (force on the soil)
// with v* = update_base + dt update_rate the velocity each solver would reach without the
// interaction (StepState) and lambda the particles' drag rates. The water gets -F_ia, the soil
// +F_ia: the exchange is antisymmetric pair by pair, so the total momentum is kept to round-off
// whatever lambda dt, and the solvers add the accelerations explicitly (dt a_int is exactly the
// impulse booked). For lambda dt << 1 it is the explicit drag at the predicted velocities; for
// lambda dt >> 1 the pair relaxes to its terminal relative velocity in one step without
// overshoot, and a steady state (f balancing the other forces) is kept exactly.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "proto/coupling_client.h"
#include "scene/scene.h"
#include "sph/damping_stage.h"

namespace porosph::coupler {

class InteractionEngine;  // soil_water_sums.h

/// What one evaluation leaves for the coupler to send and to book.
struct InteractionOutputs {
  std::vector<double> water_acceleration;  ///< n_water x D, order of water.overlap_id; empty: none
  std::vector<double> soil_acceleration;   ///< n_soil x D, order of soil.overlap_id; empty: none
  std::vector<double> saturation;          ///< s_i per soil overlap particle; empty: none
  /// n_a = 1 - sum_i V_i (1 - n_i) W_ia per water overlap particle, clamped to [0, 1]: the soil
  /// porosity the water sees (1 in free water); empty: none. Output only (StepCommand.porosity).
  std::vector<double> water_porosity;
  /// The drag's rate lambda = -d a / d v_own [1/s] per overlap particle (coupling.implicit_drag;
  /// empty: off or no force): lambda_a = sum_i V_i c_ia W_ia / rho_a and lambda_i = sum_a V_a
  /// c_ia W_ia / rho_i^s, c_ia = gamma_w (a + 2 b |v_r|) the derivative of eq. 13 along v_r.
  std::vector<double> water_rate, soil_rate;
  std::vector<double> force_on_water;  ///< sum_a m_a a_a [N] (D components)
  std::vector<double> force_on_soil;   ///< sum_i m_i^s a_i [N], fixed soil included
  /// The same sums of the explicit drag at the velocities of the state (eq. 13-17 as the paper
  /// integrates them): with the implicit drag the ledger books force_on_* and reports the
  /// difference as the implicit share.
  std::vector<double> explicit_force_on_water, explicit_force_on_soil;
  double force_magnitude_sum = 0.0;  ///< sum_i |m_i^s a_i| + sum_a |m_a a_a| [N]
};

/// What one evaluation found.
struct InteractionSummary {
  bool evaluated = false;         ///< both overlap sets were non-empty
  bool forces = false;            ///< accelerations were computed (false in the damping stage)
  std::size_t pair_count = 0;     ///< soil-water pairs with r < 2h
  double max_acceleration = 0.0;  ///< max |a| over the water and free-soil overlap [m/s^2]
  /// Eq. 21 for the interaction: C_a sqrt(h / max |a|) [s]; infinity without force.
  double dt_limit = std::numeric_limits<double>::infinity();
};

class SoilWaterInteraction {
 public:
  /// Reads h, the kernel, run.c_a, gravity, the periodic domain, the water's rho0 and viscosity
  /// (nu = viscosity / rho0), coupling.submerged_saturation, soil.damping_duration and every soil
  /// material's seepage law. Throws std::invalid_argument if the scene lacks water or soil or a
  /// material's seepage law cannot be evaluated (e.g. Kozeny-Carman with zero water viscosity).
  /// `threads`: OpenMP threads of the pair sums (0: OpenMP's default).
  explicit SoilWaterInteraction(const scene::Scene& scene, int threads = 0);
  ~SoilWaterInteraction();
  SoilWaterInteraction(const SoilWaterInteraction&) = delete;
  SoilWaterInteraction& operator=(const SoilWaterInteraction&) = delete;

  /// Evaluates the interaction between the water and soil overlap sets of one step at simulated
  /// time `time`. While time < soil.damping_duration only the saturation is computed (the soil
  /// settles under its submerged weight) and the accelerations are left empty. When either set is
  /// empty every output is empty. Throws std::runtime_error naming the phase if an overlap array
  /// has the wrong size or a soil material index is out of range.
  InteractionSummary compute(const coupling::StepState& water, const coupling::StepState& soil,
                             double time);

  /// With the implicit drag, after compute() found forces: the accelerations and forces of the
  /// pairwise implicit drag over the step `dt` (see above); the explicit ones stay in
  /// explicit_force_on_*. Without: the explicit forces are copied there and nothing changes.
  void finish_step(const coupling::StepState& water, const coupling::StepState& soil, double dt);

  /// The results of the last compute (see InteractionOutputs); the vectors are reused.
  const InteractionOutputs& outputs() const { return out_; }
  const std::vector<double>& water_acceleration() const { return out_.water_acceleration; }
  const std::vector<double>& soil_acceleration() const { return out_.soil_acceleration; }
  const std::vector<double>& saturation() const { return out_.saturation; }
  const std::vector<double>& water_rate() const { return out_.water_rate; }
  const std::vector<double>& soil_rate() const { return out_.soil_rate; }
  /// Hands the phase's accelerations (and for the soil its saturation) of the last compute to a
  /// step command by swapping buffers, no copy: afterwards those outputs hold the command's old
  /// arrays until the next compute() overwrites them.
  void hand_over(bool soil, std::vector<double>& acceleration, std::vector<double>& saturation) {
    acceleration.swap(soil ? out_.soil_acceleration : out_.water_acceleration);
    if (soil) saturation.swap(out_.saturation);
  }
  /// Hands the water's porosity of the last compute (InteractionOutputs::water_porosity) to a
  /// step command, by swapping buffers like hand_over().
  void hand_over_porosity(std::vector<double>& porosity) { porosity.swap(out_.water_porosity); }
  /// Hands the water's drag rates of the last compute (InteractionOutputs::water_rate; empty
  /// without implicit drag) to a step command, by swapping buffers like hand_over(): the water
  /// solver scales its artificial viscosity by them (fluid_solver/artificial_viscosity.h).
  void hand_over_water_rate(std::vector<double>& rate) { rate.swap(out_.water_rate); }
  /// The interaction terms of the scene (run.json interaction.terms; scene/term_registry.h).
  const std::vector<std::string>& terms() const { return terms_; }

 private:
  void check_sizes(const coupling::StepState& state, const char* phase, bool soil) const;

  std::unique_ptr<InteractionEngine> engine_;
  bool implicit_drag_ = true;
  bool forces_ = false;  ///< the last compute() computed forces
  std::vector<std::string> terms_;
  int dimension_ = 2;
  sph::DampingStage damping_;  ///< soil.damping_duration: no seepage forces in the stage
  std::size_t material_count_ = 0;
  InteractionOutputs out_;
};

}  // namespace porosph::coupler
