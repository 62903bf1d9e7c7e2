// SPDX-License-Identifier: MIT
// The robot grid the sensors query: every robot within r, each once, in cell then id order, with
// the position it was built from (the grid reads its own cell-sorted copy of the positions).
#include "sim/spatial.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sim/rng.hpp"

namespace swarmpath::sim {
namespace {

TEST(RobotGrid, FindsExactlyTheRobotsWithinRangeInCellThenIdOrderWithTheirPositions) {
  const Aabb bounds{{-5.0, -3.0}, {5.0, 3.0}};
  const double cell = 0.7;
  const CellFrame frame(bounds, cell);
  Rng rng(42);
  std::vector<Vec2> positions(500);
  for (Vec2& p : positions) p = {rng.uniform(-5.5, 5.5), rng.uniform(-3.5, 3.5)};  // some outside
  RobotGrid grid;
  grid.reset(bounds, cell, positions.size());
  grid.build(positions);
  for (int q = 0; q < 200; ++q) {
    const Vec2 p{rng.uniform(-5.0, 5.0), rng.uniform(-3.0, 3.0)};
    const double r = rng.uniform(0.05, 1.5);
    std::vector<std::pair<int, int>> found;  // (cell, id)
    grid.for_each_within(p, r, [&](int id, Vec2 at) {
      EXPECT_EQ(at.x, positions[static_cast<std::size_t>(id)].x);
      EXPECT_EQ(at.y, positions[static_cast<std::size_t>(id)].y);
      found.emplace_back(frame.index(at), id);
    });
    std::vector<std::pair<int, int>> expected;
    for (std::size_t id = 0; id < positions.size(); ++id) {
      if (norm2(positions[id] - p) <= r * r)
        expected.emplace_back(frame.index(positions[id]), static_cast<int>(id));
    }
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(found, expected) << "query " << q << " at (" << p.x << ", " << p.y << ") r " << r;
  }
}

// The query that skips rows of cells and cells (the range-and-bearing medium skips those that sent
// nothing a listener reads) gives the full query's robots in the same order, less those of the
// skipped rows and cells.
TEST(RobotGrid, SkippingCellsKeepsTheOrderOfTheOthers) {
  const Aabb bounds{{-5.0, -3.0}, {5.0, 3.0}};
  const double cell = 0.7;
  Rng rng(7);
  std::vector<Vec2> positions(400);
  for (Vec2& p : positions) p = {rng.uniform(-5.5, 5.5), rng.uniform(-3.5, 3.5)};
  RobotGrid grid;
  grid.reset(bounds, cell, positions.size());
  grid.build(positions);
  for (std::size_t id = 0; id < positions.size(); ++id) {
    EXPECT_EQ(grid.cell_of(static_cast<int>(id)), CellFrame(bounds, cell).index(positions[id]));
  }
  std::size_t within = 0;
  std::size_t skipped = 0;
  for (int q = 0; q < 100; ++q) {
    const Vec2 p{rng.uniform(-5.0, 5.0), rng.uniform(-3.0, 3.0)};
    const double r = rng.uniform(0.5, 3.0);
    const auto keep = [](int c) { return c % 3 != 1; };
    const auto columns = static_cast<int>(grid.columns());
    const auto keep_row = [](int row) { return row % 4 != 2; };
    std::vector<int> all;
    grid.for_each_within(p, r, [&](int id, Vec2) {
      ++within;
      if (keep_row(grid.cell_of(id) / columns) && keep(grid.cell_of(id))) {
        all.push_back(id);
      } else {
        ++skipped;
      }
    });
    std::vector<int> kept;
    grid.for_each_within(p, r, keep_row, keep, [&](int id, Vec2) { kept.push_back(id); });
    EXPECT_EQ(kept, all) << "query " << q;
  }
  EXPECT_GT(skipped, within / 3);  // a third of the cells skipped, and a quarter of the rows
}

TEST(RobotGrid, ARebuildForgetsTheOldPositions) {
  const Aabb bounds{{0.0, 0.0}, {4.0, 4.0}};
  RobotGrid grid;
  grid.reset(bounds, 1.0, 2);
  std::vector<Vec2> positions{{0.5, 0.5}, {3.5, 3.5}};
  grid.build(positions);
  positions = {{3.4, 3.4}, {0.6, 0.6}};
  grid.build(positions);
  std::vector<int> near_origin;
  grid.for_each_within({0.5, 0.5}, 0.3, [&](int id, Vec2) { near_origin.push_back(id); });
  EXPECT_EQ(near_origin, std::vector<int>{1});
}

}  // namespace
}  // namespace swarmpath::sim
