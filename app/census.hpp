// SPDX-License-Identifier: MIT
// A recorded run counted (view --census): the robot-ticks spent in each controller state, the table
// rows that fired, and the trips (each stay of a robot in one exploring state), by that state: how
// many, how long, and the state each ended in. From the recording's state changes, which it holds
// tick by tick; and, from its frames, the robots that stood still where they were meant to move
// (stalls.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include "sim/recording.hpp"

namespace swarmpath::app {

nlohmann::ordered_json census(const sim::Recording& r);

}  // namespace swarmpath::app
