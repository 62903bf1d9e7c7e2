// SPDX-License-Identifier: MIT
// RESTING_TASK (SPEC §2.6 T6, T7; paper Eq. (4)-(5)): a robot that task allocation does not need
// goes back to its own deployment point and rests there, LEDs off, broadcasting ALLOC_DONE; it gives
// way to a robot pressing through the crowd (give_way), and joins a chain that ran out of robots
// (rest_recruit, recruit_call: T10; refound_starved: T11).
#pragma once

#include <span>

#include "sim/params.hpp"
#include "sim/percept.hpp"
#include "task_allocation.hpp"

namespace swarmpath::sim {

struct RobotMemory;

/// To `point` (the nest: along the robot's trail once the field traps it) and stop within reach.
/// `retrace`: nav_home's (founder_retrace).
Command drive_to(const Percept& in, const Params& p, RobotMemory& mem, Vec2 point, double stop_within_cm,
                 Led led, bool retrace = false);

/// recruit_call [R]: the nearest subgoal calling for a link that no robot on the medium claims.
const RabMessage* unanswered_call(std::span<const RabMessage> inbox);

/// RESTING_TASK: to the deployment point with the field of Eq. (4)-(5), then rest; ALLOC_DONE on the
/// medium, or a JOIN to a founder allocating from the resting robots (T11).
Command rest(const Percept& in, const Params& p, RobotMemory& mem, const TaSight& sight);

}  // namespace swarmpath::sim
