// SPDX-License-Identifier: MIT
// Reactive motion with an escape from local minima [R]. The paper's robots move by potential
// fields (toward the nest, away from it while exploring), and a field has local minima in front
// of obstacles: a robot heading for the nest stops against the near face of a box, an explorer
// heading away from the nest stops against its far side. When a robot has made no progress (a
// gain of trap_progress, 30 cm) for T_trap ticks it follows the obstacle's edge, Bug-style, until
// it has made 20 cm of progress past where the following began with the way ahead clear. The side
// is chosen afresh at each obstacle, from the robot's heading; at a dead end (no progress for 5
// T_trap, or T_follow ticks gone) it turns back along the same edge once (the way back may lose
// ground for a while, so only T_follow limits it), and when that fails too it has "given up".
#pragma once

#include <cstdint>

#include "route.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"
#include "sim/rng.hpp"
#include "trail.hpp"

namespace swarmpath::sim {

struct NavMemory {
  double best = -1e18;             ///< best progress since it last improved [cm]
  std::int64_t stalled = 0;        ///< ticks since progress last improved by trap_progress
  double short_best = -1e18;       ///< nav_home with a window shorter than T_trap: its own record [cm]
  std::int64_t short_stalled = 0;  ///< ... ticks since progress improved by trap_progress pro rata
  std::int64_t following = 0;      ///< ticks left of edge following (0: not following)
  double follow_from = 0;          ///< progress when the following began [cm]
  std::int8_t side = 0;            ///< obstacle kept on the right (+1) or the left (-1); 0: not chosen
  std::int64_t off_edge = 0;       ///< ticks of the current following without any proximity reading
  bool on_trail = false;           ///< going home along the breadcrumbs
  bool fell_back = false;          ///< ... from a crumb it has been at, the nearest one having trapped it
  bool reversed = false;           ///< the current following has already turned back once
};

/// Clears the progress record (call when the robot starts on a new leg); keeps the side so that
/// consecutive followings alternate.
void nav_reset(NavMemory& nav);

/// Books this tick's progress (larger is better, cm: minus the distance to a point, or the
/// distance from the nest while exploring) and starts or ends edge following. Following starts
/// only against an obstacle the proximity ring senses; it ends once the robot has made progress
/// past where it began AND the sensors facing `wanted` (robot frame, the field's direction) read
/// nothing, or when the edge has been out of range for 100 ticks. A following that runs out
/// flips the side for the next. Returns whether the robot should follow an edge this tick.
/// `crowded` [R nest_crowd]: among robots packed round the nest, an edge is only another robot
/// and following it leads nowhere; the navigator forgets its record and leaves the way to the field.
bool nav_update(NavMemory& nav, const Params& p, Rng& rng, double progress_cm, const Percept& in, Vec2 wanted,
                bool crowded = false);

/// Robot-frame unit direction along the sensed obstacle's edge, keeping it on `side` (+1 right,
/// -1 left) at about 4 cm; with nothing in range, a curve toward that side to round a corner.
Vec2 follow_edge(const Percept& in, int side);

/// Toward `point` (global, m): the potential field, or the edge while following (never when
/// `crowded`, as in nav_update).
Vec2 nav_toward(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Vec2 point,
                bool crowded = false);

/// Toward the nest: the potential field; once the field has trapped the robot, its breadcrumb
/// trail (when it has one); the edge while following.
/// `trap_ticks` (default T_trap) is how long the field may make no progress before the trail;
/// a window shorter than T_trap asks for trap_progress pro rata (a quarter of T_trap: a quarter of
/// trap_progress), the same rate of progress as T_trap does. The field pulls toward `field_point`
/// (default: the nest itself). `retrace` [R founder_retrace]: a trail home that would begin at its
/// first crumb (where the trip began: the nest, what the field already steers at) begins instead
/// where the robot last was on its way (Trail::fall_back), also near the nest.
Vec2 nav_home(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Trail& trail, Vec2 nest,
              double trap_ticks = -1.0, const Vec2* field_point = nullptr,
              double trail_within = Trail::kEverywhere, bool retrace = false);

/// Toward `to` along `route` [R route_to_sighting]: crumb after crumb, progress measured along the way
/// left (as nav_home's trail), a crumb it cannot reach passed over after T_trap ticks without progress;
/// once the way is walked (or when there is none), nav_toward(`to`).
Vec2 nav_route(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Route& route, Vec2 to,
               bool crowded = false);

/// A navigating robot's heading (robot frame): the navigator's direction `f` plus the proximity ring's
/// avoidance (diffusion), which edge following leaves out, since it keeps to the edge itself.
Vec2 with_avoidance(const Percept& in, const Params& p, const NavMemory& nav, Vec2 f);

}  // namespace swarmpath::sim
