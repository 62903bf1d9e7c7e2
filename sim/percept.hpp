// SPDX-License-Identifier: MIT
// What a controller sees (Percept) and what it asks for (Command). No Box2D types: the
// controllers are written against these readings only, as ARGoS controllers are against CCI_*.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "led.hpp"
#include "robot_model.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

/// Positioning sensor: exact global pose (SPEC §1.3) as position and heading rotation.
struct Pose {
  Vec2 p;          ///< [m]
  double c = 1.0;  ///< cos(heading)
  double s = 0.0;  ///< sin(heading)

  /// Heading [rad], (-pi, pi].
  double yaw() const { return std::atan2(s, c); }

  /// A world-frame vector in this robot's frame.
  Vec2 to_local(Vec2 world) const { return unrotate(world, c, s); }

  /// A robot-frame vector in the world frame.
  Vec2 to_world(Vec2 local) const { return rotate(local, c, s); }
};

/// Emitter ids of the two beacons; robots are 0..N-1.
inline constexpr int kNestEmitter = -1;
inline constexpr int kGoalEmitter = -2;
/// An emitter id that matches nothing ("no reference", "no tag").
inline constexpr int kNobody = -100;

/// One camera blob per visible LED emitter (SPEC §1.3).
struct Blob {
  Led color = Led::kBlack;
  int emitter = 0;         ///< robot id, kNestEmitter or kGoalEmitter
  Vec2 dir{1.0, 0.0};      ///< unit vector toward the emitter, robot frame
  double distance_cm = 0;  ///< horizontal distance [cm]
  int tag = kNobody;       ///< what the emitter advertises with its light (vision + ID, SPEC §2.1)

  /// Bearing relative to the heading [rad], (-pi, pi], counter-clockwise positive.
  double bearing() const { return angle_of(dir); }
};

using RabPayload = std::array<std::uint8_t, kRabPayloadBytes>;

/// Kinds of range-and-bearing message, as bits that the controller gives its messages (rab_kinds):
/// the medium delivers a message only to the robots that read one of its kinds this tick
/// (rab_interest), so that a robot is not handed the crowd's chatter it would skip.
using RabKinds = std::uint32_t;
inline constexpr RabKinds kEveryRabKind = ~RabKinds{0};

/// One range-and-bearing reception, sent the tick before (SPEC §1.3).
struct RabMessage {
  int sender = 0;
  double range_cm = 0;
  Vec2 offset;  ///< the sender relative to the receiver, in the receiver's frame [m]
  RabPayload data{};

  /// Bearing relative to the receiver's heading [rad], (-pi, pi]: computed when asked, since few
  /// readers want it and the medium delivers every message to every robot in range.
  double bearing() const { return angle_of(offset); }
};

struct Percept {
  std::int64_t tick = 0;
  int id = 0;
  Pose pose;
  std::array<double, kProximityCount> proximity{};  ///< foot-bot readings in [0, 1]
  std::span<const Blob> blobs;                      ///< camera, within R_vis, line of sight
  std::span<const RabMessage> rab;                  ///< received this tick
};

struct Command {
  double left_cm_s = 0;  ///< wheel linear speeds [cm/s]
  double right_cm_s = 0;
  Led led = Led::kBlack;
  int tag = kNobody;      ///< advertised with the LED to cameras that read ids (vision + ID)
  bool rab_send = false;  ///< broadcast `rab` this tick
  RabPayload rab{};
};

/// Which sensors a controller reads; the simulator computes only these.
struct SensorNeeds {
  bool proximity = true;
  bool camera = false;
  bool rab = false;
};

}  // namespace swarmpath::sim
