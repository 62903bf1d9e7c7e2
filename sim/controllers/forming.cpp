// SPDX-License-Identifier: MIT
#include "forming.hpp"

#include <algorithm>

#include "exploring.hpp"
#include "navigation.hpp"
#include "path_formation.hpp"
#include "sim/controller.hpp"
#include "units.hpp"

namespace swarmpath::sim {

namespace {

bool nestward_of_target(const PfContext& c, Vec2 at) {
  if (!c.p.subgoal_nestward) return true;  // SPEC's rows #5, #6b: anywhere d_sub from the target
  // R (spot_on_way, task allocation; spot_on_way_pf): at its spot on the way it came, nearer the
  // nest along that way
  constexpr double kWaySpotReach = 0.25;  // [m] one crumb's spacing
  if (by_mode(c.m.role, c.p.spot_on_way_pf, c.p.spot_on_way) && c.m.has_way_spot &&
      c.m.way_spot_for == c.m.target.id && dist(at, c.m.way_spot) <= kWaySpotReach)
    return true;
  // R (link_outward, task allocation; link_outward_pf): on its own way from the nest, wherever the
  // new link extends the chain
  if (by_mode(c.m.role, c.p.link_outward_pf, c.p.link_outward) && c.on_trail && c.m.target.visible) {
    const Blob* t = blob_of(c.in, c.m.target.id);
    if (t != nullptr && t->distance_cm < c.sight.other_chain_cm) return true;
  }
  // R (anywhere_after_edge, task allocation; anywhere_after_edge_pf): a way that went round an
  // obstacle may lead away from the nest first
  const bool anywhere = by_mode(c.m.role, c.p.anywhere_after_edge_pf, c.p.anywhere_after_edge);
  if (anywhere && c.on_trail && c.went_round) return true;
  // nearer the nest than the target; retracing its own way home (which may wind round an
  // obstacle's end) a robot may stop up to trail_slack farther [R]: more, and the chain knots
  const double slack = c.on_trail ? c.p.trail_slack * kCm : 0.0;
  return dist(at, c.nest) < dist(c.m.target.last_seen, c.nest) + slack;
}

// has been within d_detect of its target (rows #5 and #6b need it)
bool target_reached(const PfMemory& m) { return m.form_leg != FormLeg::kToTarget; }

}  // namespace

bool goal_in_reach(const PfContext& c) {
  return c.sight.goal != nullptr && c.sight.goal->distance_cm <= c.p.d_detect && !c.sight.goal_claimed;
}

bool found_subgoal_nearer_nest(const PfContext& c) {
  return c.p.retarget_nearer && c.sight.red_nearer_nest != nullptr;
}

bool target_at_subgoal_distance(const PfContext& c) {
  // "in between the starting point and the detected subgoal": nearer the nest than the target
  // (or retracing the robot's own way home, which may wind)
  return target_reached(c.m) && c.m.target.visible && nestward_of_target(c, c.in.pose.p) &&
         dist(c.in.pose.p, c.m.target.last_seen) / kCm >= c.p.d_sub;
}

bool reached_nest_before_d_sub(const PfContext& c) { return c.sight.nest_distance_cm <= c.p.d_detect; }

bool entered_recovery_range(const PfContext& c) {
  return c.p.early_stop_in_rec && c.sight.recovery_near && c.m.target.visible && target_reached(c.m) &&
         nestward_of_target(c, c.in.pose.p);
}

bool target_lost_in_visible_range(const PfContext& c) {
  return lost(c.m.target, c.p) && dist(c.in.pose.p, c.m.target.last_seen) / kCm >= c.p.r_vis;
}

bool forming_timeout(const PfContext& c) { return static_cast<double>(c.m.t_state) >= c.p.t_form_timeout; }

bool forming_timeout_target_seen(const PfContext& c) { return forming_timeout(c) && c.m.target.visible; }

// R (form_retries): a robot that lost its target is no use standing ORANGE for the rest of the run
// (RECOVERY is final, SPEC §2.3 row 14); while it has retries left it goes home along its own way
// out, rests, and its next trip starts at its sighting of the chain (site_fidelity)
bool lost_target_may_retry(const PfContext& c) {
  if (static_cast<double>(c.m.form_retries) >= c.p.form_retries) return false;
  return target_lost_in_visible_range(c) || (forming_timeout(c) && !c.m.target.visible);
}

void take_target(const PfContext& c, PfMemory& m) {
  const bool goal = goal_in_reach(c);
  m.target = follow(goal ? *c.sight.goal : *c.sight.red_near, c.in.pose);
  m.form_leg = FormLeg::kBackOff;  // found within d_detect
  // found the goal from its far side: its own way from the nest leads round the goal (R)
  m.far_side = goal && dist(c.in.pose.p, c.nest) > dist(m.target.last_seen, c.nest);
  m.way_spot_for = kNobody;
  m.parent = Tracked{};
  m.child = Tracked{};
}

void retarget(const PfContext& c, PfMemory& m) {
  m.target = follow(*c.sight.red_nearer_nest, c.in.pose);
  // within d_detect of it: back off from it at once; else walk to it first
  m.form_leg = c.sight.red_nearer_nest->distance_cm <= c.p.d_detect ? FormLeg::kBackOff : FormLeg::kToTarget;
  m.far_side = false;  // the tip is reached from the chain's side; its way home is the trail
  m.way_spot_for = kNobody;
}

void target_becomes_parent(const PfContext&, PfMemory& m) { m.parent = m.target; }

void go_home_to_retry(const PfContext&, PfMemory& m) {
  ++m.form_retries;
  m.target = Tracked{};
}

void next_form_leg(const Percept& in, const Params& p, PfMemory& m) {
  if (m.form_leg == FormLeg::kToTarget && m.target.visible &&
      dist(in.pose.p, m.target.last_seen) / kCm <= p.d_detect) {
    m.form_leg = FormLeg::kBackOff;
  }
}

namespace {

// The spot a forming robot backs off to from its target `tgt`: d_sub + 5 cm from it toward the nest,
// or [R spot_crumb_tol] the crumb of its own way out nearest that distance from it (within the
// tolerance) among those nearer the nest than the target.
Vec2 backoff_spot_at(const Params& p, const RobotMemory& mem, Vec2 tgt) {
  const double r = (p.d_sub + 5.0) * kCm;
  if (p.spot_crumb_tol > 0.0) {
    Vec2 crumb;
    if (mem.trail.crumb_at(tgt, r, p.spot_crumb_tol * kCm, mem.nest, dist(tgt, mem.nest), crumb))
      return crumb;
  }
  const Vec2 to_nest = mem.nest - tgt;
  const double len = norm(to_nest);
  return len > 0.0 ? tgt + (r / len) * to_nest : mem.nest;
}

// back off to the nest side of the target: the point d_sub (+5 cm) from it toward the nest, "in
// between the starting point and the detected subgoal" [R spot_crumb_tol: the point of the robot's
// own way out that far from it, nearer the nest: round an obstacle, the way it knows is passable].
// Without progress toward it for a quarter of T_trap (a quarter of trap_progress: nav_home), along its
// own way from the nest [R trail_nestward: from the point of that way nearest it that is nearer the
// nest than the target, not back past the target]
Command to_spot(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  PfMemory& m = mem.pf;
  const Vec2 tgt = m.target.last_seen;
  // R (spot_on_way, task allocation; spot_on_way_pf): a way with no crumb for the straight-line spot
  // came round an obstacle's end: the spot is where it first came that near the target, chosen once
  // per target (the trail home consumes crumbs); falling back, it retraces that way from the crumb
  // nearest it
  const bool spot_on_way = by_mode(m.role, p.spot_on_way_pf, p.spot_on_way);
  if (spot_on_way && m.way_spot_for != m.target.id) {
    m.way_spot_for = m.target.id;
    Vec2 straight;  // a crumb of its way the straight-line rule accepts: that spot stands
    const bool straight_ok =
        p.spot_crumb_tol > 0.0 && mem.trail.crumb_at(tgt, (p.d_sub + 5.0) * kCm, p.spot_crumb_tol * kCm,
                                                     mem.nest, dist(tgt, mem.nest), straight);
    m.has_way_spot = !straight_ok && mem.trail.first_within(tgt, (p.d_sub + 5.0) * kCm, m.way_spot);
    // R (way_after_edge): only a way that went round an obstacle on this trip (the robot followed
    // its edge); in an open room the way is the robot's own wandering
    if (p.way_after_edge) m.has_way_spot = m.has_way_spot && mem.trail.went_round();
  }
  const bool on_way = spot_on_way && m.has_way_spot;
  const Vec2 spot_at = on_way ? m.way_spot : backoff_spot_at(p, mem, tgt);
  const double trail_within = p.trail_nestward && !on_way ? dist(tgt, mem.nest) : Trail::kEverywhere;
  const Vec2 f =
      nav_home(in, p, mem.nav, mem.rng, mem.trail, mem.nest, 0.25 * p.t_trap, &spot_at, trail_within);
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  return pf_drive(p, mem, p.v_max * v, PfState::kSubgoalForming);
}

}  // namespace

Command form_subgoal(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  const PfMemory& m = mem.pf;
  switch (m.form_leg) {
    case FormLeg::kBackOff: {
      // the spot (a robot that found the goal from its far side: not round the goal, R), or
      const bool spot = p.backoff_spot || (m.role == PfRole::kAllocated && p.ta_backoff_spot) ||
                        (p.backoff_far_spot && m.far_side);
      if (spot) return to_spot(in, p, mem, sight);
      // ... along the robot's own way from the nest: a route it knows is passable
      if (p.backoff_trail && !mem.nav.on_trail && !mem.trail.empty()) {
        mem.nav.on_trail = true;
        mem.trail.start_home(in.pose.p);
      }
      return go_to_nest(in, p, mem, sight, PfState::kSubgoalForming);
    }
    case FormLeg::kToTarget:
      break;
  }
  // a robot that re-targeted to a subgoal nearer the nest first walks to it (the chain's tip)
  const Vec2 f = nav_toward(in, p, mem.nav, mem.rng, m.target.last_seen);
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  return pf_drive(p, mem, p.v_max * v, PfState::kSubgoalForming);
}

void pf_join_chain_end(PfMemory& m, const Params& p, const Blob& red, const Pose& pose, Vec2 nest,
                       std::int64_t tick) {
  m.state = PfState::kSubgoalForming;
  m.t_state = 0;
  m.target = follow(red, pose);
  // on the nest side of it already, the robot need not cross the resting crowd to reach it first
  const bool reached = red.distance_cm <= p.d_detect || dist(pose.p, nest) < dist(m.target.last_seen, nest);
  m.form_leg = reached ? FormLeg::kBackOff : FormLeg::kToTarget;
  m.far_side = false;
  m.way_spot_for = kNobody;
  m.parent = Tracked{};
  m.child = Tracked{};
  m.safe_pos = pose.p;
  m.fired_tick = tick;
  m.sighting = m.target.last_seen;  // site fidelity, should it go exploring later
  m.has_sighting = true;
}

}  // namespace swarmpath::sim
