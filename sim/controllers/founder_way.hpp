// SPDX-License-Identifier: MIT
// lead_way [R] (task allocation, docs/detours.md): the goal's founder keeps the way of the trip that
// found the goal and tells it on the medium, one corner on every other tick, while it runs the
// protocol at the nest (SPEC §2.6 T4) and while it leads (T9); the decision makers and the
// allocated robots waiting or following listen, and a robot that hears the whole way walks it to
// the goal from the start once it loses its guide (T5), as the founder does while it leads. A chain's
// end that goes home to fetch more robots (refound_starved, T12) tells its way out to that end the same.
#pragma once

#include <cstdint>
#include <span>

#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

struct RobotMemory;

/// The founder's way to the goal: the breadcrumbs of the trip that found it (T2), for it to tell
/// and to lead along.
void keep_founder_way(const Params& p, RobotMemory& mem);

/// On odd ticks, the next corner of the founder's way (at most ToldWay::kMax, from where its trip
/// began to its crumb nearest the goal within R_vis + kWaySlack) into `cmd`; false on even ticks,
/// without lead_way, or when the robot knows no such way.
bool tell_founder_way(std::int64_t tick, int id, const Params& p, RobotMemory& mem, Command& cmd);

/// A decision maker, or an allocated robot waiting its turn to leave or following its guide, that
/// has not heard a founder's way whole.
bool listens_for_founder_way(const Params& p, const RobotMemory& mem, std::int64_t tick);

/// The corners heard in `inbox` from the teller heard first (the nearest; ties: the smaller id) are
/// kept in the robot's told way; once it is whole an allocated robot takes it as its route.
void hear_founder_way(std::span<const RabMessage> inbox, RobotMemory& mem);

/// An allocated robot that has heard a founder's way whole walks it (its route), from the start.
void take_founder_way(RobotMemory& mem);

}  // namespace swarmpath::sim
