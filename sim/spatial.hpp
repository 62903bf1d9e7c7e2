// SPDX-License-Identifier: MIT
// Uniform grids that keep sensing linear in the number of robots: static obstacles binned by
// cell (built once per world) and the robots (rebuilt after every physics step).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

/// The cell arithmetic the grids (and the physics regions) share: a rectangle cut into nx x ny
/// cells; points outside (or NaN) clamp to the border cells.
struct CellFrame {
  Vec2 lo;
  double inv_cell_x = 1.0;
  double inv_cell_y = 1.0;
  int nx = 1;
  int ny = 1;

  CellFrame() = default;

  /// Square cells of side `cell`, enough to cover `bounds`.
  CellFrame(Aabb bounds, double cell)
      : lo(bounds.lo),
        inv_cell_x(1.0 / cell),
        inv_cell_y(1.0 / cell),
        nx(std::max(1, static_cast<int>(std::ceil((bounds.hi.x - bounds.lo.x) / cell)))),
        ny(std::max(1, static_cast<int>(std::ceil((bounds.hi.y - bounds.lo.y) / cell)))) {}

  /// `bounds` cut into nx x ny equal rectangles.
  CellFrame(Aabb bounds, int cells_x, int cells_y)
      : lo(bounds.lo),
        inv_cell_x(cells_x / (bounds.hi.x - bounds.lo.x)),
        inv_cell_y(cells_y / (bounds.hi.y - bounds.lo.y)),
        nx(cells_x),
        ny(cells_y) {}

  std::size_t cells() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }

  int cell_x(double x) const { return clamp_cell((x - lo.x) * inv_cell_x, nx); }

  int cell_y(double y) const { return clamp_cell((y - lo.y) * inv_cell_y, ny); }

  int index(Vec2 p) const { return cell_y(p.y) * nx + cell_x(p.x); }

  /// Cell `index`'s rectangle.
  Aabb cell_bounds(int index) const {
    const Vec2 size{1.0 / inv_cell_x, 1.0 / inv_cell_y};
    const Vec2 at = lo + Vec2{size.x * (index % nx), size.y * (index / nx)};
    return {at, at + size};
  }

 private:
  static int clamp_cell(double v, int n) {
    if (!(v > 0.0)) return 0;  // also NaN
    return v >= n - 1 ? n - 1 : static_cast<int>(v);
  }
};

/// Static shapes binned by grid cell: cell c lists (ascending) every shape that comes within
/// `reach` of some point of c, so near(p) is a superset of the shapes within `reach` of p,
/// found with one lookup and no per-query bookkeeping.
class ShapeBins {
 public:
  ShapeBins() = default;
  ShapeBins(std::span<const Shape> shapes, Aabb bounds, double cell, double reach);

  std::span<const int> near(Vec2 p) const {
    const auto c = static_cast<std::size_t>(frame_.index(p));
    return {items_.data() + start_[c], items_.data() + start_[c + 1]};
  }

  double reach() const { return reach_; }

 private:
  CellFrame frame_;
  double reach_ = 0.0;
  std::vector<int> start_{0, 0};  // CSR: cell c holds items_[start_[c] .. start_[c+1])
  std::vector<int> items_;
};

/// Robots bucketed by cell with a stable counting sort: within a cell, ids ascend. The grid keeps
/// its own copy of the positions in that order, so a query reads each cell's robots from one
/// contiguous run instead of one scattered line per neighbour (at 10 000 robots those lines have
/// left the cache between ticks).
class RobotGrid {
 public:
  void reset(Aabb bounds, double cell, std::size_t robots);
  void build(std::span<const Vec2> positions);

  /// Calls f(j, position of j) for every robot j within r of p (p's own robot included), in cell
  /// then id order.
  template <typename F>
  void for_each_within(Vec2 p, double r, F&& f) const {
    const int i0 = frame_.cell_x(p.x - r);
    const int i1 = frame_.cell_x(p.x + r);
    const int j0 = frame_.cell_y(p.y - r);
    const int j1 = frame_.cell_y(p.y + r);
    const double r2 = r * r;
    for (int j = j0; j <= j1; ++j) {
      const int row = j * frame_.nx;
      // a row's cells i0..i1 are one contiguous run of items
      const int end = start_[row + i1 + 1];
      for (int k = start_[row + i0]; k < end; ++k) {
        const Vec2 q = sorted_[static_cast<std::size_t>(k)];
        if (norm2(q - p) <= r2) f(items_[static_cast<std::size_t>(k)], q);
      }
    }
  }

  /// The same, skipping every row of cells j for which keep_row(j) is false and every cell c for
  /// which keep(c) is false (the others in the same order).
  template <typename KeepRow, typename Keep, typename F>
  void for_each_within(Vec2 p, double r, KeepRow&& keep_row, Keep&& keep, F&& f) const {
    const int i0 = frame_.cell_x(p.x - r);
    const int i1 = frame_.cell_x(p.x + r);
    const int j0 = frame_.cell_y(p.y - r);
    const int j1 = frame_.cell_y(p.y + r);
    const double r2 = r * r;
    for (int j = j0; j <= j1; ++j) {
      if (!keep_row(j)) continue;
      for (int c = j * frame_.nx + i0; c <= j * frame_.nx + i1; ++c) {
        if (!keep(c)) continue;
        const int end = start_[static_cast<std::size_t>(c) + 1];
        for (int k = start_[static_cast<std::size_t>(c)]; k < end; ++k) {
          const Vec2 q = sorted_[static_cast<std::size_t>(k)];
          if (norm2(q - p) <= r2) f(items_[static_cast<std::size_t>(k)], q);
        }
      }
    }
  }

  /// How many cells, and how many of them make a row (cell c lies in row c / columns()); the cell
  /// robot `id` was in at the last build.
  std::size_t cells() const { return frame_.cells(); }

  std::size_t columns() const { return static_cast<std::size_t>(frame_.nx); }

  int cell_of(int id) const { return cell_of_[static_cast<std::size_t>(id)]; }

 private:
  CellFrame frame_;
  std::vector<int> start_;
  std::vector<int> items_;
  std::vector<Vec2> sorted_;  // sorted_[k] = the position of robot items_[k]
  std::vector<int> cell_of_;
};

}  // namespace swarmpath::sim
