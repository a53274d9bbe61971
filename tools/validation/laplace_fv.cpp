#include "tools/validation/laplace_fv.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace porosph::validation {
namespace {

constexpr double kNoHead = std::numeric_limits<double>::quiet_NaN();

/// Linear interpolation between a at t = 0 and b at t = 1.
double lerp(double a, double b, double t) { return a + t * (b - a); }

/// The overlap length of [a0, a1] and [b0, b1].
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

/// The grid line index of `at` on a grid origin + k * spacing; throws when it is not one.
int grid_line(double at, double origin, double spacing, int cells, const char* what) {
  const double s = (at - origin) / spacing;
  const int k = static_cast<int>(std::lround(s));
  if (std::fabs(s - k) > 1e-6 || k < 0 || k > cells)
    throw std::invalid_argument(std::string("solve_laplace: ") + what + " is not on a grid line");
  return k;
}

}  // namespace

double LaplaceSolution::edge_value(Side side, int k) const {
  switch (side) {
    case Side::kLeft:
      return std::isnan(left_[k]) ? head_[index(0, k)] : left_[k];
    case Side::kRight:
      return std::isnan(right_[k]) ? head_[index(nx_ - 1, k)] : right_[k];
    case Side::kBottom:
      return std::isnan(bottom_[k]) ? head_[index(k, 0)] : bottom_[k];
    case Side::kTop:
      return std::isnan(top_[k]) ? head_[index(k, ny_ - 1)] : top_[k];
  }
  return kNoHead;
}

double LaplaceSolution::row_head(int j, double x) const {
  const int row = std::clamp(j, 0, ny_ - 1);  // the row whose barriers apply
  auto node = [&](int i) {
    if (j < 0) return edge_value(Side::kBottom, i);
    if (j >= ny_) return edge_value(Side::kTop, i);
    return head_[index(i, j)];
  };
  const bool edge_row = j < 0 || j >= ny_;
  const double s = (x - x0_) / dx_ - 0.5;  // in cell-centre units
  if (s <= 0.0) {
    const double end = edge_row ? node(0) : edge_value(Side::kLeft, j);
    return lerp(end, node(0), (s + 0.5) / 0.5);
  }
  if (s >= nx_ - 1) {
    const double end = edge_row ? node(nx_ - 1) : edge_value(Side::kRight, j);
    return lerp(node(nx_ - 1), end, (s - (nx_ - 1)) / 0.5);
  }
  const int i = std::min(static_cast<int>(std::floor(s)), nx_ - 2);
  if (blocked_x_[row * (nx_ + 1) + i + 1]) return x <= x0_ + (i + 1) * dx_ ? node(i) : node(i + 1);
  return lerp(node(i), node(i + 1), s - i);
}

double LaplaceSolution::head(double x, double y) const {
  x = std::clamp(x, x0_, x0_ + nx_ * dx_);
  y = std::clamp(y, y0_, y0_ + ny_ * dy_);
  const double s = (y - y0_) / dy_ - 0.5;
  if (s <= 0.0) return lerp(row_head(-1, x), row_head(0, x), (s + 0.5) / 0.5);
  if (s >= ny_ - 1) return lerp(row_head(ny_ - 1, x), row_head(ny_, x), (s - (ny_ - 1)) / 0.5);
  const int j = std::min(static_cast<int>(std::floor(s)), ny_ - 2);
  const int column = std::clamp(static_cast<int>(std::floor((x - x0_) / dx_)), 0, nx_ - 1);
  if (blocked_y_[(j + 1) * nx_ + column]) return row_head(y <= y0_ + (j + 1) * dy_ ? j : j + 1, x);
  return lerp(row_head(j, x), row_head(j + 1, x), s - j);
}

double LaplaceSolution::flux_x(int i, int j) const {
  const double c = k_ * dy_ / dx_;
  if (i == 0) return std::isnan(left_[j]) ? 0.0 : 2 * c * (left_[j] - head_[index(0, j)]);
  if (i == nx_) return std::isnan(right_[j]) ? 0.0 : 2 * c * (head_[index(nx_ - 1, j)] - right_[j]);
  if (blocked_x_[j * (nx_ + 1) + i]) return 0.0;
  return c * (head_[index(i - 1, j)] - head_[index(i, j)]);
}

