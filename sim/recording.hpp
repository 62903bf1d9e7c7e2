// SPDX-License-Identifier: MIT
// A recorded run (.swrec): every k-th tick's robot poses, LEDs, controller states and chain links,
// every state change with the table row that fired, the milestones, the paths, and the scenario
// and params it ran with. The bytes are the format; the web viewer (web/viewer.js) reads the same.
//
//   offset 0   8 bytes   magic "SWREC\r\n\x1a"
//          8   u32 LE    format version (kRecordingVersion)
//         12   u32 LE    header length H
//         16   H bytes   header: UTF-8 JSON (everything but the frames and the state changes)
//     16 + H   u32 LE    body length in the file C, then u32 LE body length inflated R
//     24 + H   C bytes   body, zlib (RFC 1950): F frames, then E state changes
//
// A frame (N robots): i32 tick; u16 x[N], u16 y[N] (quantised positions, each the difference
// from the previous frame modulo 2^16; frame 0 from 0); u8 heading[N] (256 steps a turn);
// u8 led[N] (Led); u8 state[N] (RobotMemory::state); i32 parent[N], i32 child[N] (PfMemory's
// parent and child ids: a robot, kNestEmitter, kGoalEmitter or kNobody). A state change: i32 tick,
// i32 robot, u8 from, u8 to, u8 path-formation row, u8 task-allocation row (index + 1; 0: none).
// Little-endian throughout.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "controller.hpp"
#include "geometry.hpp"
#include "led.hpp"
#include "scenario.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

inline constexpr std::uint32_t kRecordingVersion = 1;
inline constexpr std::string_view kRecordingMagic{"SWREC\r\n\x1a", 8};

/// A named polyline of the run: the A* baseline or a chain at a milestone.
struct RecordedPath {
  std::string name;          ///< "astar", "subgoal", "opt1", "final"
  std::string label;         ///< legend text
  std::int64_t tick = -1;    ///< shown from this tick on (-1: always, the A* path)
  std::vector<Vec2> points;  ///< [m]
  std::vector<int> robots;   ///< chain robots, nest side first (empty for A*)
  double length_m = 0;
};

/// A moment the run reached (SPEC §4's T_chain, T_opt1, T_form, T_alloc, the goal in view).
struct Milestone {
  std::string name;  ///< short key: "goal", "chain", "opt1", "form", "alloc"
  std::string label;
  std::int64_t tick = -1;
};

/// Something the allocation did (founder, allocated robots, DONE), in words.
struct RecordedNote {
  std::int64_t tick = 0;
  int robot = 0;
  std::string text;
};

/// A robot's controller state changed during the tick before `tick`.
struct StateChange {
  std::int32_t tick = 0;
  std::int32_t robot = 0;
  std::uint8_t from = 0;
  std::uint8_t to = 0;
  std::uint8_t pf_row = 0;  ///< pf_row_number of the row that fired this tick (0: none)
  std::uint8_t ta_row = 0;  ///< ta_row_number ...
};

/// A transition table row's names, for the viewer's "recent transitions".
struct RowName {
  std::string row;
  std::string label;
};

struct LedName {
  std::string name;
  Rgb rgb{0, 0, 0};
};

/// A whole recording. Frame f, robot i of a per-robot array is at [f * robots + i].
struct Recording {
  // what ran
  std::string generator;      ///< the program that wrote it (version, commit)
  std::string scenario_name;  ///< e.g. "env4"
  std::string scenario_file;
  std::string scenario_toml;  ///< the scenario file's text, when known
  std::string params_toml;    ///< every parameter, as a params file
  EnvClass env_class = EnvClass::kOpen;
  Mode mode = Mode::kDiffusion;
  std::uint64_t seed = 0;
  int robots = 0;
  int ticks_per_second = 10;
  std::int64_t max_ticks = 0;
  std::int64_t every = 10;  ///< ticks between frames

  // the arena
  Vec2 arena_size;
  std::vector<Shape> obstacles;  ///< walls, boxes and cylinders (obstacle_shapes)
  Vec2 nest, goal;
  RectRegion deployment;
  double robot_radius = 0;  ///< [m]

  // positions: x = origin.x + quantum * qx
  Vec2 origin;
  double quantum = 0.001;  ///< [m]

  // names of the codes stored in frames and changes
  std::vector<std::pair<int, std::string>> state_names;  ///< state code -> name, codes present only
  std::vector<LedName> leds;                             ///< by Led code
  std::vector<RowName> pf_rows;                          ///< index + 1 = pf_row
  std::vector<RowName> ta_rows;                          ///< index + 1 = ta_row

  // what happened
  bool success = false;
  std::int64_t ticks = 0;  ///< ticks simulated
  std::uint64_t state_hash = 0;
  int allocated = -1;
  std::vector<Milestone> milestones;
  std::vector<RecordedPath> paths;
  std::vector<RecordedNote> notes;
  std::vector<StateChange> changes;

  // frames
  std::vector<std::int64_t> frame_ticks;
  std::vector<std::uint16_t> qx, qy;
  std::vector<std::uint8_t> heading;  ///< 256 steps a turn, 0 = +x, counter-clockwise
  std::vector<std::uint8_t> led;
  std::vector<std::uint8_t> state;
  std::vector<std::int32_t> parent, child;

  std::size_t frame_count() const { return frame_ticks.size(); }

  Vec2 position(std::size_t frame, int robot) const {
    const std::size_t k = frame * static_cast<std::size_t>(robots) + static_cast<std::size_t>(robot);
    return {origin.x + quantum * qx[k], origin.y + quantum * qy[k]};
  }

  double yaw(std::size_t frame, int robot) const;

  /// The name of a state code ("?" when the recording does not name it).
  std::string_view state_name(int code) const;
};

/// The quantised coordinate of x along an axis starting at `origin` (clamped to 0..65535).
std::uint16_t quantise(double x, double origin, double quantum);

/// The heading in 256 steps a turn.
std::uint8_t heading_code(double yaw);

/// The file's bytes.
std::string encode_recording(const Recording& r);

/// Reads a recording's bytes; throws ConfigError(`name`, ...) saying what is wrong with them.
Recording decode_recording(std::string_view bytes, const std::string& name);

}  // namespace swarmpath::sim
