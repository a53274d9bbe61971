#include "rigid_soil_solver/rigid_skeleton.h"

#include <cmath>
#include <stdexcept>

#include "sph/domain_box.h"
#include "sph/geometry.h"

namespace porosph::rigid_soil {

template <int D>
RigidSkeleton<D> build_rigid_skeleton(const scene::Scene& scene) {
  if (!scene.has_soil()) throw std::invalid_argument("the scene has no [soil]");
  const scene::SoilPhase& soil = *scene.soil;
  const double dp = scene.run.dp;
  const double volume = std::pow(dp, D);
  const auto box = sph::DomainBox<D>::from_scene(scene, 2.0 * scene.h());
  const std::vector<scene::Shape> walls = scene.walls_acting_on("soil");
  RigidSkeleton<D> skeleton;
  for (std::size_t b = 0; b < soil.blocks.size(); ++b) {
    const scene::Shape& block = soil.blocks[b];
    const int material = soil.material_index(block.material);
    if (material < 0) {
      throw std::invalid_argument("soil block '" + block.label + "': unknown material '" +
                                  block.material + "'");
    }
    const scene::SoilMaterial& m = soil.materials[material];
    for (const sph::Vec<D>& x : sph::fill_block_outside_walls<D>(block, walls, dp)) {
      sph::Vec<D> wrapped = x;
      box.wrap(wrapped);
      if (box.outside(x) || wrapped != x) continue;
      bool taken = false;  // an earlier block holds this lattice point
      for (std::size_t e = 0; e < b && !taken; ++e)
        taken = sph::inside_shape<D>(soil.blocks[e], x, dp);
      if (taken) continue;
      skeleton.position.push_back(x);
      skeleton.density.push_back(m.density);
      skeleton.mass.push_back(m.density * volume);
      skeleton.porosity.push_back(m.porosity);
      skeleton.saturation.push_back(0.0);
      skeleton.absorbed_impulse.push_back(sph::Vec<D>::Zero());
      skeleton.id.push_back(static_cast<std::int64_t>(skeleton.id.size()));
      skeleton.material.push_back(material);
      skeleton.fixed.push_back(1);
    }
  }
  return skeleton;
}

template RigidSkeleton<2> build_rigid_skeleton<2>(const scene::Scene&);
template RigidSkeleton<3> build_rigid_skeleton<3>(const scene::Scene&);

}  // namespace porosph::rigid_soil
