#include "sph/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace porosph::sph {
namespace {

std::string shape_name(const scene::Shape& s) {
  return s.label.empty() ? std::string("shape") : "shape '" + s.label + "'";
}

/// Closed faces of a container: closed[k][0] = face "k-" closed, closed[k][1] = "k+".
template <int D>
std::array<std::array<bool, 2>, D> closed_faces(const scene::Shape& s) {
  std::array<std::array<bool, 2>, D> closed;
  for (auto& c : closed) c = {true, true};
  for (const std::string& f : s.open_faces) {
    const bool ok = f.size() == 2 && f[0] >= 'x' && f[0] < 'x' + D && (f[1] == '-' || f[1] == '+');
    if (!ok) throw std::invalid_argument(shape_name(s) + ": unknown open face '" + f + "'");
    closed[f[0] - 'x'][f[1] == '+' ? 1 : 0] = false;
  }
  return closed;
}

/// Calls fn(point) for every point of the product of per-axis coordinate lists.
template <int D, class Fn>
void for_each_lattice_point(const std::array<std::vector<double>, D>& axes, Fn&& fn) {
  for (const auto& a : axes)
    if (a.empty()) return;
  std::array<std::size_t, D> idx{};
  while (true) {
    Vec<D> p;
    for (int k = 0; k < D; ++k) p[k] = axes[k][idx[k]];
    fn(p);
    int k = 0;
    while (k < D && ++idx[k] == axes[k].size()) idx[k++] = 0;
    if (k == D) return;
  }
}

std::vector<double> lattice_axis(double min, double max, double dp) {
  std::vector<double> out;
  const long n = lattice_count(min, max, dp);
  out.reserve(std::max(0L, n));
  for (long i = 0; i < n; ++i) out.push_back(min + (static_cast<double>(i) + 0.5) * dp);
  return out;
}

}  // namespace

bool point_in_polygon(const std::vector<std::vector<double>>& v, double x, double y) {
  bool inside = false;
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const double xi = v[i][0], yi = v[i][1], xj = v[j][0], yj = v[j][1];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

template <int D>
std::vector<Vec<D>> fill_shape(const scene::Shape& s, double dp) {
  if (!(dp > 0)) throw std::invalid_argument("fill_shape: dp must be positive");
  std::vector<Vec<D>> out;
  using Kind = scene::Shape::Kind;
  if (s.kind == Kind::Polygon) {
    if (D != 2) throw std::invalid_argument(shape_name(s) + ": polygons are 2D only");
    if (s.vertices.size() < 3) throw std::invalid_argument(shape_name(s) + ": < 3 vertices");
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& v : s.vertices) {
      if (v.size() != 2) throw std::invalid_argument(shape_name(s) + ": vertex needs 2 values");
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    }
    std::array<std::vector<double>, D> axes;
    for (int k = 0; k < D; ++k) axes[k] = lattice_axis(lo[k], hi[k], dp);
    for_each_lattice_point<D>(axes, [&](const Vec<D>& p) {
      if (point_in_polygon(s.vertices, p[0], p[1])) out.push_back(p);
    });
    return out;
  }
  const Vec<D> lo = to_vec<D>(s.min, shape_name(s) + " min");
  const Vec<D> hi = to_vec<D>(s.max, shape_name(s) + " max");
  if (static_cast<int>(s.min.size()) != D || static_cast<int>(s.max.size()) != D) {
    throw std::invalid_argument(shape_name(s) + ": min and max need " + std::to_string(D) +
                                " values");
  }
  std::array<std::vector<double>, D> axes;
  for (int k = 0; k < D; ++k) axes[k] = lattice_axis(lo[k], hi[k], dp);
  if (s.kind == Kind::Box) {
    for_each_lattice_point<D>(axes, [&](const Vec<D>& p) { out.push_back(p); });
    return out;
  }
  // Container: extend every axis by the wall layers on its closed faces, keep points outside.
  const auto closed = closed_faces<D>(s);
  std::array<std::size_t, D> inner_begin{}, inner_end{};
  for (int k = 0; k < D; ++k) {
    std::vector<double> axis;
    if (closed[k][0])
      for (int j = s.layers - 1; j >= 0; --j) axis.push_back(lo[k] - (j + 0.5) * dp);
    inner_begin[k] = axis.size();
    axis.insert(axis.end(), axes[k].begin(), axes[k].end());
    inner_end[k] = axis.size();
    if (closed[k][1])
      for (int j = 0; j < s.layers; ++j) axis.push_back(hi[k] + (j + 0.5) * dp);
    axes[k] = std::move(axis);
  }
  // Walk the index lattice to decide "outside the inner box" exactly (no coordinate round-off).
  std::array<std::size_t, D> idx{};
  for (const auto& a : axes)
    if (a.empty()) return out;
  while (true) {
    bool inner = true;
    Vec<D> p;
    for (int k = 0; k < D; ++k) {
      p[k] = axes[k][idx[k]];
      inner = inner && idx[k] >= inner_begin[k] && idx[k] < inner_end[k];
    }
    if (!inner) out.push_back(p);
    int k = 0;
    while (k < D && ++idx[k] == axes[k].size()) idx[k++] = 0;
    if (k == D) break;
  }
  return out;
}

template <int D>
bool inside_shape(const scene::Shape& s, const Vec<D>& x, double dp) {
  using Kind = scene::Shape::Kind;
  if (s.kind == Kind::Polygon) return D == 2 && point_in_polygon(s.vertices, x[0], x[1]);
  const Vec<D> lo = to_vec<D>(s.min, shape_name(s) + " min");
  const Vec<D> hi = to_vec<D>(s.max, shape_name(s) + " max");
  bool in_inner = true;
  for (int k = 0; k < D; ++k) in_inner = in_inner && x[k] >= lo[k] && x[k] <= hi[k];
  if (s.kind == Kind::Box) return in_inner;
  const auto closed = closed_faces<D>(s);
  bool in_outer = true;
  for (int k = 0; k < D; ++k) {
    const double olo = lo[k] - (closed[k][0] ? s.layers * dp : 0.0);
    const double ohi = hi[k] + (closed[k][1] ? s.layers * dp : 0.0);
    in_outer = in_outer && x[k] >= olo && x[k] <= ohi;
  }
  return in_outer && !in_inner;
}

template <int D>
std::vector<Vec<D>> fill_block_outside_walls(const scene::Shape& block,
                                             const std::vector<scene::Shape>& walls, double dp) {
  std::vector<Vec<D>> points = fill_shape<D>(block, dp);
  points.erase(std::remove_if(points.begin(), points.end(),
                              [&](const Vec<D>& p) {
                                for (const auto& w : walls)
                                  if (inside_shape<D>(w, p, dp)) return true;
                                return false;
                              }),
               points.end());
  return points;
}

#define POROSPH_INSTANTIATE(D)                                               \
  template std::vector<Vec<D>> fill_shape<D>(const scene::Shape&, double);   \
  template bool inside_shape<D>(const scene::Shape&, const Vec<D>&, double); \
  template std::vector<Vec<D>> fill_block_outside_walls<D>(                  \
      const scene::Shape&, const std::vector<scene::Shape>&, double);
POROSPH_INSTANTIATE(2)
POROSPH_INSTANTIATE(3)
#undef POROSPH_INSTANTIATE

}  // namespace porosph::sph
