// SPDX-License-Identifier: MIT
#include "exploring.hpp"

#include <algorithm>

#include "forming.hpp"
#include "navigation.hpp"
#include "path_formation.hpp"
#include "sighting_share.hpp"
#include "sim/controller.hpp"
#include "sim/motion.hpp"
#include "units.hpp"

namespace swarmpath::sim {

bool found_goal_or_subgoal(const PfContext& c) {
  if (c.m.role == PfRole::kScout) return false;  // a TA scout that finds the goal becomes the founder instead
  // one at a time [R]: while another robot in view is forming, wait for it to become the tip
  if (c.p.form_one_at_a_time && c.sight.forming_in_view) return false;
  // ... and robots waiting for one do not all start in the same tick (p_form per tick)
  if (c.p.form_one_at_a_time && !c.sight.may_form) return false;
  return goal_in_reach(c) || c.sight.red_near != nullptr;
}

// [R return_finds]: a robot going home still finds the goal it passes (not a subgoal: robots go
// home past the chain, and each would start a side branch)
bool found_on_the_way_home(const PfContext& c) {
  return c.p.return_finds && c.m.role != PfRole::kScout && goal_in_reach(c);
}

bool exploration_time_over(const PfContext& c) {
  // travelling back to a sighting does not spend the budget (travel_cap budgets at most)
  const double spent = static_cast<double>(c.m.t_state - c.m.travel_ticks);
  const bool lost_way =
      c.p.travel_cap > 0.0 && static_cast<double>(c.m.travel_ticks) >= c.p.travel_cap * c.m.t_explore;
  return spent >= c.m.t_explore || c.m.explore_leg == ExploreLeg::kTripOver || lost_way;
}

bool reached_nest(const PfContext& c) {
  return static_cast<double>(c.m.nest_ticks) >= std::max(1.0, c.p.t_nest_search);
}

bool resting_time_over(const PfContext& c) { return static_cast<double>(c.m.t_state) >= c.p.t_rest; }

void grow_budget(const PfContext& c, PfMemory& m) {
  m.t_explore = std::min((m.t_explore + c.p.dt_explore) * c.p.g_explore, c.p.t_explore_max);
}

ExploreLeg first_leg(const Params& p, const PfMemory& m) {
  return p.site_fidelity && m.has_sighting ? ExploreLeg::kToSighting : ExploreLeg::kWalk;
}

namespace {

bool following(ExploreLeg leg) {
  return leg == ExploreLeg::kFollowThenWalk || leg == ExploreLeg::kFollowThenSighting;
}

// the leg after following the guides
ExploreLeg after_following(ExploreLeg leg) {
  return leg == ExploreLeg::kFollowThenSighting ? ExploreLeg::kToSighting : ExploreLeg::kWalk;
}

// Guided departure [R] (task allocation): an allocated robot's first trip follows the CYAN lights,
// the founder going back to the goal and the robots following it, keeping guide_gap from the one
// fewest hops from the founder (ties: farthest from the nest); the goal, a free RED subgoal or a
// forming robot in view ends it, and so does seeing no guide for T_guide_lost. Following does not
// spend the budget (it is travel, like row 2's). False when the following has just ended.
bool follow_guide(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight, Command& cmd) {
  PfMemory& m = mem.pf;
  if (sight.lure != nullptr || sight.forming_link != nullptr) {
    m.explore_leg = after_following(m.explore_leg);
    return false;
  }
  if (sight.guide == nullptr) {
    if (static_cast<double>(++m.guide_unseen) >= p.t_guide_lost) {
      m.explore_leg = after_following(m.explore_leg);
      return false;
    }
  } else {
    m.guide_unseen = 0;
    m.guide_hops = (sight.guide->tag == kNobody ? 0 : sight.guide->tag) + 1;
  }
  ++m.travel_ticks;
  mem.trail.record(in.pose.p);
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (avoid.collision ? avoid.direction : Vec2{}) + sight.repulsion;
  if (sight.guide != nullptr) {
    const double gap = std::clamp((sight.guide->distance_cm - p.guide_gap) / p.guide_gap, -1.0, 1.0);
    v += gap * sight.guide->dir;
  }
  cmd = pf_drive(p, mem, p.v_max * v, PfState::kExploring);
  cmd.led = Led::kCyan;
  return true;
}

// seek_tip [R]: an allocated explorer that sees a robot forming the next link (WHITE) and no
// free subgoal walks to it and waits tip_hover from it for the RED it becomes, which lures it
// (row 1). Waiting spends the budget, and ends a travel leg.
Command wait_by_forming_robot(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  PfMemory& m = mem.pf;
  if (m.explore_leg == ExploreLeg::kToSighting || m.explore_leg == ExploreLeg::kLead)
    m.explore_leg = ExploreLeg::kWalk;
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (avoid.collision ? avoid.direction : Vec2{}) + sight.repulsion;
  const double gap = std::clamp((sight.forming_link->distance_cm - p.tip_hover) / p.tip_hover, -1.0, 1.0);
  if (gap > 0.0) v += gap * sight.forming_link->dir;
  return pf_drive(p, mem, p.v_max * v, PfState::kExploring);
}

// a travel leg over: the random walk goes on along the robot's heading, from where it stands
void walk_on_from_here(const Pose& pose, RobotMemory& mem) {
  mem.walk_heading = pose.yaw();
  mem.walk_dir = {pose.c, pose.s};
  nav_reset(mem.nav);
}

// site fidelity: travelling to the sighting (the founder leading at guide_speed, CYAN); there, or
// with a lure in view, the robot explores from where it stands, or (sighting_returns) with nothing
// free there, its trip is over: the tip has moved nestward, past this robot, and its way home
// passes it. False when the travel has just ended.
bool travel_to_sighting(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight,
                        bool in_crowd, Command& cmd) {
  PfMemory& m = mem.pf;
  ++m.travel_ticks;
  if (sight.lure != nullptr || dist(in.pose.p, m.sighting) < 0.5) {
    const bool nothing_there = p.sighting_returns && claims_links(p, m) && sight.lure == nullptr;
    m.explore_leg = nothing_there ? ExploreLeg::kTripOver : ExploreLeg::kWalk;
    m.answering = -1;
    walk_on_from_here(in.pose, mem);
    return false;
  }
  // R (walk_way: task allocation; share_way: path formation; lead_way: the founder's, told at the
  // nest): a way to the sighting, its own or one heard whole, is walked from the start
  const bool walk_way =
      (p.share_way || ((p.walk_way || p.lead_way) && m.role != PfRole::kSwarm)) && m.knows_way;
  if (walk_way && !mem.route.begun_for(m.trip_start, m.sighting)) {
    mem.route.set_trip(m.trip_start, m.sighting);
    mem.route.begin(in.pose.p, m.sighting, p.r_vis * kCm + kWaySlack, dist(in.pose.p, mem.nest));
    nav_reset(mem.nav);
  }
  Vec2 f;
  if ((p.route_to_sighting || walk_way) && mem.route.begun_for(m.trip_start, m.sighting)) {
    f = nav_route(in, p, mem.nav, mem.rng, mem.route, m.sighting, in_crowd);
  } else {
    f = nav_toward(in, p, mem.nav, mem.rng, m.sighting, in_crowd);
    // R (route_to_sighting): trapped by the field (edge following begins), along the way of the trip
    // that saw the sighting, if that way passed within R_vis of it, from where the robot can be on it
    if (p.route_to_sighting && mem.nav.following > 0) {
      mem.route.set_trip(m.trip_start, m.sighting);
      if (mem.route.begin(in.pose.p, m.sighting, p.r_vis * kCm, dist(in.pose.p, mem.nest))) {
        nav_reset(mem.nav);
        f = nav_route(in, p, mem.nav, mem.rng, mem.route, m.sighting, in_crowd);
      }
    }
  }
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  if (m.explore_leg != ExploreLeg::kLead) {
    cmd = pf_drive(p, mem, p.v_max * v, PfState::kExploring);
    return true;
  }
  cmd = pf_drive(p, mem, p.guide_speed * p.v_max * v, PfState::kExploring);
  cmd.led = Led::kCyan;
  return true;
}

// resume_search: the way ends at its last crumb, where the trip ended
constexpr double kFrontierSeen = 0.01;  // [m]

// R (resume_search): along the way of the last trip, which saw nothing, to where it ended; there, or
// with a lure in view, the robot explores from where it stands. Travel, not budget (travel_cap
// bounds it). False when the travel has just ended.
bool travel_to_frontier(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight,
                        bool in_crowd, Command& cmd) {
  PfMemory& m = mem.pf;
  if (sight.lure != nullptr || dist(in.pose.p, m.frontier) < 0.5) {
    m.explore_leg = ExploreLeg::kWalk;
    walk_on_from_here(in.pose, mem);
    return false;
  }
  ++m.travel_ticks;
  if (!mem.route.begun_for(m.trip_start, m.frontier)) {
    mem.route.set_trip(m.trip_start, m.frontier);
    mem.route.begin(in.pose.p, m.frontier, kFrontierSeen, dist(in.pose.p, mem.nest));
    nav_reset(mem.nav);
  }
  const Vec2 f = nav_route(in, p, mem.nav, mem.rng, mem.route, m.frontier, in_crowd);
  cmd =
      pf_drive(p, mem, p.v_max * (with_avoidance(in, p, mem.nav, f) + sight.repulsion), PfState::kExploring);
  return true;
}

}  // namespace

bool keep_frontier(RobotMemory& mem) {
  if (mem.trail.size() < 2) return false;
  mem.pf.frontier = mem.trail.crumb(mem.trail.size() - 1);
  mem.route.keep(mem.trail);
  return true;
}

Command explore(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  mem.trail.record(in.pose.p);
  if (mem.nav.following > 0) mem.trail.mark_edge();
  update_walk_heading(mem.walk_heading, mem.walk_dir, mem.rng, p);
  PfMemory& m = mem.pf;
  Command cmd;
  if (following(m.explore_leg) && follow_guide(in, p, mem, sight, cmd)) return cmd;
  if (sight.lure == nullptr && sight.forming_link != nullptr) return wait_by_forming_robot(in, p, mem, sight);
  // R (nest_crowd): robots crowd the nest in task allocation; edge following them is no way out
  const bool in_crowd = sight.nest_distance_cm < crowd_radius_cm(p, m);
  const bool travelling = m.explore_leg == ExploreLeg::kToSighting || m.explore_leg == ExploreLeg::kLead;
  if (travelling && travel_to_sighting(in, p, mem, sight, in_crowd, cmd)) return cmd;
  if (m.explore_leg == ExploreLeg::kToFrontier && travel_to_frontier(in, p, mem, sight, in_crowd, cmd))
    return cmd;
  // away from the nest; the obstacle's edge when the field traps the robot (no lure in view)
  if (sight.lure == nullptr) {
    const bool trapped = nav_update(mem.nav, p, mem.rng, sight.nest_distance_cm, in,
                                    -field_toward(in.pose, mem.nest), in_crowd);
    if (trapped) return pf_drive(p, mem, p.v_max * follow_edge(in, mem.nav.side), PfState::kExploring);
  }
  const Avoidance avoid = diffusion(in.proximity, p);
  const Vec2 away = -field_toward(in.pose, mem.nest);
  Vec2 v = avoid.direction + m.w_away * away + p.w_rw * in.pose.to_local(mem.walk_dir) + sight.repulsion;
  if (sight.lure != nullptr) v += p.w_seek * sight.lure->dir;
  v *= p.v_max;
  return pf_drive(p, mem, v, PfState::kExploring);
}

Command go_to_nest(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight, PfState s) {
  const Avoidance avoid = diffusion(in.proximity, p);
  // [R return_lured] a task-allocation scout going home that sees the goal has found it: to it, and T2
  if (s == PfState::kReturnToNest && mem.pf.role == PfRole::kScout && p.return_finds && p.return_lured &&
      sight.goal != nullptr)
    return pf_drive(p, mem, p.v_max * (avoid.direction + sight.goal->dir + sight.repulsion), s);
  const Vec2 f = nav_home(in, p, mem.nav, mem.rng, mem.trail, mem.nest);
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  return pf_drive(p, mem, p.v_max * v, s);
}

}  // namespace swarmpath::sim
