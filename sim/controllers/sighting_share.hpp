// SPDX-License-Identifier: MIT
// share_sighting [R] (path formation without task allocation): robots at the nest tell each other
// where they last saw the goal or the chain, over the range-and-bearing medium, as task
// allocation's founder tells its allocated robots where it saw the goal (share_goal, SPEC §2.6 T5).
// A resting robot without a sighting of its own takes the one it hears, and its next trip starts
// toward it (site_fidelity); a trip that sees nothing there forgets it on the way home.
#pragma once

#include <cstdint>

#include "pf_memory.hpp"
#include "route.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

/// Whether robot `m` may tell at `tick`: with share_after_trips > 0, once it has come home that many
/// times from a trip without a sighting (its own record of a stalled search; share_after then plays
/// no part); otherwise from tick share_after of the run on.
bool may_tell(const Params& p, const PfMemory& m, std::int64_t tick);

/// A robot of path formation without task allocation that knows a sighting tells it while it is
/// within share_sighting of the nest (`nest_distance_cm` from the positioning sensor), when it may
/// (may_tell).
bool tells_sighting(const Params& p, const PfMemory& m, double nest_distance_cm, std::int64_t tick);

/// A resting robot of path formation without task allocation with no sighting of its own listens at
/// `tick` under the condition of the telling: a message is heard one tick after it is told, so from
/// tick share_after + 1 of the run on, or (share_after_trips > 0) once it has made that many
/// fruitless trips itself. Before then nobody it could hear tells.
bool listens_for_sighting(const Params& p, const PfMemory& m, std::int64_t tick);

/// The message telling `m.sighting` (relative to the nest, in cm) from robot `id`, into `cmd`.
void tell_sighting(int id, Vec2 nest, const PfMemory& m, Command& cmd);

/// The sighting told by the nearest robot heard (ties: the smaller id) becomes this robot's own
/// (not seen on this trip, so that a trip that finds nothing there forgets it); false when none.
/// With share_way the robot then listens for that teller's way (listens_for_way).
bool hear_sighting(std::span<const RabMessage> inbox, Vec2 nest, PfMemory& m);

/// share_way [R]: a way to a sighting ends at its crumb nearest the sighting within R_vis and this
/// much more [m]: the robot saw it from within R_vis, and its trail keeps a crumb every 25 cm (fewer
/// on straight stretches).
inline constexpr double kWaySlack = 0.5;

/// share_way [R]: the corners of the way to `m.sighting` that the robot tells (m.tell_corners,
/// m.tell_count: 0 when its route does not come near the sighting), worked out when the route or
/// the sighting has changed. With share_way a robot tells only when it knows such a way.
void work_out_way(const Params& p, const Route& route, PfMemory& m);

/// share_way, lead_way [R]: on odd ticks, the corner of the robot's way to `m.sighting` it tells at
/// `tick` (work_out_way's, one after another): its index `k` and where it lies relative to `nest`
/// [cm]. False on even ticks, and when the robot knows no such way.
bool corner_to_tell(const Params& p, const Route& route, PfMemory& m, std::int64_t tick, Vec2 nest, int& k,
                    Vec2& rel_cm);

/// share_way [R]: a teller that knows a way to its sighting (its own trip's, or one heard whole)
/// tells, on odd ticks, one corner of that way after another (work_out_way: at most ToldWay::kMax,
/// from where the way began near the nest to its crumb nearest the sighting within R_vis +
/// kWaySlack), instead of the sighting, which it tells on even ticks. False (tell the sighting)
/// when it knows no such way.
bool tell_way(int id, Vec2 nest, const Params& p, const Route& route, PfMemory& m, std::int64_t tick,
              Command& cmd);

/// share_way [R]: a robot that took a teller's sighting and has not heard its whole way listens for
/// it, resting or on its trip (within the medium's 3 m of the teller).
bool listens_for_way(const Params& p, const PfMemory& m);

/// share_way [R]: the corners of the teller's way heard in `inbox` are kept; false when none.
bool hear_way(std::span<const RabMessage> inbox, Vec2 nest, PfMemory& m);

}  // namespace swarmpath::sim
