// SPDX-License-Identifier: MIT
// The occupancy heat map's counts: each booked tick adds one per robot to the cell it stands in,
// only robots with the wanted LED when one is given, none outside the arena.
#include "sim/occupancy.hpp"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace swarmpath::sim {
namespace {

Pose at(double x, double y) { return Pose{{x, y}, 1.0, 0.0}; }

TEST(Occupancy, CountsEachRobotInTheCellItStandsInOncePerTick) {
  Occupancy occ({{-2.0, -1.0}, {2.0, 1.0}}, 0.5);
  ASSERT_EQ(occ.cells_x(), 8);
  ASSERT_EQ(occ.cells_y(), 4);
  const std::vector<Pose> poses = {at(-1.9, -0.9), at(-1.8, -0.8), at(1.9, 0.9), at(5.0, 0.0)};
  const std::vector<Led> leds(poses.size(), Led::kGreen);
  occ.add(poses, leds);
  occ.add(poses, leds);
  EXPECT_EQ(occ.ticks(), 2);
  EXPECT_EQ(occ.count(0, 0), 4);  // two robots in the south-west cell, two ticks
  EXPECT_EQ(occ.count(7, 3), 2);  // north-east
  std::int64_t total = 0;
  for (int iy = 0; iy < occ.cells_y(); ++iy)
    for (int ix = 0; ix < occ.cells_x(); ++ix) total += occ.count(ix, iy);
  EXPECT_EQ(total, 6);  // the robot outside the arena is not counted
  // two robots on 0.25 m^2 on average: 8 robots per m^2
  EXPECT_DOUBLE_EQ(occ.density(0, 0), 8.0);
  EXPECT_DOUBLE_EQ(occ.density(1, 0), 0.0);
}

TEST(Occupancy, CountsOnlyTheWantedLedColour) {
  Occupancy occ({{0.0, 0.0}, {1.0, 1.0}}, 1.0, Led::kGreen);
  const std::vector<Pose> poses = {at(0.5, 0.5), at(0.6, 0.5), at(0.7, 0.5)};
  const std::vector<Led> leds = {Led::kGreen, Led::kRed, Led::kGreen};
  occ.add(poses, leds);
  EXPECT_EQ(occ.count(0, 0), 2);
  EXPECT_EQ(occ.only(), Led::kGreen);
}

// a 1 m arena in 40 cm cells: the last column and row are 20 cm wide, and a robot there stands on
// half a cell's floor
TEST(Occupancy, ACellCutByTheArenaEdgeCountsDensityOverItsOwnFloor) {
  Occupancy occ({{0.0, 0.0}, {1.0, 1.0}}, 0.4);
  ASSERT_EQ(occ.cells_x(), 3);
  const Aabb edge = occ.cell_bounds(2, 0);
  EXPECT_DOUBLE_EQ(edge.hi.x, 1.0);
  EXPECT_DOUBLE_EQ(edge.hi.y, 0.4);
  const std::vector<Pose> poses = {at(0.9, 0.1), at(0.1, 0.1)};
  const std::vector<Led> leds(poses.size(), Led::kGreen);
  occ.add(poses, leds);
  EXPECT_DOUBLE_EQ(occ.density(0, 0), 1.0 / 0.16);
  EXPECT_DOUBLE_EQ(occ.density(2, 0), 1.0 / 0.08);  // 0.2 m x 0.4 m
  EXPECT_DOUBLE_EQ(occ.cell_bounds(2, 2).hi.y, 1.0);
}

TEST(Occupancy, RejectsACellThatIsNotPositive) {
  EXPECT_THROW(Occupancy({{0.0, 0.0}, {1.0, 1.0}}, 0.0), std::invalid_argument);
  EXPECT_THROW(Occupancy({{0.0, 0.0}, {1.0, 1.0}}, -0.5), std::invalid_argument);
}

}  // namespace
}  // namespace swarmpath::sim
