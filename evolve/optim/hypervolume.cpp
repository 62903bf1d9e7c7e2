// SPDX-License-Identifier: MIT
// Hypervolume by sweeps: 2D sort-and-sweep, 3D as a sum of 2D areas over slices of the third axis
// (the dimension-sweep idea of While et al. 2006 / Fonseca et al. 2006, without their AVL tree).
#include "evolve/optim/hypervolume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swarmpath::evolve {
namespace {

using Point2 = std::array<double, 2>;

/// Area dominated by 2D points that are all strictly inside the reference.
double area_2d(std::vector<Point2> pts, const Point2& ref) {
  // sorted by the first objective, each point adds the strip between its second objective and the
  // best second objective of the points before it
  std::sort(pts.begin(), pts.end());
  double area = 0.0;
  double level = ref[1];
  for (const auto& p : pts) {
    if (p[1] < level) {
      area += (ref[0] - p[0]) * (level - p[1]);
      level = p[1];
    }
  }
  return area;
}

}  // namespace

double hypervolume(const std::vector<Vector>& points, const Vector& reference) {
  const std::size_t m = reference.size();
  if (m != 2 && m != 3) {
    throw std::invalid_argument("hypervolume: only 2 or 3 objectives are supported, got " +
                                std::to_string(m));
  }
  for (const double r : reference) {
    if (!std::isfinite(r)) throw std::invalid_argument("hypervolume: the reference point must be finite");
  }
  std::vector<Vector> inside;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].size() != m) {
      throw std::invalid_argument("hypervolume: point " + std::to_string(i) + " has " +
                                  std::to_string(points[i].size()) + " objectives, the reference " +
                                  std::to_string(m));
    }
    bool better = true;
    for (std::size_t k = 0; k < m; ++k) better = better && points[i][k] < reference[k];  // NaN: false
    if (better) inside.push_back(points[i]);
  }
  if (m == 2) {
    std::vector<Point2> pts;
    pts.reserve(inside.size());
    for (const auto& p : inside) pts.push_back({p[0], p[1]});
    return area_2d(std::move(pts), {reference[0], reference[1]});
  }
  // 3D: sorted by the third objective, the 2D cross-section is constant between consecutive values
  std::sort(inside.begin(), inside.end(), [](const Vector& a, const Vector& b) { return a[2] < b[2]; });
  double volume = 0.0;
  std::vector<Point2> slice;
  for (std::size_t i = 0; i < inside.size(); ++i) {
    slice.push_back({inside[i][0], inside[i][1]});
    const double z_next = i + 1 < inside.size() ? inside[i + 1][2] : reference[2];
    const double depth = z_next - inside[i][2];
    if (depth > 0.0) volume += area_2d(slice, {reference[0], reference[1]}) * depth;
  }
  return volume;
}

bool dominates(const Vector& a, const Vector& b) {
  bool strictly = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!(a[k] <= b[k])) return false;
    strictly = strictly || a[k] < b[k];
  }
  return strictly;
}

std::vector<std::size_t> non_dominated(const std::vector<Vector>& points) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (points[i].size() != points[0].size()) {
      throw std::invalid_argument("non_dominated: point " + std::to_string(i) + " has " +
                                  std::to_string(points[i].size()) + " objectives, point 0 has " +
                                  std::to_string(points[0].size()));
    }
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && dominates(points[j], points[i]);
    if (!dominated) kept.push_back(i);
  }
  return kept;
}

}  // namespace swarmpath::evolve