double LaplaceSolution::flux_y(int i, int j) const {
  const double c = k_ * dx_ / dy_;
  if (j == 0) return std::isnan(bottom_[i]) ? 0.0 : 2 * c * (bottom_[i] - head_[index(i, 0)]);
  if (j == ny_) return std::isnan(top_[i]) ? 0.0 : 2 * c * (head_[index(i, ny_ - 1)] - top_[i]);
  if (blocked_y_[j * nx_ + i]) return 0.0;
  return c * (head_[index(i, j - 1)] - head_[index(i, j)]);
}

double LaplaceSolution::discharge_across_vertical(double at, double from, double to) const {
  const double eps = 1e-9 * dy_;
  auto line = [&](int i) {
    double q = 0.0;
    for (int j = 0; j < ny_; ++j) {
      const double yc = y0_ + (j + 0.5) * dy_;
      if (yc >= from - eps && yc <= to + eps) q += flux_x(i, j);
    }
    return q;
  };
  const double s = std::clamp((at - x0_) / dx_, 0.0, static_cast<double>(nx_));
  const int i = std::min(static_cast<int>(std::floor(s)), nx_ - 1);
  if (std::fabs(s - std::lround(s)) < 1e-6) return line(static_cast<int>(std::lround(s)));
  return lerp(line(i), line(i + 1), s - i);
}

double LaplaceSolution::discharge_across_horizontal(double at, double from, double to) const {
  const double eps = 1e-9 * dx_;
  auto line = [&](int j) {
    double q = 0.0;
    for (int i = 0; i < nx_; ++i) {
      const double xc = x0_ + (i + 0.5) * dx_;
      if (xc >= from - eps && xc <= to + eps) q += flux_y(i, j);
    }
    return q;
  };
  const double s = std::clamp((at - y0_) / dy_, 0.0, static_cast<double>(ny_));
  const int j = std::min(static_cast<int>(std::floor(s)), ny_ - 1);
  if (std::fabs(s - std::lround(s)) < 1e-6) return line(static_cast<int>(std::lround(s)));
  return lerp(line(j), line(j + 1), s - j);
}

double LaplaceSolution::mean_outward_gradient(Side side, double from, double to) const {
  const bool along_x = side == Side::kBottom || side == Side::kTop;
  const int faces = along_x ? nx_ : ny_;
  const double origin = along_x ? x0_ : y0_, length = along_x ? dx_ : dy_;
  double sum = 0.0;
  for (int k = 0; k < faces; ++k) {
    const double weight =
        overlap(origin + k * length, origin + (k + 1) * length, from, to) / length;
    if (weight <= 0.0) continue;
    double outward = 0.0;
    switch (side) {
      case Side::kLeft:
        outward = -flux_x(0, k);
        break;
      case Side::kRight:
        outward = flux_x(nx_, k);
        break;
      case Side::kBottom:
        outward = -flux_y(k, 0);
        break;
      case Side::kTop:
        outward = flux_y(k, ny_);
        break;
    }
    sum += weight * outward;
  }
  return sum / (k_ * (to - from));
}

