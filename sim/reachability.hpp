// SPDX-License-Identifier: MIT
// Whether a robot can drive from one point of a scenario to another at all: a goal that no robot
// can reach makes every run fail and the A* baseline empty, so a scenario with one is refused when
// it is loaded.
#pragma once

#include "scenario.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

/// True when a robot's centre (radius kRobotRadius) can travel from `from` to `to` between the
/// scenario's obstacles and walls. A flood fill over square cells of 2 cm (coarser on large arenas:
/// at most about a million cells) in which a cell is blocked only when every point of it lies
/// within kRobotRadius of an obstacle: the check never refuses a way a robot could take, so a gap a
/// few millimetres narrower than a robot may still pass it (the A* baseline, SPEC §4.5, decides there).
bool robot_can_drive(const Scenario& s, Vec2 from, Vec2 to);

}  // namespace swarmpath::sim
