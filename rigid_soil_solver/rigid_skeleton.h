// The particles of a rigid porous skeleton: soil that never moves, never deforms and carries no
// stress, but whose porosity, density and mass the coupler needs for the seepage force (seed eq.
// 13-16). Structure of arrays; every particle is fixed (n_free = 0), ids are the fill order.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::rigid_soil {

template <int D>
struct RigidSkeleton {
  using Vec = sph::Vec<D>;
  /// Always 0: the skeleton has no free particle (kept for sph/checkpoint_arrays.h, and because
  /// every per-phase figure of the protocol is one of the free particles).
  std::size_t n_free = 0;

  std::vector<Vec> position;          ///< lattice point, for the whole run [m]
  std::vector<double> density;        ///< the material's bulk density [kg/m^3]
  std::vector<double> mass;           ///< density dp^D [kg] (per metre in 2D)
  std::vector<double> porosity;       ///< the material's n0 (a rigid skeleton keeps it)
  std::vector<double> saturation;     ///< water volume fraction around it (from the coupler)
  std::vector<Vec> absorbed_impulse;  ///< sum over steps of m^s a dt [N s]: the drag it took up
  std::vector<std::int64_t> id;
  std::vector<std::int64_t> material;  ///< index into scene.soil.materials
  std::vector<std::uint8_t> fixed;     ///< 1 for every particle (snapshot field "fixed")

  std::size_t size() const { return position.size(); }

  /// Calls fn(array) on every per-particle array (checkpoints store them in this order).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(position), fn(density), fn(mass), fn(porosity), fn(saturation), fn(absorbed_impulse);
    fn(id), fn(material), fn(fixed);
  }
};

/// The skeleton of scene.soil.blocks, on the lattice the built-in soil_solver uses
/// (sph/geometry.h): points inside the soil's walls, outside the domain or already in an earlier
/// block are skipped. Every material is rigid, whatever its `fixed` key says. Mass rho dp^D,
/// porosity n0, saturation and absorbed impulse 0. Throws std::invalid_argument when the scene has
/// no soil or a block names an unknown material.
template <int D>
RigidSkeleton<D> build_rigid_skeleton(const scene::Scene& scene);

extern template RigidSkeleton<2> build_rigid_skeleton<2>(const scene::Scene&);
extern template RigidSkeleton<3> build_rigid_skeleton<3>(const scene::Scene&);

}  // namespace porosph::rigid_soil
