// SPDX-License-Identifier: MIT
// Everything that changes during a run (MuJoCo's mjData to the Scenario's mjModel): robot
// poses, LEDs, controller memory, the Box2D world, the neighbour grid and the per-tick sensor
// buffers. One World per evaluation, never shared between threads.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "controller.hpp"
#include "faults.hpp"
#include "params.hpp"
#include "percept.hpp"
#include "physics.hpp"
#include "scenario.hpp"
#include "spatial.hpp"

namespace swarmpath::sim {

struct World {
  std::int64_t tick = 0;
  Mode mode = Mode::kDiffusion;
  std::uint64_t seed = 0;

  std::unique_ptr<Physics> physics;
  std::vector<Shape> shapes;  ///< obstacle_shapes(scenario)
  ShapeBins touch_bins;       ///< shapes within proximity reach of each cell
  ShapeBins camera_bins;      ///< ... within R_vis
  ShapeBins rab_bins;         ///< ... within RAB range
  RobotGrid grid;

  // robot state, indexed by robot id (= Box2D creation order)
  std::vector<Pose> poses;
  std::vector<Vec2> positions;
  std::vector<Led> leds;                  ///< as set by the last act phase
  std::vector<int> tags;                  ///< advertised with the LEDs (vision + ID)
  std::vector<std::uint8_t> rab_sending;  ///< broadcast last tick
  std::vector<RabPayload> rab_out;
  std::vector<RabKinds> rab_kinds;  ///< the kinds of message each robot broadcast last tick (0: none)
  /// Per cell of `grid`: the kinds its robots broadcast last tick (their rab_kinds or'ed), so that a
  /// listener skips the cells that hold nothing it reads. Tallied as a tick's sensing starts.
  std::vector<RabKinds> rab_cell_kinds;
  /// The same per row of cells (its cells' kinds or'ed): a listener skips a row at once.
  std::vector<RabKinds> rab_row_kinds;
  /// The medium hands each robot only the kinds of message it reads (rab_interest); false: every
  /// message to every robot that listens (what the readers then see is the same, at more cost).
  /// make_world sets it false under packet loss, which draws a loss for every message handed out.
  bool rab_by_kind = true;
  std::vector<RobotMemory> memory;
  std::vector<Command> commands;
  FaultState faults;  ///< failures and noise streams (Scenario::faults)

  // per-tick sensor buffers, reused so that a tick allocates nothing after warm-up
  SensorNeeds needs;
  std::vector<Percept> percepts;  ///< sized and filled by sense_all (phase by phase); step() needs one
  std::vector<Blob> blobs;
  std::vector<std::size_t> blob_begin;
  std::vector<RabMessage> rab_inbox;
  std::vector<std::size_t> rab_begin;

  int robot_count() const { return static_cast<int>(poses.size()); }
};

/// Builds the world: obstacles, then `s.robots` robots placed uniformly in the deployment region
/// (no overlap: centre distance >= min_spacing; clear of obstacles), uniform random yaw, all
/// drawn from `seed`. Throws ConfigError when the region cannot be filled.
World make_world(const Scenario& s, const Params& p, Mode mode, std::uint64_t seed);

/// Same, with the robots at the given start poses instead of a random deployment (tests, scripted
/// set-ups); the scenario's robot count is ignored.
World make_world(const Scenario& s, const Params& p, Mode mode, std::uint64_t seed,
                 std::span<const Pose> start);

/// The deployment positions and yaws alone (what make_world uses), for tests and pictures.
std::vector<Pose> deploy(const Scenario& s, std::span<const Shape> shapes, std::uint64_t seed);

/// Robot `id` fail-stops now: its wheels stop (braked, it stays where it is as an obstacle), its
/// LEDs go dark, it no longer senses, decides or sends; its memory stays as it was.
void fail_robot(World& w, int id);

/// Whether robot `id` has failed.
inline bool has_failed(const World& w, int id) {
  const auto i = static_cast<std::size_t>(id);
  return i < w.faults.failed.size() && w.faults.failed[i] != 0;
}

/// A hash of every robot's pose, controller state, turning mode and LED, and the tick:
/// two runs with equal hashes went the same way.
std::uint64_t state_hash(const World& w);

}  // namespace swarmpath::sim
