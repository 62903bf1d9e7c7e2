// SPDX-License-Identifier: MIT
// The robot's sensors (SPEC §1.3), computed from a read-only snapshot of the world:
// 24-ray proximity ring, omnidirectional colour camera, range-and-bearing receiver.
// Each query is local (uniform grids), so sensing all robots is linear in their number.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "led.hpp"
#include "percept.hpp"
#include "spatial.hpp"

namespace swarmpath::sim {

/// What the sensors read: the world as it stood after the last physics step.
struct SensorView {
  std::span<const Pose> poses;
  std::span<const Led> leds;
  std::span<const int> tags;
  std::span<const std::uint8_t> rab_sending;
  std::span<const RabPayload> rab_out;
  std::span<const RabKinds> rab_kinds;  ///< the kinds of each robot's message (0: it sent none)
  /// per grid cell, its robots' rab_kinds or'ed (World::rab_cell_kinds: sense_all and step tally it)
  std::span<const RabKinds> rab_cell_kinds;
  std::span<const RabKinds> rab_row_kinds;  ///< the same per row of cells (World::rab_row_kinds)
  const RobotGrid* grid = nullptr;
  std::span<const Shape> shapes;           ///< every obstacle and wall
  const ShapeBins* touch_bins = nullptr;   ///< shapes within proximity reach of a cell
  const ShapeBins* camera_bins = nullptr;  ///< shapes within R_vis of a cell
  const ShapeBins* rab_bins = nullptr;     ///< shapes within RAB range of a cell
  Vec2 nest;
  Vec2 goal;
  double camera_range = 1.0;  ///< R_vis [m]
  bool occlude_by_robots = false;
  bool led_ring = true;  ///< a robot counts as seen when its LED ring is (false: its centre only)
};

/// Proximity ring: rays of kProximityRange from the body edge at proximity_angle(k), against
/// obstacles and other robots; readings follow proximity_response().
void sense_proximity(const SensorView& v, int id, std::array<double, kProximityCount>& out);

/// Camera: appends one blob per lit emitter (robots, nest and goal beacons) within R_vis whose
/// line of sight is not blocked by an obstacle (or, with the flag, another robot's body). A
/// robot counts as seen when its LED ring is: the line to its centre or to either of the ring's
/// tangent points (9 cm to the side) is clear.
void sense_camera(const SensorView& v, int id, std::vector<Blob>& out);

/// Range and bearing: appends the payloads broadcast last tick by robots within kRabRange with
/// line of sight past the obstacles, of the kinds in `interest` (v.rab_kinds), in grid order.
void sense_rab(const SensorView& v, int id, RabKinds interest, std::vector<RabMessage>& out);

}  // namespace swarmpath::sim
