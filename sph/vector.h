// Fixed-size vectors of the particle methods and conversions from the scene's std::vector<double>.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::sph {

/// A point or vector in D dimensions (D = 2 or 3).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// Converts a scene vector (length D) to Vec<D>; an empty vector gives `fallback`.
/// Throws std::invalid_argument naming `what` if the length is neither 0 nor D.
template <int D>
Vec<D> to_vec(const std::vector<double>& v, const std::string& what,
              const Vec<D>& fallback = Vec<D>::Zero()) {
  if (v.empty()) return fallback;
  if (static_cast<int>(v.size()) != D) {
    throw std::invalid_argument(what + ": expected " + std::to_string(D) + " components, got " +
                                std::to_string(v.size()));
  }
  Vec<D> out;
  for (int k = 0; k < D; ++k) out[k] = v[k];
  return out;
}

/// Writes a Vec<D> into a std::vector<double> of length D (reusing its storage).
template <int D>
void assign(std::vector<double>& out, const Vec<D>& v) {
  out.resize(D);
  for (int k = 0; k < D; ++k) out[k] = v[k];
}

}  // namespace porosph::sph
