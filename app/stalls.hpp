// SPDX-License-Identifier: MIT
// Robots that stood still where they were meant to move (view --census, "stalls"): a stay of one
// robot in one travelling state (exploring, going home, forming a subgoal, a goal founder on its way)
// within kStallCm of where the stay began, for kStallTicks or more, found in the recording's frames.
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/recording.hpp"

namespace swarmpath::app {

inline constexpr std::int64_t kStallTicks = 2000;  ///< 200 s
inline constexpr double kStallCm = 25.0;

struct Stall {
  int robot = 0;
  int state = 0;  ///< the recording's state code
  std::int64_t from = 0;
  std::int64_t ticks = 0;
  sim::Vec2 at;  ///< where it stood [m]
};

/// Every stall of the recording, robot by robot, each in tick order.
std::vector<Stall> find_stalls(const sim::Recording& r);

/// The census's "stalls": the thresholds, the count and robot-ticks by state, and the ten longest.
nlohmann::ordered_json stalls_json(const sim::Recording& r);

}  // namespace swarmpath::app
