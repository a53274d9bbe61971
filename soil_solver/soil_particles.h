// Particles of the soil solver, structure of arrays. Indices [0, n_free) are free soil particles,
// [n_free, size()) fixed particles: wall particles (material -1) and fixed soil (a rigid porous
// bed, material >= 0). Ids are stable across removal and re-ordering.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "sph/permutation_scratch.h"
#include "sph/vector.h"

namespace porosph::soil {

template <int D>
struct SoilParticles {
  using Vec = sph::Vec<D>;
  using Tensor = Eigen::Matrix3d;
  std::size_t n_free = 0;

  std::vector<Vec> position, velocity;
  std::vector<Vec> acceleration;   ///< internal dv/dt of this step (incl. gravity)
  std::vector<Vec> interaction;    ///< acceleration added by the coupler (last step)
  std::vector<Vec> wall_velocity;  ///< fixed: velocity seen by the viscous terms (mirrored)
  std::vector<Vec> displacement;   ///< integral of v dt since t = 0 (periodic-safe)
  std::vector<Vec>
      wall_normal;             ///< fixed: geometric normal (wall_normals.h; 0 corner, NaN unknown)
  std::vector<Tensor> stress;  ///< sigma, tension positive, plane strain in 2D [Pa]
  std::vector<Tensor> velocity_gradient;  ///< L = dv/dx of this step (eq. 7-8), 3x3 embedded
  std::vector<Tensor> artificial_stress;  ///< R of Gray et al. 2001 (zero when off)
  std::vector<double> density, density_rate, reference_density, mass;
  std::vector<double> porosity;        ///< eq. 20, from the density
  std::vector<double> plastic_strain;  ///< accumulated plastic multiplier lambda [-]
  std::vector<double> saturation;      ///< water volume fraction around it (coupler; 0 when far)
  std::vector<double> weight_ratio;    ///< rho^s / rho: submerged_ratio when submerged, else 1
  std::vector<double> remove_at;       ///< walls: removal time [s] (< 0: never)
  std::vector<std::int64_t> id;
  std::vector<std::int64_t> material;  ///< index into SoilParams::materials; -1 for walls
  std::vector<std::uint8_t> fixed;     ///< 1 for fixed particles (snapshot field "fixed")
  std::vector<std::uint8_t> no_slip;   ///< fixed: 1 no-slip, 0 free-slip
  /// fixed: 1 inside a straight stretch of wall (straight_walls.h; 0 in checkpoints before it)
  std::vector<std::uint8_t> straight_wall;
  std::vector<std::uint8_t> wet;   ///< has touched water (sticky; wet_cohesion_loss)
  std::vector<std::int32_t> load;  ///< index of the surface load it carries; -1: none
  /// Walls: the side of a thin wall whose soil sees it (sph::wall_side_tag; 0 for soil and for the
  /// particles of other walls).
  std::vector<std::int32_t> wall_side;

  // Derived per step, not part of the particle state (not resized, permuted or checkpointed with
  // the arrays above; whoever fills them sizes them):
  /// 1 where R != 0 (some principal stress in tension; update_artificial_stress): pairs of two 0
  /// particles skip the artificial-stress term.
  std::vector<std::uint8_t> in_tension;
  /// Per free particle: the part of `acceleration` from its fixed neighbours (walls, fixed soil;
  /// soil_rates.h), filled with it: the walls' impulse in the solver's books.
  std::vector<Vec> wall_acceleration;
  /// Per free particle: sum_j (r_i - r_j) / 2 a_ij over its free neighbours j of the artificial
  /// stress and viscosity terms a_ij (r = weight_ratio), filled with `acceleration`: what these
  /// terms, not antisymmetric in the effective mass r m across a water surface, add to the soil's
  /// momentum (soil_impulse_book.h).
  std::vector<Vec> submergence_acceleration;

  std::size_t size() const { return position.size(); }

  /// Calls fn(array) on every per-particle array (to resize, permute or compact them together).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(position), fn(velocity), fn(acceleration), fn(interaction), fn(wall_velocity);
    fn(displacement), fn(wall_normal), fn(stress), fn(velocity_gradient), fn(artificial_stress),
        fn(density);
    fn(density_rate), fn(reference_density), fn(mass), fn(porosity), fn(plastic_strain);
    fn(saturation), fn(weight_ratio), fn(wet);
    fn(remove_at), fn(id), fn(material), fn(fixed), fn(no_slip), fn(load), fn(wall_side);
    fn(straight_wall);
  }

  /// Re-orders every array: new[i] = old[order[i]]; `order` must keep free before fixed.
  /// Uses one scratch buffer per element type (no allocation once they have grown).
  void permute(const std::vector<std::int32_t>& order) {
    for_each_array([&](auto& array) { scratch_.permute(array, order); });
  }

 private:
  sph::PermutationScratch<Vec, Tensor, double, std::int64_t, std::uint8_t, std::int32_t> scratch_;
};

}  // namespace porosph::soil
