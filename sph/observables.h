// Observables (scene::Observable): quantities measured on the free particles of one phase at every
// output time. Each is a plain O(N) reduction over a read-only view of the particles.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "scene/scene.h"
#include "sph/vector.h"

namespace porosph::sph {

/// Read-only view of the free particles of a phase (structure of arrays; pressure may be null for
/// a phase without pressure).
template <int D>
struct ParticleView {
  const Vec<D>* position = nullptr;
  const Vec<D>* velocity = nullptr;
  const double* mass = nullptr;
  const double* pressure = nullptr;
  std::size_t count = 0;
};

/// front_position / max_height: max_i (x_i - origin) . direction; NaN without particles.
template <int D>
double front_position(const ParticleView<D>& p, const Vec<D>& origin, const Vec<D>& direction) {
  double best = -std::numeric_limits<double>::infinity();
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(max : best) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    best = std::max(best, (p.position[i] - origin).dot(direction));
  return n > 0 ? best : std::numeric_limits<double>::quiet_NaN();
}

/// max_i |v_i| (0 without particles).
template <int D>
double max_speed(const ParticleView<D>& p) {
  double best2 = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(max : best2) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) best2 = std::max(best2, p.velocity[i].squaredNorm());
  return std::sqrt(best2);
}

/// sum_i m_i |v_i|^2 / 2 [J] (per metre of depth in 2D).
template <int D>
double kinetic_energy(const ParticleView<D>& p) {
  double e = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) e += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  return e;
}

/// Shepard-interpolated pressure at `point`: sum_i p_i W_i / sum_i W_i over the particles within
/// the kernel support; NaN if there is none. (Minimum image is not applied: probes are meant to be
/// away from periodic faces.)
template <int D, class Kernel>
double pressure_at(const ParticleView<D>& p, const Vec<D>& point, const Kernel& kernel) {
  if (p.pressure == nullptr) return std::numeric_limits<double>::quiet_NaN();
  double sum_pw = 0.0, sum_w = 0.0;
  const double support2 = kernel.support() * kernel.support();
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : sum_pw, sum_w) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const double r2 = (p.position[i] - point).squaredNorm();
    if (r2 >= support2) continue;
    const double w = kernel.w(std::sqrt(r2));
    sum_pw += p.pressure[i] * w;
    sum_w += w;
  }
  return sum_w > 0.0 ? sum_pw / sum_w : std::numeric_limits<double>::quiet_NaN();
}

/// An observable with its kind decoded and its vectors converted, ready to evaluate every step
/// without string work or allocation.
template <int D>
struct PreparedObservable {
  enum class Kind { FrontPosition, MaxHeight, MaxSpeed, KineticEnergy, ParticleCount, PressureAt };
  std::string name;
  Kind kind = Kind::MaxSpeed;
  Vec<D> origin = Vec<D>::Zero(), direction = Vec<D>::Zero(), point = Vec<D>::Zero();
};

/// Decodes kind front_position | max_height | max_speed | kinetic_energy | particle_count |
/// pressure_at. Throws std::invalid_argument on an unknown kind or a vector of the wrong length.
template <int D>
PreparedObservable<D> prepare_observable(const scene::Observable& o) {
  using Kind = typename PreparedObservable<D>::Kind;
  PreparedObservable<D> p;
  p.name = o.name;
  const std::string what = "observable '" + o.name + "'";
  if (o.kind == "front_position" || o.kind == "max_height") {
    p.kind = o.kind == "max_height" ? Kind::MaxHeight : Kind::FrontPosition;
    p.origin = to_vec<D>(o.origin, what + " origin");
    p.direction = to_vec<D>(o.direction, what + " direction");
    if (o.direction.empty()) throw std::invalid_argument(what + ": direction is required");
  } else if (o.kind == "max_speed") {
    p.kind = Kind::MaxSpeed;
  } else if (o.kind == "kinetic_energy") {
    p.kind = Kind::KineticEnergy;
  } else if (o.kind == "particle_count") {
    p.kind = Kind::ParticleCount;
  } else if (o.kind == "pressure_at") {
    p.kind = Kind::PressureAt;
    p.point = to_vec<D>(o.point, what + " point");
    if (o.point.empty()) throw std::invalid_argument(what + ": point is required");
  } else {
    throw std::invalid_argument(what + ": unknown kind '" + o.kind + "'");
  }
  return p;
}

template <int D, class Kernel>
double evaluate_observable(const PreparedObservable<D>& o, const ParticleView<D>& p,
                           const Kernel& kernel) {
  using Kind = typename PreparedObservable<D>::Kind;
  switch (o.kind) {
    case Kind::FrontPosition:
    case Kind::MaxHeight:
      return front_position(p, o.origin, o.direction);
    case Kind::MaxSpeed:
      return max_speed(p);
    case Kind::KineticEnergy:
      return kinetic_energy(p);
    case Kind::ParticleCount:
      return static_cast<double>(p.count);
    case Kind::PressureAt:
      return pressure_at(p, o.point, kernel);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace porosph::sph
