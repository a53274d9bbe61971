#include "coupler/interaction/overlap_region.h"

#include <cmath>

namespace porosph::coupler {

void overlap_region_for(const coupling::StepState& other, const scene::Scene& scene,
                        std::vector<double>& min, std::vector<double>& max) {
  const std::size_t d = static_cast<std::size_t>(scene.run.dimension);
  min.clear();
  max.clear();
  if (other.region_min.size() != d || other.region_max.size() != d) return;
  for (std::size_t k = 0; k < d; ++k) {
    if (!(other.region_min[k] <= other.region_max[k])) return;  // empty (or NaN)
  }
  const double support = 2.0 * scene.h();
  for (std::size_t k = 0; k < d; ++k) {
    const bool periodic = k < scene.run.periodic.size() && scene.run.periodic[k] &&
                          k < scene.domain.min.size() && k < scene.domain.max.size();
    min.push_back(periodic ? scene.domain.min[k] : other.region_min[k] - support);
    max.push_back(periodic ? scene.domain.max[k] : other.region_max[k] + support);
  }
}

}  // namespace porosph::coupler
