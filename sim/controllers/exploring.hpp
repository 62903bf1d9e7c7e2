// SPDX-License-Identifier: MIT
// EXPLORING, RETURN_TO_NEST and RESTING (SPEC §2.1, §2.3 rows #1-#4; paper, "Exploring" and "Return
// To Nest"): explorers walk away from the nest on a random heading for their budget T_explore, the
// trips that find nothing go home, rest, and go out again with a larger budget. A trip moves in the
// legs of ExploreLeg.
#pragma once

#include "pf_perception.hpp"

namespace swarmpath::sim {

struct RobotMemory;

// guards
bool found_goal_or_subgoal(const PfContext& c);  ///< #1, label c
bool found_on_the_way_home(const PfContext& c);  ///< #1h [R return_finds]
bool exploration_time_over(const PfContext& c);  ///< #2, label b (or the trip ended)
bool reached_nest(const PfContext& c);           ///< #3, label d
bool resting_time_over(const PfContext& c);      ///< #4, label i

/// #4: "increase the minimum exploring time"
void grow_budget(const PfContext& c, PfMemory& m);

/// The first leg of a trip: to the last sighting first (site_fidelity), else exploring.
ExploreLeg first_leg(const Params& p, const PfMemory& m);

/// resume_search [R]: keeps the trip's way (its breadcrumbs) and where it ended, for the next trip to
/// travel along before it explores; false when the trip left no way (fewer than two crumbs).
bool keep_frontier(RobotMemory& mem);

/// EXPLORING (LED green): V = v_max (D + w_away F_away(nest) + w_rw u_phi + R), after the trip's
/// travel legs; the obstacle's edge when the robot can get no farther from the nest.
Command explore(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight);

/// V = v_max (D + F_toward(nest) + R): returning robots and robots backing off along their trail;
/// F is the navigator's direction (the field, the trail, or the obstacle's edge when trapped).
Command go_to_nest(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight, PfState s);

}  // namespace swarmpath::sim
