// SPDX-License-Identifier: MIT
// Differential drive through Box2D (SPEC §1.2): v = (vL + vR)/2, omega = (vR - vL)/0.14 m.
#include "sim/physics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "sim/robot_model.hpp"

namespace swarmpath::sim {
namespace {

TEST(Physics, StraightDriveCoversSpeedTimesTime) {
  Physics ph({});
  ph.add_robot({0.0, 0.0}, 0.0);
  std::vector<Pose> pose(1);
  for (int t = 0; t < 50; ++t) {  // 5 s at 10 cm/s
    ph.set_wheels(0, 0.10, 0.10);
    ph.step(0.1, 8, 3);
  }
  ph.read_poses(pose);
  EXPECT_NEAR(pose[0].p.x, 0.5, 1e-4);
  EXPECT_NEAR(pose[0].p.y, 0.0, 1e-6);
}

TEST(Physics, OppositeWheelsTurnInPlace) {
  Physics ph({});
  ph.add_robot({1.0, 1.0}, 0.0);
  std::vector<Pose> pose(1);
  for (int t = 0; t < 10; ++t) {  // omega = 0.2 / 0.14 rad/s for 1 s
    ph.set_wheels(0, -0.10, 0.10);
    ph.step(0.1, 8, 3);
  }
  ph.read_poses(pose);
  EXPECT_NEAR(pose[0].yaw(), 0.2 / kWheelBase, 1e-4);
  EXPECT_NEAR(dist(pose[0].p, {1.0, 1.0}), 0.0, 1e-6);
}

TEST(Physics, WallsStopRobots) {
  const Shape wall = Shape::box({1.0, 0.0}, {0.1, 2.0}, 0.0);  // face at x = 0.95
  Physics ph(std::span<const Shape>(&wall, 1));
  ph.add_robot({0.5, 0.0}, 0.0);
  std::vector<Pose> pose(1);
  for (int t = 0; t < 100; ++t) {
    ph.set_wheels(0, 0.10, 0.10);
    ph.step(0.1, 8, 3);
  }
  ph.read_poses(pose);
  EXPECT_LT(pose[0].p.x + kRobotRadius, 0.95 + 0.006);  // within Box2D's linear slop
  EXPECT_GT(pose[0].p.x + kRobotRadius, 0.95 - 0.02);   // pressed against it
}

}  // namespace
}  // namespace swarmpath::sim
