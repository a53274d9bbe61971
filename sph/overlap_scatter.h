// Per-overlap-particle values from the coupler (StepCommand arrays, in the order of the overlap
// set a solver last reported) scattered onto a solver's particle arrays.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::sph {

/// per_particle = 0 for all n particles, then per_particle[overlap_index[k]] = values[k] for the
/// overlap particles with index < movable (fixed particles never move). `values` empty: zeros.
/// Throws std::invalid_argument naming `what` when values holds neither none nor one per overlap
/// particle.
template <class Index>
void scatter_overlap_values(const std::vector<Index>& overlap_index,
                            const std::vector<double>& values, std::size_t n, std::size_t movable,
                            std::vector<double>& per_particle, const char* what) {
  if (!values.empty() && values.size() != overlap_index.size()) {
    throw std::invalid_argument(std::string(what) + ": expected " +
                                std::to_string(overlap_index.size()) + " values, got " +
                                std::to_string(values.size()));
  }
  per_particle.assign(n, 0.0);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(overlap_index[k]);
    if (i < movable) per_particle[i] = values[k];
  }
}

}  // namespace porosph::sph