LaplaceSolution solve_laplace(const LaplaceProblem& p) {
  if (p.cells_x < 2 || p.cells_y < 2 || !(p.x1 > p.x0) || !(p.y1 > p.y0) || !(p.conductivity > 0))
    throw std::invalid_argument("solve_laplace: bad grid or conductivity");
  LaplaceSolution s;
  s.x0_ = p.x0, s.y0_ = p.y0, s.nx_ = p.cells_x, s.ny_ = p.cells_y, s.k_ = p.conductivity;
  s.dx_ = (p.x1 - p.x0) / p.cells_x, s.dy_ = (p.y1 - p.y0) / p.cells_y;
  const int nx = s.nx_, ny = s.ny_;
  s.left_.assign(ny, kNoHead), s.right_.assign(ny, kNoHead);
  s.bottom_.assign(nx, kNoHead), s.top_.assign(nx, kNoHead);
  auto in = [](double c, double from, double to, double spacing) {
    return c >= from - 1e-9 * spacing && c <= to + 1e-9 * spacing;
  };
  for (const auto& f : p.fixed_heads) {
    const bool along_x = f.side == Side::kBottom || f.side == Side::kTop;
    auto& faces = f.side == Side::kLeft     ? s.left_
                  : f.side == Side::kRight  ? s.right_
                  : f.side == Side::kBottom ? s.bottom_
                                            : s.top_;
    const double origin = along_x ? s.x0_ : s.y0_, length = along_x ? s.dx_ : s.dy_;
    for (int k = 0; k < static_cast<int>(faces.size()); ++k)
      if (in(origin + (k + 0.5) * length, f.from, f.to, length)) faces[k] = f.head;
  }
  s.blocked_x_.assign((nx + 1) * ny, 0);
  s.blocked_y_.assign(nx * (ny + 1), 0);
  for (const auto& b : p.barriers) {
    if (b.vertical) {
      const int i = grid_line(b.at, s.x0_, s.dx_, nx, "a vertical barrier");
      for (int j = 0; j < ny; ++j)
        if (in(s.y0_ + (j + 0.5) * s.dy_, b.from, b.to, s.dy_)) {
          s.blocked_x_[j * (nx + 1) + i] = 1;
          if (i == 0) s.left_[j] = kNoHead;
          if (i == nx) s.right_[j] = kNoHead;
        }
    } else {
      const int j = grid_line(b.at, s.y0_, s.dy_, ny, "a horizontal barrier");
      for (int i = 0; i < nx; ++i)
        if (in(s.x0_ + (i + 0.5) * s.dx_, b.from, b.to, s.dx_)) {
          s.blocked_y_[j * nx + i] = 1;
          if (j == 0) s.bottom_[i] = kNoHead;
          if (j == ny) s.top_[i] = kNoHead;
        }
    }
  }
  std::vector<char> solid(nx * ny, 0);
  for (const auto& b : p.solids) {
    const int i0 = grid_line(b.x0, s.x0_, s.dx_, nx, "a solid block's left edge");
    const int i1 = grid_line(b.x1, s.x0_, s.dx_, nx, "a solid block's right edge");
    const int j0 = grid_line(b.y0, s.y0_, s.dy_, ny, "a solid block's bottom edge");
    const int j1 = grid_line(b.y1, s.y0_, s.dy_, ny, "a solid block's top edge");
    for (int j = j0; j < j1; ++j)
      for (int i = i0; i < i1; ++i) {
        solid[s.index(i, j)] = 1;
        s.blocked_x_[j * (nx + 1) + i] = s.blocked_x_[j * (nx + 1) + i + 1] = 1;
        s.blocked_y_[j * nx + i] = s.blocked_y_[(j + 1) * nx + i] = 1;
        if (i == 0) s.left_[j] = kNoHead;
        if (i == nx - 1) s.right_[j] = kNoHead;
        if (j == 0) s.bottom_[i] = kNoHead;
        if (j == ny - 1) s.top_[i] = kNoHead;
      }
  }
  // Assembly: per cell, the sum of the conductances to its open neighbours and fixed heads.
  const double cx = p.conductivity * s.dy_ / s.dx_, cy = p.conductivity * s.dx_ / s.dy_;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(5 * nx * ny);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nx * ny);
  bool any_fixed = false;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = s.index(i, j);
      if (solid[k]) {  // decoupled: every face is blocked; h = 0 here, NaN after the solve
        triplets.emplace_back(k, k, 1.0);
        continue;
      }
      double diagonal = 0.0;
      auto neighbour = [&](bool open, int other, double c) {
        if (!open) return;
        diagonal += c;
        triplets.emplace_back(k, other, -c);
      };
      auto fixed = [&](double h, double c) {
        if (std::isnan(h)) return;
        diagonal += 2 * c, rhs[k] += 2 * c * h, any_fixed = true;
      };
      if (i > 0)
        neighbour(!s.blocked_x_[j * (nx + 1) + i], s.index(i - 1, j), cx);
      else
        fixed(s.left_[j], cx);
      if (i < nx - 1)
        neighbour(!s.blocked_x_[j * (nx + 1) + i + 1], s.index(i + 1, j), cx);
      else
        fixed(s.right_[j], cx);
      if (j > 0)
        neighbour(!s.blocked_y_[j * nx + i], s.index(i, j - 1), cy);
      else
        fixed(s.bottom_[i], cy);
      if (j < ny - 1)
        neighbour(!s.blocked_y_[(j + 1) * nx + i], s.index(i, j + 1), cy);
      else
        fixed(s.top_[i], cy);
      triplets.emplace_back(k, k, diagonal);
    }
  if (!any_fixed) throw std::invalid_argument("solve_laplace: no fixed head, h undetermined");
  Eigen::SparseMatrix<double> a(nx * ny, nx * ny);
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("solve_laplace: factorisation failed");
  const Eigen::VectorXd h = solver.solve(rhs);
  s.head_.assign(h.data(), h.data() + h.size());
  for (int k = 0; k < nx * ny; ++k)
    if (solid[k]) s.head_[k] = kNoHead;
  return s;
}

}  // namespace porosph::validation
