// The O(N) reductions behind the observables (sph/observables.h): each runs over a read-only view
// of the free particles of one phase, restricted to the particles inside an optional box region.
// No allocation; OpenMP reductions over the particles.
#pragma once

#include <Eigen/Core>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "sph/vector.h"

namespace porosph::sph {

/// Read-only view of the free particles of a phase (structure of arrays). position, velocity and
/// mass are always set (when count > 0); the other fields are null when the phase lacks them.
template <int D>
struct ParticleView {
  const Vec<D>* position = nullptr;
  const Vec<D>* velocity = nullptr;
  const double* mass = nullptr;
  const double* pressure = nullptr;  ///< [Pa]; water only
  std::size_t count = 0;
  const double* density = nullptr;          ///< [kg/m^3]
  const double* porosity = nullptr;         ///< [-]; soil only
  const Eigen::Matrix3d* stress = nullptr;  ///< [Pa], tension positive, plane strain in 2D
  const Vec<D>* displacement = nullptr;     ///< displacement since t = 0 [m]
};

/// The closed box [lo, hi] an observable is restricted to; has_region = false: every particle.
template <int D>
struct Region {
  bool has_region = false;
  Vec<D> lo = Vec<D>::Zero();
  Vec<D> hi = Vec<D>::Zero();

  bool contains(const Vec<D>& x) const {
    return !has_region || ((x.array() >= lo.array()).all() && (x.array() <= hi.array()).all());
  }
};

/// The particle fields mean_field can average (scene key observables[].field).
enum class ParticleField {
  Density,
  Mass,
  Pressure,
  Porosity,
  Speed,
  VelocityX,
  VelocityY,
  VelocityZ,
  StressXX,
  StressYY,
  StressZZ,
  StressXY,
  StressXZ,
  StressYZ
};

namespace observables_detail {
constexpr double nan() { return std::numeric_limits<double>::quiet_NaN(); }
}  // namespace observables_detail

/// front_position / max_height: max_i (x_i - origin) . direction over the particles in `region`;
/// NaN without such particles.
template <int D>
double front_position(const ParticleView<D>& p, const Vec<D>& origin, const Vec<D>& direction,
                      const Region<D>& region = {}) {
  double best = -std::numeric_limits<double>::infinity();
  std::int64_t inside = 0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(max : best) reduction(+ : inside) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!region.contains(p.position[i])) continue;
    best = std::max(best, (p.position[i] - origin).dot(direction));
    ++inside;
  }
  return inside > 0 ? best : observables_detail::nan();
}

/// max_i |v_i| over the particles in `region` (0 without such particles).
template <int D>
double max_speed(const ParticleView<D>& p, const Region<D>& region = {}) {
  double best2 = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(max : best2) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (region.contains(p.position[i])) best2 = std::max(best2, p.velocity[i].squaredNorm());
  return std::sqrt(best2);
}

/// sum_i m_i |v_i|^2 / 2 over the particles in `region` [J] (per metre of depth in 2D).
template <int D>
double kinetic_energy(const ParticleView<D>& p, const Region<D>& region = {}) {
  double e = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (region.contains(p.position[i])) e += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  return e;
}

/// Number of particles in `region`.
template <int D>
double particle_count(const ParticleView<D>& p, const Region<D>& region = {}) {
  if (!region.has_region) return static_cast<double>(p.count);
  std::int64_t inside = 0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : inside) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (region.contains(p.position[i])) ++inside;
  return static_cast<double>(inside);
}

/// max_i |u_i| (u: displacement since t = 0) over the particles in `region`; 0 without such
/// particles, NaN if the phase has no displacement (p.displacement null).
template <int D>
double max_displacement(const ParticleView<D>& p, const Region<D>& region = {}) {
  if (p.displacement == nullptr) return observables_detail::nan();
  double best2 = 0.0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(max : best2) schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    if (region.contains(p.position[i])) best2 = std::max(best2, p.displacement[i].squaredNorm());
  return std::sqrt(best2);
}

/// (1/N) sum_i value(i) over the N particles in `region`; NaN if N = 0.
template <int D, class Value>
double regional_mean(const ParticleView<D>& p, const Region<D>& region, const Value& value) {
  double sum = 0.0;
  std::int64_t inside = 0;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : sum, inside) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!region.contains(p.position[i])) continue;
    sum += value(i);
    ++inside;
  }
  return inside > 0 ? sum / static_cast<double>(inside) : observables_detail::nan();
}

