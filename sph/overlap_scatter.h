// Per-overlap-particle values from the coupler (StepCommand arrays, in the order of the overlap
// set a solver last reported) scattered onto a solver's particle arrays.
#pragma once

#include <cstddef>
#include <cstdint>
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

/// After the particles were re-ordered (new[i] = old[order[i]]), points each overlap index at its
/// particle's new place. A solver re-sorts its particles in compute_rates(), after it reported the
/// overlap set and before the coupler's answer is scattered onto that set: without this the
/// interaction of that step lands on other particles (it did, every 100th step, until
/// 2026-12-04: tests/cases/momentum_exchange_test.cpp). `inverse` is scratch (reused).
template <class Index>
void remap_overlap_index(std::vector<Index>& overlap_index, const std::vector<std::int32_t>& order,
                         std::vector<std::int32_t>& inverse) {
  if (overlap_index.empty()) return;
  inverse.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    inverse[static_cast<std::size_t>(order[i])] = static_cast<std::int32_t>(i);
  for (Index& index : overlap_index) index = static_cast<Index>(inverse[index]);
}

}  // namespace porosph::sph
