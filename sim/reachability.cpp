// SPDX-License-Identifier: MIT
#include "reachability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "robot_model.hpp"

namespace swarmpath::sim {

bool robot_can_drive(const Scenario& s, Vec2 from, Vec2 to) {
  const Aabb a = s.arena_bounds();
  const double h = std::max(0.02, std::sqrt(s.arena_size.x * s.arena_size.y / 1.0e6));
  const int nx = std::max(1, static_cast<int>(std::ceil(s.arena_size.x / h)));
  const int ny = std::max(1, static_cast<int>(std::ceil(s.arena_size.y / h)));
  const auto cell = [&](double v, double lo, int n) {
    return std::clamp(static_cast<int>(std::floor((v - lo) / h)), 0, n - 1);
  };
  // blocked: the whole cell lies within a robot's radius of an obstacle
  const double reach = kRobotRadius - 0.5 * std::sqrt(2.0) * h;
  std::vector<std::uint8_t> blocked(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
  for (const Shape& sh : obstacle_shapes(s)) {
    const int i0 = cell(sh.bounds.lo.x - kRobotRadius, a.lo.x, nx);
    const int i1 = cell(sh.bounds.hi.x + kRobotRadius, a.lo.x, nx);
    const int j0 = cell(sh.bounds.lo.y - kRobotRadius, a.lo.y, ny);
    const int j1 = cell(sh.bounds.hi.y + kRobotRadius, a.lo.y, ny);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const Vec2 c{a.lo.x + (i + 0.5) * h, a.lo.y + (j + 0.5) * h};
        if (signed_distance(sh, c) < reach) blocked[static_cast<std::size_t>(j) * nx + i] = 1;
      }
    }
  }
  const auto index = [&](Vec2 p) {
    return static_cast<std::size_t>(cell(p.y, a.lo.y, ny)) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(cell(p.x, a.lo.x, nx));
  };
  const std::size_t start = index(from), goal = index(to);
  if (blocked[start] || blocked[goal]) return false;
  // breadth-first over the 4 neighbours (8-connected moves without corner cutting reach no more)
  std::vector<std::size_t> queue{start};
  blocked[start] = 1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const std::size_t c = queue[k];
    if (c == goal) return true;
    const std::size_t i = c % static_cast<std::size_t>(nx);
    const std::size_t j = c / static_cast<std::size_t>(nx);
    const auto visit = [&](std::size_t n) {
      if (!blocked[n]) {
        blocked[n] = 1;
        queue.push_back(n);
      }
    };
    if (i > 0) visit(c - 1);
    if (i + 1 < static_cast<std::size_t>(nx)) visit(c + 1);
    if (j > 0) visit(c - static_cast<std::size_t>(nx));
    if (j + 1 < static_cast<std::size_t>(ny)) visit(c + static_cast<std::size_t>(nx));
  }
  return false;
}

}  // namespace swarmpath::sim
