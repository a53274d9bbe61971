// Particles of the water solver, structure of arrays. Indices [0, n_free) are water particles,
// [n_free, size()) fixed wall particles. Ids are stable across removal and re-ordering.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid_solver/diffusion_state.h"
#include "sph/permutation_scratch.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
struct WaterParticles {
  using Vec = sph::Vec<D>;
  std::size_t n_free = 0;

  std::vector<Vec> position, velocity;
  std::vector<Vec> velocity_previous;  ///< v^{n-1} of the modified Verlet scheme
  std::vector<Vec> acceleration;       ///< internal dv/dt of this step (incl. gravity)
  std::vector<Vec> interaction;        ///< acceleration added by the coupler (last step)
  std::vector<Vec> wall_velocity;      ///< walls: velocity seen by viscous terms (Adami 2012)
  /// The share s_a in [0, 1] of the artificial viscosity that the seepage drag replaces at a water
  /// particle, from the drag rate the coupler sent with the last command (artificial_viscosity.h):
  /// 0 in free water, for walls and after any resize (array resizes fill 0).
  std::vector<double> viscosity_cut;
  /// The seepage drag rate lambda_a [1/s] the coupler sent with the last command (0 in free
  /// water, for walls and after any resize): the hydrostatic difference form's weight
  /// (hydrostatic_difference.h) compares it with its neighbours'.
  std::vector<double> drag_rate;
  std::vector<double> density, density_previous, density_rate;
  std::vector<double> pressure, sound_speed, mass;
  std::vector<double> remove_at;  ///< walls: removal time [s] (< 0: never); water: -1
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> fixed;  ///< 1 for wall particles (snapshot field "fixed")
  /// Index of the inflow zone (scene water.inflows) whose prescribed velocity a water particle
  /// follows (flow_zones.h); -1 for free water and for walls. Array resizes fill 0: set it.
  std::vector<std::int32_t> zone;
  /// Walls: index of the moving wall it belongs to (moving_walls.h); -1 for fixed walls and water.
  std::vector<std::int32_t> wall_motion;
  /// Walls: the side of a thin wall whose water sees it (sph::wall_side_tag; 0 for water and for
  /// the particles of other walls). Array resizes fill 0.
  std::vector<std::int32_t> wall_side;

  // Derived per step, not part of the particle state (not resized, permuted or checkpointed with
  // the arrays above; whoever fills them sizes them):
  /// 1 / rho and m / rho of every particle, from density and mass at the start of each rate
  /// evaluation (water_rates.h), so that the pair loop multiplies instead of dividing.
  std::vector<double> inverse_density, volume;
  /// Per water particle: the kernel gradient's renormalisation s_a (particle_gradient.h; 1 unless
  /// run.kernel_gradient = "particle"), filled at the start of each rate evaluation.
  std::vector<double> gradient_scale;
  /// Per water particle: the kernel gradient's correction matrix C_a (particle_gradient.h) with
  /// run.kernel_gradient = "particle_matrix", filled at the start of each rate evaluation; empty
  /// otherwise.
  std::vector<Eigen::Matrix<double, D, D>> gradient_matrix;
  /// Per water particle: the drag weight s_a (drag_weight.h) of the hydrostatic difference form
  /// and the drag-replaced artificial viscosity, filled at the start of each rate evaluation when
  /// either is on; empty otherwise.
  std::vector<double> drag_weight;
  /// Renormalised gradient of the density diffusion's departure potential (water particles only;
  /// density_diffusion_gradient.h), filled before the pair loop when the diffusion is on.
  std::vector<Vec> departure_gradient;
  /// The density diffusion's per-particle state (water particles only), filled with it.
  std::vector<DiffusionState> diffusion_state;
  /// Per water particle: the part of `acceleration` from its wall neighbours (pressure and
  /// viscous terms; water_rates.h), filled with it: the walls' impulse in the solver's books.
  std::vector<Vec> wall_acceleration;
  /// Per water particle: the part of `acceleration` by which the hydrostatic difference form
  /// inside soil departs from the antisymmetric pressure pairs (hydrostatic_difference.h; 0
  /// elsewhere), filled with it: an internal force that is booked, not conserved.
  std::vector<Vec> pressure_form_acceleration;

  std::size_t size() const { return position.size(); }
  std::size_t wall_count() const { return size() - n_free; }

  /// Calls fn(array) on every per-particle array (to resize, permute or compact them together).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    apply_to_arrays(fn, *this);
  }
  /// Calls fn(array, other's same array) on every per-particle array.
  template <class Fn>
  void for_each_array_with(const WaterParticles& other, Fn&& fn) {
    apply_to_arrays(fn, *this, other);
  }

  /// Appends a copy of particle i of `source` (every array) at the end; n_free is unchanged.
  void append_copy(const WaterParticles& source, std::size_t i) {
    for_each_array_with(source, [i](auto& array, const auto& from) { array.push_back(from[i]); });
  }

  /// Inserts every particle of `born` as water particles at [n_free, n_free + born.size()) (the
  /// walls move up, in order); n_free grows. Allocates only when an array's capacity is exceeded.
  void insert_free(const WaterParticles& born) {
    const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(n_free);
    for_each_array_with(born, [at](auto& array, const auto& from) {
      array.insert(array.begin() + at, from.begin(), from.end());
    });
    n_free += born.size();
  }

  /// Reserves room for `capacity` particles in every array.
  void reserve(std::size_t capacity) {
    for_each_array([capacity](auto& array) { array.reserve(capacity); });
  }

  /// Re-orders every array: new[i] = old[order[i]]; `order` must keep water before walls.
  /// Capacities are kept (the scratch buffers take the arrays' capacity).
  void permute(const std::vector<std::int32_t>& order) {
    for_each_array([&](auto& array) { scratch_.permute(array, order); });
  }

 private:
  /// The one list of the per-particle arrays: fn(p.array...) for each array of every p.
  template <class Fn, class... Particles>
  static void apply_to_arrays(Fn& fn, Particles&... p) {
    fn(p.position...), fn(p.velocity...), fn(p.velocity_previous...), fn(p.acceleration...);
    fn(p.interaction...), fn(p.wall_velocity...), fn(p.density...), fn(p.density_previous...);
    fn(p.density_rate...), fn(p.pressure...), fn(p.sound_speed...), fn(p.mass...);
    fn(p.remove_at...), fn(p.id...), fn(p.fixed...), fn(p.zone...), fn(p.viscosity_cut...);
    fn(p.drag_rate...), fn(p.wall_motion...), fn(p.wall_side...);
  }

  sph::PermutationScratch<Vec, double, std::int64_t, std::int32_t, std::uint8_t> scratch_;
};

}  // namespace porosph::water
