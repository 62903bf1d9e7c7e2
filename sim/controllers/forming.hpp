// SPDX-License-Identifier: MIT
// SUBGOAL_FORMING (SPEC §2.3 rows #1 actions, #5-#8; paper, "Subgoal Formation"): a robot that found
// the goal or a RED subgoal backs off toward the nest and stops as the next subgoal d_sub from it,
// in the legs of FormLeg.
#pragma once

#include "pf_perception.hpp"

namespace swarmpath::sim {

struct RobotMemory;

// guards
bool found_subgoal_nearer_nest(const PfContext& c);     ///< #5r [R], label c while forming
bool target_at_subgoal_distance(const PfContext& c);    ///< #5
bool reached_nest_before_d_sub(const PfContext& c);     ///< #6a
bool entered_recovery_range(const PfContext& c);        ///< #6b
bool target_lost_in_visible_range(const PfContext& c);  ///< #7, label f
bool forming_timeout_target_seen(const PfContext& c);   ///< #8a
bool forming_timeout(const PfContext& c);               ///< #8b
bool lost_target_may_retry(const PfContext& c);         ///< #7h [R]: #7 or #8b, form_retries left

/// the goal beacon within d_detect, and (single_child) no robot in view claims it
bool goal_in_reach(const PfContext& c);

// actions
void take_target(const PfContext& c, PfMemory& m);  ///< #1: the goal if in reach, else the RED subgoal
void retarget(const PfContext& c, PfMemory& m);     ///< #5r: the RED subgoal nearer the nest
void target_becomes_parent(const PfContext& c, PfMemory& m);  ///< #5-#8: stop as the subgoal
void go_home_to_retry(const PfContext& c, PfMemory& m);       ///< #7h [R]: one retry spent, home

/// The forming robot's leg, after perception and before the table: at its target (within
/// d_detect) it backs off.
void next_form_leg(const Percept& in, const Params& p, PfMemory& m);

/// SUBGOAL_FORMING (LED white): toward the target, then back off toward the nest from it.
Command form_subgoal(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight);

/// rest_recruit [R] (T10): the robot starts SUBGOAL_FORMING from `red`, a free subgoal in view; it
/// walks to it first unless within d_detect of it or nearer the nest than it (then rows #5-#8).
void pf_join_chain_end(PfMemory& m, const Params& p, const Blob& red, const Pose& pose, Vec2 nest,
                       std::int64_t tick);

}  // namespace swarmpath::sim
