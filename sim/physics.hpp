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

class Physics {
 public:
  /// Builds a zero-gravity world with one static body holding every obstacle shape.
  explicit Physics(std::span<const Shape> obstacles);
  ~Physics();
  Physics(const Physics&) = delete;
  Physics& operator=(const Physics&) = delete;

  /// Adds a foot-bot body (circle of kRobotRadius); robots get ids 0, 1, ... in call order.
  int add_robot(Vec2 position, double yaw);

  /// Differential drive (SPEC §1.2): v = (vL + vR)/2, omega = (vR - vL)/wheel base.
  /// Wheel speeds in m/s; applied as the body's velocity for the next step. Both wheels at zero
  /// brake the robot (a much heavier body, hard to push).
  void set_wheels(int id, double left_m_s, double right_m_s);

  /// One physics step of dt seconds.
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
