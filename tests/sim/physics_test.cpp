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

// Two regions split at x = 0 over a 4 m x 2 m arena.
PhysicsLayout two_regions() {
  PhysicsLayout layout;
  layout.bounds = {{-2.0, -1.0}, {2.0, 1.0}};
  layout.nx = 2;
  return layout;
}

// Poses after `ticks` ticks of both robots driving at their wheel speeds.
std::vector<Pose> drive(Physics& ph, const std::vector<std::pair<double, double>>& wheels, int ticks) {
  std::vector<Pose> pose(wheels.size());
  for (int t = 0; t < ticks; ++t) {
    for (std::size_t i = 0; i < wheels.size(); ++i)
      ph.set_wheels(static_cast<int>(i), wheels[i].first, wheels[i].second);
    ph.step(0.1, 8, 3);
  }
  ph.read_poses(pose);
  return pose;
}

TEST(PhysicsRegions, ARobotCrossingIntoTheNextRegionKeepsItsExactPath) {
  // a curving robot crosses x = 0 from region 0 into region 1: its body moves to the other
  // world with pose and velocities, and the path is bit-for-bit that of one world
  Physics one({});
  Physics two({}, two_regions());
  one.add_robot({-0.5, 0.0}, 0.3);
  two.add_robot({-0.5, 0.0}, 0.3);
  const std::vector<std::pair<double, double>> wheels{{0.12, 0.10}};
  for (int leg = 0; leg < 4; ++leg) {  // 10 s in legs, the crossing at ~4 s
    const std::vector<Pose> a = drive(one, wheels, 25);
    const std::vector<Pose> b = drive(two, wheels, 25);
    EXPECT_EQ(a[0].p.x, b[0].p.x) << "leg " << leg;
    EXPECT_EQ(a[0].p.y, b[0].p.y) << "leg " << leg;
    EXPECT_EQ(a[0].c, b[0].c) << "leg " << leg;
  }
  EXPECT_GT(drive(two, wheels, 0)[0].p.x, 0.2);  // it did cross
}

TEST(PhysicsRegions, WallsNearABoundaryStopRobotsOnBothSides) {
  // a wall straddling x = 0 belongs to both regions' worlds
  const Shape wall = Shape::box({0.0, 0.5}, {1.0, 0.1}, 0.0);  // lower face at y = 0.45
  Physics ph(std::span<const Shape>(&wall, 1), two_regions());
  ph.add_robot({-0.3, 0.0}, kPi / 2);
  ph.add_robot({0.3, 0.0}, kPi / 2);
  const std::vector<Pose> pose = drive(ph, {{0.1, 0.1}, {0.1, 0.1}}, 80);
  for (const Pose& q : pose) EXPECT_LT(q.p.y + kRobotRadius, 0.45 + 0.006);
}

TEST(PhysicsRegions, RobotsInDifferentRegionsDoNotCollide) {
  // the documented price of regions (ARGoS's too): head-on across the boundary, two robots
  // block each other in one world and pass through each other in two
  const std::vector<std::pair<double, double>> head_on{{0.1, 0.1}, {0.1, 0.1}};
  Physics one({});
  one.add_robot({-0.3, 0.0}, 0.0);
  one.add_robot({0.3, 0.0}, kPi);
  const std::vector<Pose> blocked = drive(one, head_on, 60);
  EXPECT_LT(blocked[0].p.x, 0.0);
  Physics two({}, two_regions());
  two.add_robot({-0.3, 0.0}, 0.0);
  two.add_robot({0.3, 0.0}, kPi);
  const std::vector<Pose> passed = drive(two, head_on, 60);
  EXPECT_GT(passed[0].p.x, 0.2);
  EXPECT_LT(passed[1].p.x, -0.2);
}

TEST(PhysicsRegions, WarmingTheCacheChangesNothing) {
  // the sweeps that read each region's data before its step are loads only: the same robots,
  // pressed together in a crowd (many contacts), end bit-identically with and without them
  PhysicsLayout warm = two_regions();
  warm.warm_from_robots = 0;
  PhysicsLayout cold = two_regions();
  cold.warm_from_robots = 1000000;
  Physics a({}, warm);
  Physics b({}, cold);
  std::vector<std::pair<double, double>> wheels;
  for (int k = 0; k < 24; ++k) {
    const Vec2 at{-0.9 + 0.2 * (k % 8), -0.4 + 0.2 * (k / 8)};
    a.add_robot(at, 0.4 * k);
    b.add_robot(at, 0.4 * k);
    wheels.emplace_back(k % 3 == 0 ? 0.0 : 0.1, 0.1);  // some braked, most driving into others
  }
  const std::vector<Pose> pa = drive(a, wheels, 100);
  const std::vector<Pose> pb = drive(b, wheels, 100);
  EXPECT_GT(a.contact_count(), 10);
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i].p.x, pb[i].p.x) << "robot " << i;
    EXPECT_EQ(pa[i].p.y, pb[i].p.y) << "robot " << i;
  }
}

}  // namespace
}  // namespace swarmpath::sim
