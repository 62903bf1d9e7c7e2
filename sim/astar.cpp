// SPDX-License-Identifier: MIT
#include "astar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "config_error.hpp"

namespace swarmpath::sim {

namespace {

struct Grid {
  int nx = 0;
  int ny = 0;
  Vec2 lo;
  double h = 0.01;
  std::vector<std::uint8_t> blocked;

  Vec2 centre(int i, int j) const { return {lo.x + (i + 0.5) * h, lo.y + (j + 0.5) * h}; }

  int cell_x(double x) const { return static_cast<int>(std::floor((x - lo.x) / h + 1e-9)); }

  int cell_y(double y) const { return static_cast<int>(std::floor((y - lo.y) / h + 1e-9)); }
};

Grid rasterise(const Scenario& s, const AStarOptions& o) {
  Grid g;
  const Aabb a = s.arena_bounds();
  g.lo = a.lo;
  g.h = o.resolution;
  g.nx = static_cast<int>(std::ceil(s.arena_size.x / g.h - 1e-9));
  g.ny = static_cast<int>(std::ceil(s.arena_size.y / g.h - 1e-9));
  const std::int64_t cells = static_cast<std::int64_t>(g.nx) * g.ny;
  if (cells > kMaxAStarCells) {
    throw ConfigError(s.file, 0, "arena.size",
                      "the A* grid would have " + std::to_string(cells) + " cells (limit " +
                          std::to_string(kMaxAStarCells) + "); use a coarser A* resolution");
  }
  g.blocked.assign(static_cast<std::size_t>(cells), 0);
  for (const Shape& sh : obstacle_shapes(s)) {
    const int i0 = std::max(0, g.cell_x(sh.bounds.lo.x - o.inflation) - 1);
    const int i1 = std::min(g.nx - 1, g.cell_x(sh.bounds.hi.x + o.inflation) + 1);
    const int j0 = std::max(0, g.cell_y(sh.bounds.lo.y - o.inflation) - 1);
    const int j1 = std::min(g.ny - 1, g.cell_y(sh.bounds.hi.y + o.inflation) + 1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        if (signed_distance(sh, g.centre(i, j)) <= o.inflation) {
          g.blocked[static_cast<std::size_t>(j) * g.nx + i] = 1;
        }
      }
    }
  }
  return g;
}

struct Open {
  double f;
  double g;
  std::int32_t idx;
};

// min-f first; among equal f the deeper node (larger g), then the smaller index
struct OpenAfter {
  bool operator()(const Open& a, const Open& b) const {
    if (a.f != b.f) return a.f > b.f;
    if (a.g != b.g) return a.g < b.g;
    return a.idx > b.idx;
  }
};

}  // namespace

AStarResult astar(const Scenario& s, const AStarOptions& o) {
  const Grid grid = rasterise(s, o);
  AStarResult result;
  const int sx = grid.cell_x(s.nest.x);
  const int sy = grid.cell_y(s.nest.y);
  const int gx = grid.cell_x(s.goal.x);
  const int gy = grid.cell_y(s.goal.y);
  const auto index = [&](int i, int j) { return static_cast<std::int32_t>(j * grid.nx + i); };
  if (grid.blocked[static_cast<std::size_t>(index(sx, sy))] ||
      grid.blocked[static_cast<std::size_t>(index(gx, gy))]) {
    return result;  // nest or goal within the inflation of an obstacle
  }
  const double kDiag = std::sqrt(2.0);
  const bool eight = o.connectivity == Connectivity::kEight;
  const auto heuristic = [&](int i, int j) {
    const double dx = std::abs(i - gx);
    const double dy = std::abs(j - gy);
    return eight ? (dx + dy) + (kDiag - 2.0) * std::min(dx, dy) : dx + dy;
  };

  const std::size_t n = grid.blocked.size();
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> parent(n, -1);
  std::vector<std::uint8_t> closed(n, 0);
  std::priority_queue<Open, std::vector<Open>, OpenAfter> open;

  const std::int32_t start = index(sx, sy);
  const std::int32_t goal = index(gx, gy);
  g[static_cast<std::size_t>(start)] = 0.0;
  open.push({heuristic(sx, sy), 0.0, start});

  static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  const int moves = eight ? 8 : 4;
  while (!open.empty()) {
    const Open cur = open.top();
    open.pop();
    const auto ci = static_cast<std::size_t>(cur.idx);
    if (closed[ci]) continue;
    closed[ci] = 1;
    ++result.expanded;
    if (cur.idx == goal) break;
    const int i = cur.idx % grid.nx;
    const int j = cur.idx / grid.nx;
    for (int m = 0; m < moves; ++m) {
      const int ni = i + kDx[m];
      const int nj = j + kDy[m];
      if (ni < 0 || nj < 0 || ni >= grid.nx || nj >= grid.ny) continue;
      const auto nidx = static_cast<std::size_t>(index(ni, nj));
      if (grid.blocked[nidx] || closed[nidx]) continue;
      if (m >= 4) {  // no corner cutting: both orthogonal neighbours must be free
        if (grid.blocked[static_cast<std::size_t>(index(ni, j))] ||
            grid.blocked[static_cast<std::size_t>(index(i, nj))]) {
          continue;
        }
      }
      const double ng = cur.g + (m >= 4 ? kDiag : 1.0);
      if (ng < g[nidx]) {
        g[nidx] = ng;
        parent[nidx] = cur.idx;
        open.push({ng + heuristic(ni, nj), ng, static_cast<std::int32_t>(nidx)});
      }
    }
  }
  if (!closed[static_cast<std::size_t>(goal)]) return result;

  result.found = true;
  result.length_m = g[static_cast<std::size_t>(goal)] * grid.h;
  // walk back and keep only the corners
  std::vector<std::int32_t> cells;
  for (std::int32_t c = goal; c != -1; c = parent[static_cast<std::size_t>(c)]) cells.push_back(c);
  std::reverse(cells.begin(), cells.end());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const bool corner =
        k == 0 || k + 1 == cells.size() || (cells[k] - cells[k - 1]) != (cells[k + 1] - cells[k]);
    if (corner) result.path.push_back(grid.centre(cells[k] % grid.nx, cells[k] / grid.nx));
  }
  return result;
}

double astar8_baseline_tu(const Scenario& s, const std::string& file) {
  const AStarResult a = astar(s);
  if (!a.found) throw ConfigError(file, 0, "", std::string(kNoAStarPath) + "; path / A* would be undefined");
  return to_tu(a.length_m);
}

}  // namespace swarmpath::sim
