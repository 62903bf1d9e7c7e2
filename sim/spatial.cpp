// SPDX-License-Identifier: MIT
#include "spatial.hpp"

#include <algorithm>

namespace swarmpath::sim {

ShapeBins::ShapeBins(std::span<const Shape> shapes, Aabb bounds, double cell, double reach)
    : frame_(bounds, cell), reach_(reach) {
  const std::size_t cells = frame_.cells();
  // the cells a shape's bounds, grown by reach, overlap
  const auto each_cell = [&](const Shape& sh, auto&& f) {
    const int i0 = frame_.cell_x(sh.bounds.lo.x - reach);
    const int i1 = frame_.cell_x(sh.bounds.hi.x + reach);
    const int j0 = frame_.cell_y(sh.bounds.lo.y - reach);
    const int j1 = frame_.cell_y(sh.bounds.hi.y + reach);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) f(static_cast<std::size_t>(j * frame_.nx + i));
    }
  };
  start_.assign(cells + 1, 0);
  for (const Shape& sh : shapes) each_cell(sh, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 1; c <= cells; ++c) start_[c] += start_[c - 1];
  items_.assign(static_cast<std::size_t>(start_[cells]), 0);
  std::vector<int> cursor(start_.begin(), start_.end() - 1);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    each_cell(shapes[s],
              [&](std::size_t c) { items_[static_cast<std::size_t>(cursor[c]++)] = static_cast<int>(s); });
  }
}

void RobotGrid::reset(Aabb bounds, double cell, std::size_t robots) {
  frame_ = CellFrame(bounds, cell);
  start_.assign(frame_.cells() + 1, 0);
  items_.assign(robots, 0);
  sorted_.assign(robots, Vec2{});
  cell_of_.assign(robots, 0);
}

void RobotGrid::build(std::span<const Vec2> positions) {
  std::fill(start_.begin(), start_.end(), 0);
  for (std::size_t id = 0; id < positions.size(); ++id) {
    const int c = frame_.index(positions[id]);
    cell_of_[id] = c;
    ++start_[static_cast<std::size_t>(c) + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  // stable fill: walk ids in order, using a cursor per cell (reuse start_ shifted by one)
  for (std::size_t id = 0; id < positions.size(); ++id) {
    const auto c = static_cast<std::size_t>(cell_of_[id]);
    const auto k = static_cast<std::size_t>(start_[c]++);
    items_[k] = static_cast<int>(id);
    sorted_[k] = positions[id];
  }
  // start_[c] now holds the end of cell c; shift right to restore the starts
  for (std::size_t c = start_.size() - 1; c > 0; --c) start_[c] = start_[c - 1];
  start_[0] = 0;
}

}  // namespace swarmpath::sim
