// SPDX-License-Identifier: MIT
// The rigid-body layer: static obstacles and differential-drive robots as Box2D bodies.
// physics.cpp is the only file of swarmpath that includes Box2D.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "geometry.hpp"
#include "percept.hpp"

namespace swarmpath::sim {

/// How the physics is laid out. The arena can be cut into nx x ny equal rectangles over `bounds`,
/// each its own Box2D world, as ARGoS assigns regions to physics engines: a robot's body lives in
/// the region that holds its centre and moves to the next world when it crosses over, and robots
/// in different regions do not collide. 1 x 1 (the default) is one world, exact. Each world's
/// step is then one pass over the data it touches, which stays in cache at any swarm size.
struct PhysicsLayout {
  Aabb bounds;
  int nx = 1;
  int ny = 1;
  /// From this many robots on (Box2D holds ~0.7 KB a robot: 2 000 outgrow a 1 MiB L2), each
  /// region's bodies, fixtures and contacts are read in sweeps just before its step (see
  /// physics.cpp); results never depend on it.
  std::size_t warm_from_robots = 2000;
};

class Physics {
 public:
  /// Builds zero-gravity worlds, each with one static body holding the obstacle shapes near
  /// its region.
  explicit Physics(std::span<const Shape> obstacles, const PhysicsLayout& layout = {});
  ~Physics();
  Physics(const Physics&) = delete;
  Physics& operator=(const Physics&) = delete;

  /// Adds a foot-bot body (circle of kRobotRadius); robots get ids 0, 1, ... in call order.
  int add_robot(Vec2 position, double yaw);

  /// Differential drive (SPEC §1.2): v = (vL + vR)/2, omega = (vR - vL)/wheel base.
  /// Wheel speeds in m/s; applied as the body's velocity (from its heading then) at the start of
  /// the next step. Both wheels at zero brake the robot (a much heavier body, hard to push).
  void set_wheels(int id, double left_m_s, double right_m_s);

  /// One physics step of dt seconds in every region, then robots that crossed into another
  /// region move there (in id order).
  void step(double dt, int velocity_iterations, int position_iterations);

  /// Current poses of all robots, in id order.
  void read_poses(std::span<Pose> out) const;

  int robot_count() const;

  /// Box2D contacts (pairs whose enlarged bounding boxes overlap), for diagnostics.
  int contact_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarmpath::sim