/// Arithmetic mean of `field` over the particles in `region` (speed = |v|; stress_* from the 3x3
/// stress, tension positive). NaN if no particle is inside, if the view lacks the field (its
/// pointer is null), or for velocity_z in 2D.
template <int D>
double mean_field(const ParticleView<D>& p, ParticleField field, const Region<D>& region = {}) {
  const auto scalar = [&](const double* f) {
    if (f == nullptr) return observables_detail::nan();
    return regional_mean(p, region, [f](std::int64_t i) { return f[i]; });
  };
  const auto velocity = [&](int k) {
    if (k >= D) return observables_detail::nan();
    return regional_mean(p, region, [&p, k](std::int64_t i) { return p.velocity[i][k]; });
  };
  const auto stress = [&](int r, int c) {
    if (p.stress == nullptr) return observables_detail::nan();
    return regional_mean(p, region, [&p, r, c](std::int64_t i) { return p.stress[i](r, c); });
  };
  switch (field) {
    case ParticleField::Density:
      return scalar(p.density);
    case ParticleField::Mass:
      return scalar(p.mass);
    case ParticleField::Pressure:
      return scalar(p.pressure);
    case ParticleField::Porosity:
      return scalar(p.porosity);
    case ParticleField::Speed:
      return regional_mean(p, region, [&p](std::int64_t i) { return p.velocity[i].norm(); });
    case ParticleField::VelocityX:
      return velocity(0);
    case ParticleField::VelocityY:
      return velocity(1);
    case ParticleField::VelocityZ:
      return velocity(2);
    case ParticleField::StressXX:
      return stress(0, 0);
    case ParticleField::StressYY:
      return stress(1, 1);
    case ParticleField::StressZZ:
      return stress(2, 2);
    case ParticleField::StressXY:
      return stress(0, 1);
    case ParticleField::StressXZ:
      return stress(0, 2);
    case ParticleField::StressYZ:
      return stress(1, 2);
  }
  return observables_detail::nan();
}

/// Pressure at `point` from the particles within the kernel support, first-order accurate
/// (docs/water-in-soil.md, "Pressure probes"): the linear moving-least-squares fit
/// p(x) ~ a + b . (x - point) minimising sum_i W_i (p_i - a - b . (x_i - point))^2, whose a is
/// exact for any linear pressure field whatever the stencil's shape (a probe beside a wall or a
/// free surface sees a one-sided stencil). Where the stencil cannot fix a slope (fewer than D + 1
/// particles, or all on a line: the moment matrix's reciprocal condition number below 1e-6), the
/// Shepard value sum_i p_i W_i / sum_i W_i, which is the pressure at the stencil's weighted
/// centroid rather than at the point. NaN if no particle is within the support or the phase has no
/// pressure. (Minimum image is not applied: probes are meant to be away from periodic faces.)
template <int D, class Kernel>
double pressure_at(const ParticleView<D>& p, const Vec<D>& point, const Kernel& kernel) {
  if (p.pressure == nullptr) return observables_detail::nan();
  // Moments in coordinates scaled by the support: M = sum W [1 d^T; d d d^T], r = sum W p [1; d].
  constexpr int K = D + 1;
  double m[K * K] = {}, r[K] = {};
  const double support = kernel.support();
  const double support2 = support * support;
  const std::int64_t n = static_cast<std::int64_t>(p.count);
#pragma omp parallel for reduction(+ : m[:K * K], r[:K]) schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const Vec<D> dx = p.position[i] - point;
    const double r2 = dx.squaredNorm();
    if (r2 >= support2) continue;
    const double w = kernel.w(std::sqrt(r2));
    double basis[K];
    basis[0] = 1.0;
    for (int k = 0; k < D; ++k) basis[k + 1] = dx[k] / support;
    for (int a = 0; a < K; ++a) {
      r[a] += w * p.pressure[i] * basis[a];
      for (int b = 0; b < K; ++b) m[a * K + b] += w * basis[a] * basis[b];
    }
  }
  if (!(m[0] > 0.0)) return observables_detail::nan();
  const double shepard = r[0] / m[0];
  const Eigen::Matrix<double, K, K> moments = Eigen::Map<const Eigen::Matrix<double, K, K>>(m);
  const Eigen::Matrix<double, K, 1> rhs = Eigen::Map<const Eigen::Matrix<double, K, 1>>(r);
  const Eigen::JacobiSVD<Eigen::Matrix<double, K, K>> svd(
      moments, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sigma = svd.singularValues();
  if (!(sigma[K - 1] > 1e-6 * sigma[0])) return shepard;
  return svd.solve(rhs)[0];
}

}  // namespace porosph::sph
