// SPDX-License-Identifier: MIT
#include "path_formation.hpp"

#include <algorithm>
#include <cmath>

#include "alignment.hpp"
#include "navigation.hpp"
#include "sim/controller.hpp"
#include "sim/motion.hpp"
#include "ta_protocol.hpp"

namespace swarmpath::sim {

std::string_view to_string(PfState s) {
  switch (s) {
    case PfState::kExploring:
      return "exploring";
    case PfState::kReturnToNest:
      return "return_to_nest";
    case PfState::kResting:
      return "resting";
    case PfState::kSubgoalForming:
      return "subgoal_forming";
    case PfState::kSubgoal:
      return "subgoal";
    case PfState::kOpt1:
      return "opt1";
    case PfState::kSubNest:
      return "sub_nest";
    case PfState::kOpt2:
      return "opt2";
    case PfState::kPathDone:
      return "path_done";
    case PfState::kRecovery:
      return "recovery";
  }
  return "?";
}

Led led_of(PfState s) {
  switch (s) {
    case PfState::kExploring:
      return Led::kGreen;
    case PfState::kReturnToNest:
      return Led::kGray50;
    case PfState::kResting:
      return Led::kBlack;
    case PfState::kSubgoalForming:
      return Led::kWhite;
    case PfState::kSubgoal:
      return Led::kRed;
    case PfState::kOpt1:
      return Led::kMagenta;
    case PfState::kSubNest:
      return Led::kBlue;
    case PfState::kOpt2:
      return Led::kPurple;
    case PfState::kPathDone:
      return Led::kBrown;
    case PfState::kRecovery:
      return Led::kOrange;
  }
  return Led::kBlack;
}

void pf_init(PfMemory& m, const Params& p) {
  m = PfMemory{};
  m.t_explore = p.t_explore0;
}

namespace {

constexpr double kCm = 0.01;  // metres per cm

Vec2 blob_position(const Pose& pose, const Blob& b) {
  return pose.p + (b.distance_cm * kCm) * pose.to_world(b.dir);
}

// robots an explorer keeps clear of besides recovery robots (SPEC §2.3, paper label e)
bool is_path_colour(Led c) {
  return c == Led::kWhite || c == Led::kMagenta || c == Led::kBlue || c == Led::kPurple || c == Led::kBrown ||
         c == Led::kOrange;
}

// single_child [R]: what robots claim, the goal or a subgoal: a WHITE robot forming from it, or
// a chain robot advertising it as its parent, seen (vision + ID tags) or heard on the
// range-and-bearing medium (3 m, past the camera's R_vis). Gathered once per tick.
struct Claims {
  IdSet robots;
  bool goal = false;

  void add(int emitter) {
    if (emitter == kGoalEmitter) goal = true;
    if (emitter >= 0 && emitter <= 255) robots.insert(static_cast<std::uint8_t>(emitter));
  }

  bool has(int emitter) const {
    if (emitter == kGoalEmitter) return goal;
    return emitter >= 0 && emitter <= 255 && robots.contains(static_cast<std::uint8_t>(emitter));
  }
};

// every (robot, what it names as its target or parent) this tick: a chain robot's or forming
// robot's light tag (not a recovery robot's), and claims on the medium
template <typename F>
void for_each_naming(const Percept& in, F&& f) {
  for (const Blob& b : in.blobs) {
    if (b.emitter < 0 || b.tag == kNobody) continue;
    if (b.color == Led::kRed || (is_path_colour(b.color) && b.color != Led::kOrange)) f(b.emitter, b.tag);
  }
  for_each_claim_heard(in.rab, f);
}

Claims gather_claims(const Percept& in) {
  Claims c;
  for_each_naming(in, [&](int, int named) { c.add(named); });
  return c;
}

// colours a reference may show, for vision-only tracking
bool allowed_for(const Tracked& t, Led c, bool nest_side) {
  if (t.id == kGoalEmitter) return c == Led::kYellow;
  if (t.id == kNestEmitter) return false;  // beacons are matched by emitter below
  if (nest_side) return c == Led::kBlue || c == Led::kMagenta || c == Led::kPurple || c == Led::kBrown;
  return c == Led::kRed || c == Led::kMagenta || c == Led::kBlue || c == Led::kPurple || c == Led::kBrown ||
         c == Led::kWhite;
}

// Updates one tracked reference from the blobs: by emitter id (vision + ID), or by the nearest
// blob of an allowed colour within the gate around its last position (vision only).
void track(Tracked& t, const Percept& in, const Params& p, bool nest_side) {
  if (!t.valid()) return;
  const Blob* seen = nullptr;
  const bool beacon = t.id == kNestEmitter || t.id == kGoalEmitter;
  if (beacon || p.neighbour_id == NeighbourId::kVisionId) {
    for (const Blob& b : in.blobs) {
      if (b.emitter == t.id) {
        seen = &b;
        break;
      }
    }
  } else {
    double best = p.track_gate * kCm;
    for (const Blob& b : in.blobs) {
      if (!allowed_for(t, b.color, nest_side)) continue;
      const double d = dist(blob_position(in.pose, b), t.last_seen);
      if (d <= best) {
        best = d;
        seen = &b;
      }
    }
  }
  t.visible = seen != nullptr;
  if (seen == nullptr) {
    ++t.unseen;
    return;
  }
  t.unseen = 0;
  t.id = seen->emitter;
  t.color = seen->color;
  t.last_seen = blob_position(in.pose, *seen);
}

Tracked follow(const Blob& b, const Pose& pose) {
  Tracked t;
  t.id = b.emitter;
  t.last_seen = blob_position(pose, b);
  t.visible = true;
  t.color = b.color;
  return t;
}

bool lost(const Tracked& t, const Params& p) { return !t.valid() || t.unseen >= static_cast<int>(p.t_lost); }

// robot-frame position of a reference [cm]
Vec2 local_cm(const Pose& pose, const Tracked& t) {
  return (1.0 / kCm) * pose.to_local(t.last_seen - pose.p);
}

// back where the alignment began: align() stops within d_tol of it (1 cm for the bodies' give)
bool back_at_safe_pos(const Pose& pose, const PfMemory& m, const Params& p) {
  return dist(pose.p, m.safe_pos) / kCm <= p.d_tol + 1.0;
}

// ---- guards, named after the paper's conditions ----

// the goal beacon within d_detect, and (single_child) no robot in view claims it
bool goal_in_reach(const PfContext& c) {
  return c.sight.goal != nullptr && c.sight.goal->distance_cm <= c.p.d_detect && !c.sight.goal_claimed;
}

bool found_goal_or_subgoal(const PfContext& c) {  // row 1, label c
  if (c.m.scout) return false;  // a TA scout that finds the goal becomes the founder instead
  // one at a time [R]: while another robot in view is forming, wait for it to become the tip
  if (c.p.form_one_at_a_time && c.sight.forming_in_view) return false;
  // ... and robots waiting for one do not all start in the same tick (p_form per tick)
  if (c.p.form_one_at_a_time && !c.sight.may_form) return false;
  return goal_in_reach(c) || c.sight.red_near != nullptr;
}

// [R return_finds]: a robot going home still finds the goal it passes (not a subgoal: robots go
// home past the chain, and each would start a side branch)
bool found_on_the_way_home(const PfContext& c) { return c.p.return_finds && !c.m.scout && goal_in_reach(c); }

bool exploration_time_over(const PfContext& c) {  // row 2, label b (or blocked for good)
  // travelling back to a sighting does not spend the budget (capped at three budgets)
  const double spent = static_cast<double>(c.m.t_state - c.m.travel_ticks);
  const bool lost_way =
      c.p.travel_cap > 0.0 && static_cast<double>(c.m.travel_ticks) >= c.p.travel_cap * c.m.t_explore;
  return spent >= c.m.t_explore || c.m.explore_blocked || lost_way;
}

bool reached_nest(const PfContext& c) {  // row 3, label d
  return static_cast<double>(c.m.nest_ticks) >= std::max(1.0, c.p.t_nest_search);
}

bool resting_time_over(const PfContext& c) {  // row 4, label i
  return static_cast<double>(c.m.t_state) >= c.p.t_rest;
}

bool nestward_of_target(const PfContext& c, Vec2 at) {
  if (!c.p.subgoal_nestward) return true;  // SPEC's rows #5, #6b: anywhere d_sub from the target
  // nearer the nest than the target; retracing its own way home (which may wind round an
  // obstacle's end) a robot may stop up to trail_slack farther [R]: more, and the chain knots
  const double slack = c.on_trail ? c.p.trail_slack * kCm : 0.0;
  return dist(at, c.nest) < dist(c.m.target.last_seen, c.nest) + slack;
}

bool found_subgoal_nearer_nest(const PfContext& c) {  // row 5r, label c while forming
  return c.p.retarget_nearer && c.sight.red_nearer_nest != nullptr;
}

bool target_at_subgoal_distance(const PfContext& c) {  // row 5
  // "in between the starting point and the detected subgoal": nearer the nest than the target
  // (or retracing the robot's own way home, which may wind)
  return c.m.target_reached && c.m.target.visible && nestward_of_target(c, c.in.pose.p) &&
         dist(c.in.pose.p, c.m.target.last_seen) / kCm >= c.p.d_sub;
}

bool reached_nest_before_d_sub(const PfContext& c) {  // row 6a
  return c.sight.nest_distance_cm <= c.p.d_detect;
}

bool entered_recovery_range(const PfContext& c) {  // row 6b
  return c.p.early_stop_in_rec && c.sight.recovery_near && c.m.target.visible && c.m.target_reached &&
         nestward_of_target(c, c.in.pose.p);
}

bool back_at_view_edge(const PfContext& c) {  // row 7a [R]
  return c.m.to_view_edge && dist(c.in.pose.p, c.m.last_saw_target) <= 0.02;
}

bool target_lost_in_visible_range(const PfContext& c) {  // row 7, label f
  return lost(c.m.target, c.p) && dist(c.in.pose.p, c.m.target.last_seen) / kCm >= c.p.r_vis;
}

bool forming_timeout(const PfContext& c) {  // row 8
  return static_cast<double>(c.m.t_state) >= c.p.t_form_timeout;
}

bool forming_timeout_target_seen(const PfContext& c) {  // row 8a
  return forming_timeout(c) && c.m.target.visible;
}

bool sees_nest(const PfContext& c) { return c.sight.nest != nullptr; }  // row 9a, label g

bool sees_own_sub_nest(const PfContext& c) { return c.sight.my_subnest != nullptr; }  // row 9b, label g

bool sees_grandparent(const PfContext& c) { return c.sight.grandparent != nullptr; }  // row 15 [R]

bool bypassed(const PfContext& c) { return c.sight.bypassed; }  // row 16 [R]

bool alignment_done(const PfContext& c) {  // rows 10 and 12
  const bool both_seen = c.m.parent.visible && c.m.child.visible;
  // out of time: done, provided both references are in view (else first back to the start; SPEC: done)
  if (static_cast<double>(c.m.t_state) >= c.p.t_align_max && (both_seen || !c.p.align_keep_view)) return true;
  if (lost(c.m.parent, c.p) || lost(c.m.child, c.p)) return false;
  // as aligned as the view allows: a reference slipped out of sight; back at the start, both in view
  if (c.m.view_limited && c.m.parent.visible && c.m.child.visible && back_at_safe_pos(c.in.pose, c.m, c.p)) {
    return true;
  }
  const Vec2 a = local_cm(c.in.pose, c.m.parent);
  const Vec2 b = local_cm(c.in.pose, c.m.child);
  return aligned(angle_of(a), angle_of(b), alignment_target(a, b, c.p), c.p);
}

bool parent_done_or_last_subgoal(const PfContext& c) {  // row 11, label h
  return c.m.parent.id == kGoalEmitter || (c.m.parent.visible && c.m.parent.color == Led::kBrown);
}

// R (seek_hidden_reference): the one reference out of view (`debounced`: lost, else not seen this
// tick) while T_align_max is not spent, or nullptr (both in view, or both out of it)
const Tracked* hidden_reference(const PfMemory& m, const Params& p, bool debounced) {
  if (!p.seek_hidden_reference || !p.align_keep_view || static_cast<double>(m.t_state) >= p.t_align_max)
    return nullptr;
  const bool parent_out = debounced ? lost(m.parent, p) : !m.parent.visible;
  const bool child_out = debounced ? lost(m.child, p) : !m.child.visible;
  if (parent_out == child_out) return nullptr;
  return parent_out ? &m.parent : &m.child;
}

bool seeking_reference(const PfContext& c) {  // R: one reference out of view, looked for (align())
  const Tracked* hidden = hidden_reference(c.m, c.p, true);
  return hidden != nullptr && dist(c.in.pose.p, hidden->last_seen) / kCm > c.p.d_detect;  // not there yet
}

bool reference_lost(const PfContext& c) {  // row 13, label f
  // a reference that slipped behind an obstacle while the robot moved counts as lost only once
  // the robot is back where it last saw both and it is still out of sight, and (option) it has
  // looked for it where it was last seen
  if (seeking_reference(c)) return false;
  // (or, stall guard, cannot get back there in another T_align_max)
  const bool back = !c.m.view_limited || back_at_safe_pos(c.in.pose, c.m, c.p) ||
                    static_cast<double>(c.m.t_state) >= 2.0 * c.p.t_align_max;
  return (lost(c.m.parent, c.p) || lost(c.m.child, c.p)) && back;
}

bool heir_in_view(const PfContext& c) { return c.sight.heir != nullptr; }  // row 17 [R]

bool orphaned(const PfContext& c) {  // row 14 option: revert_orphans
  return c.p.revert_orphans && lost(c.m.parent, c.p);
}

// ---- actions ----

void take_target(const PfContext& c, PfMemory& m) {  // row 1: the goal if in range, else the red subgoal
  const bool goal = goal_in_reach(c);
  m.target = follow(goal ? *c.sight.goal : *c.sight.red_near, c.in.pose);
  m.target_reached = true;  // found within d_detect
  // found the goal from its far side: its own way from the nest leads round the goal (R)
  m.far_side = goal && dist(c.in.pose.p, c.nest) > dist(m.target.last_seen, c.nest);
  m.parent = Tracked{};
  m.child = Tracked{};
}

void target_becomes_parent(const PfContext&, PfMemory& m) { m.parent = m.target; }

void retarget(const PfContext& c, PfMemory& m) {
  m.target = follow(*c.sight.red_nearer_nest, c.in.pose);
  m.target_reached = c.sight.red_nearer_nest->distance_cm <= c.p.d_detect;  // else walk to it first
  m.far_side = false;  // the tip is reached from the chain's side; its way home is the trail
}

void grow_budget(const PfContext& c, PfMemory& m) {  // row 4: "increase the minimum exploring time"
  m.t_explore = std::min((m.t_explore + c.p.dt_explore) * c.p.g_explore, c.p.t_explore_max);
}

void child_is_nest(const PfContext& c, PfMemory& m) { m.child = follow(*c.sight.nest, c.in.pose); }

void child_is_sub_nest(const PfContext& c, PfMemory& m) { m.child = follow(*c.sight.my_subnest, c.in.pose); }

void grandparent_becomes_parent(const PfContext& c, PfMemory& m) {  // row 15 [R]
  m.parent = follow(*c.sight.grandparent, c.in.pose);
}

void heir_becomes_parent(const PfContext& c, PfMemory& m) {  // row 17 [R]
  m.parent = follow(*c.sight.heir, c.in.pose);
}

// row 16 [R]: back to the nest along its way out, then out again to the sighting, the RED robot
// nearest the nest that it saw (pf_perceive): its next approach to the tip is from the nest side
void leave_chain(const PfContext&, PfMemory& m) {
  m.parent = Tracked{};
  m.target = Tracked{};
}

// clang-format off
// SPEC §2.3, in its order (paper Table 2 labels where they exist). For each state the first row
// whose guard holds fires; rows 6, 8, 9 and 13 are split where the SPEC lists two conditions.
const std::array<PfTransition, 25> kTable{{
  {PfState::kExploring,      found_goal_or_subgoal,        PfState::kSubgoalForming, take_target,           "#1",  "c"},
  {PfState::kExploring,      exploration_time_over,        PfState::kReturnToNest,   nullptr,               "#2",  "b"},
  {PfState::kReturnToNest,   found_on_the_way_home,        PfState::kSubgoalForming, take_target,           "#1h", "c"},
  {PfState::kReturnToNest,   reached_nest,                 PfState::kResting,        nullptr,               "#3",  "d"},
  {PfState::kResting,        resting_time_over,            PfState::kExploring,      grow_budget,           "#4",  "i"},
  {PfState::kSubgoalForming, found_subgoal_nearer_nest,    PfState::kSubgoalForming, retarget,              "#5r", "c"},
  {PfState::kSubgoalForming, target_at_subgoal_distance,   PfState::kSubgoal,        target_becomes_parent, "#5",  ""},
  {PfState::kSubgoalForming, reached_nest_before_d_sub,    PfState::kSubgoal,        target_becomes_parent, "#6a", ""},
  {PfState::kSubgoalForming, entered_recovery_range,       PfState::kSubgoal,        target_becomes_parent, "#6b", ""},
  {PfState::kSubgoalForming, back_at_view_edge,            PfState::kSubgoal,        target_becomes_parent, "#7a", ""},
  {PfState::kSubgoalForming, target_lost_in_visible_range, PfState::kRecovery,       nullptr,               "#7",  "f"},
  {PfState::kSubgoalForming, forming_timeout_target_seen,  PfState::kSubgoal,        target_becomes_parent, "#8a", ""},
  {PfState::kSubgoalForming, forming_timeout,              PfState::kRecovery,       nullptr,               "#8b", ""},
  {PfState::kSubgoal,        sees_nest,                    PfState::kOpt1,           child_is_nest,         "#9a", "g"},
  {PfState::kSubgoal,        sees_own_sub_nest,            PfState::kOpt1,           child_is_sub_nest,     "#9b", "g"},
  {PfState::kOpt1,           alignment_done,               PfState::kSubNest,        nullptr,               "#10", ""},
  {PfState::kSubNest,        parent_done_or_last_subgoal,  PfState::kOpt2,           nullptr,               "#11", "h"},
  {PfState::kOpt2,           alignment_done,               PfState::kPathDone,       nullptr,               "#12", "a"},
  {PfState::kOpt1,           reference_lost,               PfState::kRecovery,       nullptr,               "#13a","f"},
  {PfState::kOpt2,           reference_lost,               PfState::kRecovery,       nullptr,               "#13b","f"},
  {PfState::kSubNest,        orphaned,                     PfState::kSubgoal,        nullptr,               "#14a",""},
  {PfState::kPathDone,       orphaned,                     PfState::kSubgoal,        nullptr,               "#14b",""},
  {PfState::kSubgoal,        sees_grandparent,             PfState::kSubgoal,        grandparent_becomes_parent, "#15", ""},
  {PfState::kSubgoal,        bypassed,                     PfState::kReturnToNest,   leave_chain,           "#16", ""},
  {PfState::kSubNest,        heir_in_view,                 PfState::kSubNest,        heir_becomes_parent,   "#17", ""},
}};

// clang-format on

// ---- behaviours, one per state ----

Command drive(const Params& p, RobotMemory& mem, Vec2 v_cm_s, PfState s) {
  return drive_command(v_cm_s, p, mem.turn, led_of(s));
}

Command stop(PfState s) {
  Command cmd;
  cmd.led = led_of(s);
  return cmd;
}

// Guided departure [R] (task allocation): an allocated robot's first trip follows the CYAN
// lights, the founder going back to the goal and the robots following it, keeping guide_gap from
// the one fewest hops from the founder (ties: farthest from the nest); the goal, a free RED subgoal or a
// forming robot in view ends it, and so does seeing no guide for T_guide_lost. Following does not spend the
// budget (it is travel, like row 2's).
bool follow_guide(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight, Command& cmd) {
  PfMemory& m = mem.pf;
  if (sight.lure != nullptr || sight.forming_link != nullptr) {
    m.follow_guide = false;
    return false;
  }
  if (sight.guide == nullptr) {
    if (static_cast<double>(++m.guide_unseen) >= p.t_guide_lost) {
      m.follow_guide = false;
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
  cmd = drive(p, mem, p.v_max * v, PfState::kExploring);
  cmd.led = Led::kCyan;
  return true;
}

// seek_tip [R]: an allocated explorer that sees a robot forming the next link (WHITE) and no
// free subgoal walks to it and waits tip_hover from it for the RED it becomes, which lures it
// (row 1). Waiting spends the budget.
Command wait_by_forming_robot(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  PfMemory& m = mem.pf;
  m.to_sighting = false;
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (avoid.collision ? avoid.direction : Vec2{}) + sight.repulsion;
  const double gap = std::clamp((sight.forming_link->distance_cm - p.tip_hover) / p.tip_hover, -1.0, 1.0);
  if (gap > 0.0) v += gap * sight.forming_link->dir;
  return drive(p, mem, p.v_max * v, PfState::kExploring);
}

// V = v_max (D + w_away F_away(nest) + w_rw u_phi + R), or the obstacle's edge when the robot
// can get no farther from the nest; an explorer whose edge following gets it nowhere (the arena's
// boundary, a corner) ends its trip
Command explore(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  mem.trail.record(in.pose.p);
  update_walk_heading(mem.walk_heading, mem.walk_dir, mem.rng, p);
  // site fidelity: travel back to where the chain was seen, then explore from there
  PfMemory& m = mem.pf;
  if (m.follow_guide) {
    if (Command cmd; follow_guide(in, p, mem, sight, cmd)) return cmd;
  }
  if (sight.lure == nullptr && sight.forming_link != nullptr) return wait_by_forming_robot(in, p, mem, sight);
  if (m.to_sighting) ++m.travel_ticks;
  if (m.to_sighting && (sight.lure != nullptr || dist(in.pose.p, m.sighting) < 0.5)) {
    // [R sighting_returns] task allocation: arrived where the chain's tip was and nothing free
    // there: the tip has moved nestward, past this robot; its trip ends and its way home passes it
    if (p.sighting_returns && m.single_child && sight.lure == nullptr) m.explore_blocked = true;
    m.to_sighting = false;
    m.answering = -1;
    mem.walk_heading = in.pose.yaw();
    mem.walk_dir = {in.pose.c, in.pose.s};
    nav_reset(mem.nav);
  }
  // R (nest_crowd): robots crowd the nest in task allocation; edge following them is no way out
  const bool in_crowd = sight.nest_distance_cm < m.nest_crowd_cm;
  if (m.to_sighting) {
    const Vec2 f = nav_toward(in, p, mem.nav, mem.rng, m.sighting, in_crowd);
    const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
    if (!m.guide) return drive(p, mem, p.v_max * v, PfState::kExploring);
    Command cmd = drive(p, mem, p.guide_speed * p.v_max * v, PfState::kExploring);
    cmd.led = Led::kCyan;
    return cmd;
  }
  m.guide = false;
  if (sight.lure == nullptr && nav_update(mem.nav, p, mem.rng, sight.nest_distance_cm, in,
                                          -field_toward(in.pose, mem.nest), in_crowd)) {
    return drive(p, mem, p.v_max * follow_edge(in, mem.nav.side), PfState::kExploring);
  }
  mem.pf.explore_blocked = mem.pf.explore_blocked || (p.blocked_trip_ends && mem.nav.gave_up);
  const Avoidance avoid = diffusion(in.proximity, p);
  const Vec2 away = -field_toward(in.pose, mem.nest);
  Vec2 v = avoid.direction + p.w_away * away + p.w_rw * in.pose.to_local(mem.walk_dir) + sight.repulsion;
  if (sight.lure != nullptr) v += p.w_seek * sight.lure->dir;
  v *= p.v_max;
  return drive(p, mem, v, PfState::kExploring);
}

// V = v_max (D + F_toward(nest) + R): returning robots and robots forming a subgoal; F is the
// navigator's direction (the field, or the obstacle's edge when trapped).
Command go_to_nest(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight, PfState s) {
  const Avoidance avoid = diffusion(in.proximity, p);
  // [R return_lured] a task-allocation scout going home that sees the goal has found it: to it, and T2
  if (s == PfState::kReturnToNest && mem.pf.scout && p.return_finds && p.return_lured &&
      sight.goal != nullptr)
    return drive(p, mem, p.v_max * (avoid.direction + sight.goal->dir + sight.repulsion), s);
  const Vec2 f = nav_home(in, p, mem.nav, mem.rng, mem.trail, mem.nest);
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  return drive(p, mem, p.v_max * v, s);
}

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

// SUBGOAL_FORMING (LED white): back off toward the nest from the target; a robot that re-targeted
// to a subgoal nearer the nest first walks to it (the chain's tip), then backs off from there
Command form_subgoal(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  if (mem.pf.to_view_edge) {  // back to where the target was last in view (row 7a)
    const Vec2 back = (1.0 / kCm) * in.pose.to_local(mem.pf.last_saw_target - in.pose.p);
    const double len = norm(back);
    if (len <= 2.0) return stop(PfState::kSubgoalForming);
    return drive(p, mem, (std::min(p.v_max, len) / len) * back, PfState::kSubgoalForming);
  }
  // a robot that found the goal from its far side backs off to the spot, not round the goal (R)
  const bool spot = p.backoff_spot || mem.pf.backoff_spot || (p.backoff_far_spot && mem.pf.far_side);
  if (mem.pf.target_reached && !spot) {
    // back off along the robot's own way from the nest: a route it knows is passable
    if (p.backoff_trail && !mem.nav.on_trail && !mem.trail.empty()) {
      mem.nav.on_trail = true;
      mem.trail.start_home(in.pose.p);
    }
    return go_to_nest(in, p, mem, sight, PfState::kSubgoalForming);
  }
  if (mem.pf.target_reached) {
    // back off to the nest side of the target: the point d_sub (+5 cm) from it toward the nest,
    // "in between the starting point and the detected subgoal" [R spot_crumb_tol: the point of the
    // robot's own way out that far from it, nearer the nest: round an obstacle, the way it knows
    // is passable]. Without progress toward it for spot_patience ticks, or a quarter of T_trap with
    // a wall in the way, along its own way from the nest [R trail_nestward: from the point of that
    // way nearest it that is nearer the nest than the target, not back past the target]
    const Vec2 tgt = mem.pf.target.last_seen;
    const Vec2 spot_at = backoff_spot_at(p, mem, tgt);
    const bool wall = wall_in_the_way(in, in.pose.to_local(spot_at - in.pose.p));
    const double patience = p.spot_patience > 0.0 && !wall ? p.spot_patience : 0.25 * p.t_trap;
    const double trail_within = p.trail_nestward ? dist(tgt, mem.nest) : Trail::kEverywhere;
    const Vec2 f = nav_home(in, p, mem.nav, mem.rng, mem.trail, mem.nest, patience, &spot_at, trail_within);
    const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
    return drive(p, mem, p.v_max * v, PfState::kSubgoalForming);
  }
  const Vec2 f = nav_toward(in, p, mem.nav, mem.rng, mem.pf.target.last_seen);
  const Vec2 v = with_avoidance(in, p, mem.nav, f) + sight.repulsion;
  return drive(p, mem, p.v_max * v, PfState::kSubgoalForming);
}

// drive at the alignment speed toward where a reference out of view was last seen (robot frame, cm)
Command look_for(const Percept& in, const Params& p, RobotMemory& mem, Vec2 toward, PfState s) {
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (1.0 / std::max(norm(toward), 1e-9)) * toward;
  if (avoid.collision) v += avoid.direction;
  return drive(p, mem, p.v_align * p.v_max * v, s);
}

// SUB_NEST (LED blue) waits for its parent to be done (row 11). The camera's view of a corner need
// not be mutual, so a parent can be waited for for ever: one still RED T_nudge ticks on, which sees
// this robot only from its own side past a corner, if at all, and so never took row 9b (R,
// nudge_parent: close in on it while the child stays in view); one out of view, behind a corner
// (R, seek_hidden_reference); or one that turned RECOVERY in its alignment (row 13), whose own
// parent this robot looks for (R, relink_recovery; row 17 takes it). For these two, go round the
// corner toward where the parent was last seen, the child in view or not: under a wall's tip a
// robot may see neither
Command wait_for_parent(const Percept& in, const Params& p, RobotMemory& mem) {
  const PfMemory& m = mem.pf;
  const PfState s = PfState::kSubNest;
  // (the three exclude each other: the parent out of view, in view and RED, in view and ORANGE)
  const bool hidden = p.seek_hidden_reference && lost(m.parent, p);
  const bool blind = p.nudge_parent && m.parent.visible && m.parent.color == Led::kRed &&
                     static_cast<double>(m.t_state) >= p.t_nudge;
  const bool broken = p.relink_recovery && m.parent.visible && m.parent.color == Led::kOrange;
  if (!(hidden || blind || broken) || (blind && lost(m.child, p))) return stop(s);
  const Vec2 toward = local_cm(in.pose, m.parent);
  // (a broken link: to the edge of its repulsion, since its parent stands up to d_sub beyond it)
  if (norm(toward) <= (broken ? p.r_rec : p.d_detect)) return stop(s);
  if (blind) return look_for(in, p, mem, toward, s);
  const Vec2 f = nav_toward(in, p, mem.nav, mem.rng, m.parent.last_seen);
  const Vec2 v = with_avoidance(in, p, mem.nav, f);
  return drive(p, mem, p.v_align * p.v_max * v, s);
}

// SPEC §2.4: drive to the alignment target P; speed v_align v_max, tapering over the last
// centimetres (P in cm, so |P| cm/s reaches it in about a second) so that the robot stops on P.
Command align(const Percept& in, const Params& p, RobotMemory& mem, PfState s) {
  PfMemory& m = mem.pf;
  const Vec2 a = local_cm(in.pose, m.parent);
  const Vec2 b = local_cm(in.pose, m.child);
  // keep both references in view: where one slips behind an obstacle, go back to where the
  // alignment began (both were in view there) and stay (SPEC §2.4, bounded by line of sight)
  if (p.align_keep_view &&
      (!m.parent.visible || !m.child.visible || static_cast<double>(m.t_state) >= p.t_align_max)) {
    m.view_limited = true;
  }
  // still out of view from there (a subgoal's parent just behind an obstacle's corner): drive
  // toward where it was last seen until both are in view, and stop there (R)
  const Tracked* hidden = hidden_reference(m, p, false);
  if (hidden != nullptr && m.view_limited && (m.seek_ref || back_at_safe_pos(in.pose, m, p))) {
    m.seek_ref = true;
    return look_for(in, p, mem, local_cm(in.pose, *hidden), s);
  }
  if (m.seek_ref && m.parent.visible && m.child.visible) {
    m.seek_ref = false;
    m.safe_pos = in.pose.p;  // found it: both in view here
  }
  const Vec2 target =
      m.view_limited ? (1.0 / kCm) * in.pose.to_local(m.safe_pos - in.pose.p) : alignment_target(a, b, p);
  const double len = norm(target);
  if (len <= p.d_tol) return stop(s);
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (1.0 / len) * target;
  // R_keep bounds the robot itself, not only P: pushed past it, go back toward that reference
  // (not on the way back to where the alignment began: both were in view there)
  if (p.r_keep_pull && !m.view_limited && norm(a) > p.r_keep) {
    v = (1.0 / norm(a)) * a;
  } else if (p.r_keep_pull && !m.view_limited && norm(b) > p.r_keep) {
    v = (1.0 / norm(b)) * b;
  }
  // SPEC §2.4 as written: V = v_align v_max P/|P| + D, D the diffusion vector
  if (!p.align_taper) return drive(p, mem, p.v_align * p.v_max * v + avoid.direction, s);
  const double speed = std::min(p.v_align * p.v_max, len);
  if (avoid.collision) v += avoid.direction;  // avoidance at the same (slow) speed as the pull
  return drive(p, mem, speed * v, s);
}

}  // namespace

std::span<const PfTransition> pf_transitions() { return kTable; }

std::uint8_t pf_row_number(std::string_view row) {
  const auto rows = pf_transitions();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].row == row) return static_cast<std::uint8_t>(i + 1);
  }
  return 0;
}

namespace {

// the blob of one emitter this tick (its light's tag names its parent, or its target), if in view
const Blob* blob_of(const Percept& in, int emitter) {
  for (const Blob& b : in.blobs) {
    if (b.emitter == emitter) return &b;
  }
  return nullptr;
}

// chain_bypass [R]: a RED subgoal whose parent's parent (the RED robot the parent's light names, or
// the goal) is in view within d_sub + 10 cm skips the parent. A RED subgoal leaves the chain once
// every robot that has named it as parent (its children, by their lights' tags or claims on the
// medium) is seen or heard naming another, one of them its own parent: it was skipped
void perceive_bypass(const Percept& in, const Params& p, PfMemory& m, const Claims& claims, PfSight& sight) {
  // what each robot that ever named me names this tick
  std::array<int, Claimants::kMax> names;
  names.fill(kNobody);
  for_each_naming(in, [&](int robot, int named) {
    if (named == in.id) m.claimants.add(robot);
    for (std::size_t i = 0; i < m.claimants.ids.size(); ++i) {
      if (m.claimants.ids[i] == robot) names[i] = named;
    }
  });
  const Claimants& who = m.claimants;
  bool all_renamed = who.count > 0 && who.count <= Claimants::kMax && !claims.has(in.id);
  bool to_parent = false;
  for (int i = 0; i < std::min(who.count, Claimants::kMax); ++i) {
    all_renamed = all_renamed && names[i] != kNobody && names[i] != in.id;
    to_parent = to_parent || (m.parent.valid() && names[i] == m.parent.id);
  }
  sight.bypassed = all_renamed && to_parent;

  if (!m.parent.valid() || !m.parent.visible) return;
  const Blob* parent = blob_of(in, m.parent.id);
  const int grandparent = parent != nullptr && parent->color == Led::kRed ? parent->tag : kNobody;
  for (const Blob& b : in.blobs) {
    // (not where the grandparent names my parent or me as its own: a loop, not a chain)
    if (grandparent != kNobody && b.emitter == grandparent && b.distance_cm <= p.d_sub + 10.0 &&
        (b.color == Led::kRed || b.emitter == kGoalEmitter) && b.tag != m.parent.id && b.tag != in.id) {
      sight.grandparent = &b;
    }
  }
}

// relink_recovery [R]: a parent that turned RECOVERY (row 13) still names its own parent with its
// light's tag; that robot, in view, is the heir
void perceive_heir(const Percept& in, const PfMemory& m, PfSight& sight) {
  if (!m.parent.valid() || !m.parent.visible || m.parent.color != Led::kOrange) return;
  const Blob* parent = blob_of(in, m.parent.id);
  const int heir = parent != nullptr ? parent->tag : kNobody;
  if (heir == kNobody || heir == in.id) return;
  for (const Blob& b : in.blobs) {
    if (b.emitter == heir && b.color != Led::kOrange) sight.heir = &b;
  }
}

}  // namespace

void pf_perceive(const Percept& in, const Params& p, Vec2 nest, PfMemory& m, PfSight& sight) {
  sight = PfSight{};
  Claims claims;
  if (m.single_child) claims = gather_claims(in);
  sight.nest_distance_cm = dist(in.pose.p, nest) / kCm;
  double red_best = p.d_detect;
  double lure_best = p.r_vis + 1.0;
  double sub_best = p.r_vis + 1.0;
  // R: a follower takes only a guide fewer hops from the founder than itself (a fresh one counts
  // kMaxGuideHops), so that hop counts only go down and no followers follow each other in a loop
  int guide_hops = m.guide_hops - 1;
  double guide_far = -1.0;
  double forming_to_nest = 1e18;
  for (const Blob& b : in.blobs) {
    if (m.follow_guide && b.color == Led::kCyan && b.emitter >= 0) {
      // the light's tag is its hop count to the founder (the founder at the nest advertises none)
      const int hops = b.tag == kNobody ? 0 : b.tag;
      const double to_nest = dist(blob_position(in.pose, b), nest);
      if (hops >= 0 && (hops < guide_hops || (hops == guide_hops && to_nest > guide_far))) {
        guide_hops = hops;
        guide_far = to_nest;
        sight.guide = &b;
      }
      continue;
    }
    if (b.emitter == kGoalEmitter) {
      sight.goal = &b;
      sight.goal_claimed = claims.has(kGoalEmitter);
      if (!sight.goal_claimed) {
        sight.lure = &b;
        lure_best = -1.0;  // the goal beats any subgoal
      }
      continue;
    }
    if (b.emitter == kNestEmitter) {
      sight.nest = &b;
      continue;
    }
    const bool free_red = b.color == Led::kRed && !claims.has(b.emitter);
    if (free_red && b.distance_cm <= red_best) {
      red_best = b.distance_cm;
      sight.red_near = &b;
    }
    if (free_red && b.distance_cm < lure_best) {
      lure_best = b.distance_cm;
      sight.lure = &b;
    }
    const bool mine = p.neighbour_id == NeighbourId::kVisionId ? b.tag == in.id : b.emitter != m.parent.id;
    if (b.color == Led::kBlue && mine && b.distance_cm < sub_best) {
      sub_best = b.distance_cm;
      sight.my_subnest = &b;
    }
    if (b.color == Led::kWhite && b.emitter >= 0) sight.forming_in_view = true;
    // R (seek_tip): the forming (WHITE) robot nearest the nest, where the next free subgoal will stand
    if (m.seek_tip && b.color == Led::kWhite && b.emitter >= 0) {
      const double to_nest = dist(blob_position(in.pose, b), nest);
      if (to_nest < forming_to_nest) {
        forming_to_nest = to_nest;
        sight.forming_link = &b;
      }
    }
    // R: recovery robots repel everyone; explorers keep clear of path robots too (label e)
    const bool repels =
        b.color == Led::kOrange || (m.state == PfState::kExploring && is_path_colour(b.color));
    if (repels && b.distance_cm <= p.r_rec) {
      sight.repulsion -= p.k_rec * (1.0 - b.distance_cm / p.r_rec) * b.dir;
      if (b.color == Led::kOrange) sight.recovery_near = true;
    }
  }
  track(m.target, in, p, false);
  track(m.parent, in, p, false);
  track(m.child, in, p, true);
  if (m.bypass && m.state == PfState::kSubgoal) perceive_bypass(in, p, m, claims, sight);
  if (p.relink_recovery && m.state == PfState::kSubNest) perceive_heir(in, m, sight);
  // recruit_call [R]: how long this subgoal has gone without a robot forming from it or naming it
  m.unclaimed = m.call_links && m.state == PfState::kSubgoal && !claims.has(in.id) ? m.unclaimed + 1 : 0;
  // refound_starved [R]: its child left to fetch robots; it does not leave itself meanwhile
  if (p.refound_starved && m.state == PfState::kSubgoal) {
    for (const RabMessage& r : in.rab) {
      if (fetch_for(decode(r.data)) == in.id)
        m.help_until = in.tick + static_cast<std::int64_t>(3.0 * p.t_refound);
    }
  }
  if (m.target.visible && dist(in.pose.p, m.target.last_seen) / kCm <= p.d_detect) m.target_reached = true;
  // forming robots that lose their target at least d_sub/2 from it, nearer the nest, go back to
  // the last place they saw it and stop there (row 7a): the chain bends round the obstacle
  if (m.state == PfState::kSubgoalForming) {
    if (m.target.visible) {
      m.last_saw_target = in.pose.p;
    } else if (p.stop_at_view_edge && !m.to_view_edge && m.target_reached && lost(m.target, p) &&
               dist(m.last_saw_target, m.target.last_seen) / kCm >= 0.5 * p.d_sub &&
               dist(m.last_saw_target, nest) < dist(m.target.last_seen, nest)) {
      m.to_view_edge = true;
    }
  }
  // site fidelity: remember where the chain needs robots: the RED subgoal in view nearest the
  // nest (its tip), or else the goal
  bool seen = false;
  double tip_to_nest = 1e18;
  for (const Blob& b : in.blobs) {
    if (b.color != Led::kRed) continue;
    const Vec2 at = blob_position(in.pose, b);
    if (dist(at, nest) < tip_to_nest) {
      tip_to_nest = dist(at, nest);
      m.sighting = at;
      seen = true;
    }
  }
  if (!seen && sight.goal != nullptr) {
    m.sighting = blob_position(in.pose, *sight.goal);
    seen = true;
  }
  if (seen) {
    m.has_sighting = true;
    m.sighted_this_trip = true;
  }
  // while forming: the RED subgoal in view that lies nearest the nest, if it is nearer than the
  // target (the chain's tip, so that the new subgoal extends it)
  if (m.state == PfState::kSubgoalForming && m.target.valid()) {
    constexpr double kMargin = 0.2;  // [m]
    double best = dist(m.target.last_seen, nest) - kMargin;
    for (const Blob& b : in.blobs) {
      if (b.color != Led::kRed || b.emitter == m.target.id) continue;
      if (claims.has(b.emitter)) continue;
      const double to_nest = dist(blob_position(in.pose, b), nest);
      if (to_nest < best) {
        best = to_nest;
        sight.red_nearer_nest = &b;
      }
    }
  }
  m.nest_ticks =
      (m.state == PfState::kReturnToNest && sight.nest_distance_cm <= p.r_nest_reach) ? m.nest_ticks + 1 : 0;
}

const Blob* free_subgoal_in_view(const Percept& in) {
  const Claims claims = gather_claims(in);
  const Blob* best = nullptr;
  for (const Blob& b : in.blobs) {
    if (b.emitter < 0 || b.color != Led::kRed || claims.has(b.emitter)) continue;
    if (best == nullptr || b.distance_cm < best->distance_cm) best = &b;
  }
  return best;
}

void pf_join_chain_end(PfMemory& m, const Params& p, const Blob& red, const Pose& pose, Vec2 nest,
                       std::int64_t tick) {
  m.state = PfState::kSubgoalForming;
  m.t_state = 0;
  m.target = follow(red, pose);
  // on the nest side of it already, the robot need not cross the resting crowd to reach it first
  m.target_reached = red.distance_cm <= p.d_detect || dist(pose.p, nest) < dist(m.target.last_seen, nest);
  m.far_side = false;
  m.parent = Tracked{};
  m.child = Tracked{};
  m.last_saw_target = pose.p;
  m.safe_pos = pose.p;
  m.to_view_edge = false;
  m.fired_tick = tick;
  m.sighting = m.target.last_seen;  // site fidelity, should it go exploring later
  m.has_sighting = true;
}

const PfTransition* pf_transition(const PfContext& c, PfMemory& m) {
  for (std::size_t i = 0; i < kTable.size(); ++i) {
    const PfTransition& row = kTable[i];
    if (row.from != m.state || !row.when(c)) continue;
    if (row.act != nullptr) row.act(c, m);
    m.state = row.to;
    m.t_state = 0;
    m.last_row = static_cast<std::uint8_t>(i + 1);
    m.fired_tick = c.in.tick;
    return &row;
  }
  return nullptr;
}

Command path_formation_step(const Percept& in, const Params& p, RobotMemory& mem) {
  PfMemory& m = mem.pf;
  PfSight sight;
  pf_perceive(in, p, mem.nest, m, sight);
  sight.may_form = !p.form_one_at_a_time || m.state != PfState::kExploring || sight.lure == nullptr ||
                   mem.rng.bernoulli(p.p_form);
  // transitions happen only here, via the table
  const PfContext c{in, p, m, sight, mem.nest, mem.nav.on_trail};
  if (const PfTransition* fired = pf_transition(c, m)) {
    nav_reset(mem.nav);
    m.explore_blocked = false;
    m.to_view_edge = false;
    m.last_saw_target = in.pose.p;
    m.view_limited = false;
    m.safe_pos = in.pose.p;
    m.seek_ref = false;
    m.claimants = Claimants{};
    m.guide = false;
    m.follow_guide = false;
    m.answering = -1;
    if (fired->to == PfState::kReturnToNest && !m.sighted_this_trip) m.has_sighting = false;  // a stale lead
    if (fired->to == PfState::kExploring) {
      // a new trip: head for the last sighting (site fidelity), else keep the random heading
      m.sighted_this_trip = false;
      mem.trail.reset(in.pose.p);
      m.to_sighting = p.site_fidelity && m.has_sighting;
      m.travel_ticks = 0;
      m.trip_start = in.tick;
    }
  }
  ++m.t_state;
  mem.state = static_cast<std::uint8_t>(m.state);

  Command cmd;
  switch (m.state) {
    case PfState::kExploring:
      cmd = explore(in, p, mem, sight);
      break;
    case PfState::kReturnToNest:
      cmd = go_to_nest(in, p, mem, sight, m.state);
      break;
    case PfState::kSubgoalForming:
      cmd = form_subgoal(in, p, mem, sight);
      break;
    case PfState::kOpt1:
    case PfState::kOpt2:
      cmd = align(in, p, mem, m.state);
      break;
    case PfState::kSubNest:
      cmd = wait_for_parent(in, p, mem);
      break;
    case PfState::kResting:
    case PfState::kSubgoal:
    case PfState::kPathDone:
    case PfState::kRecovery:
      cmd = stop(m.state);
      break;
  }
  // vision + ID: the light also carries the robot's parent (SPEC §2.1), so that a subgoal can
  // tell which sub-nest is its own (row 9b)
  cmd.tag = m.parent.valid() ? m.parent.id : kNobody;
  // ... and a forming robot's light, its target: the target is claimed (single_child)
  if (m.state == PfState::kSubgoalForming && m.target.valid()) cmd.tag = m.target.id;
  // single_child: the claim also goes on the medium, which reaches past the camera's range
  const bool chained = m.state != PfState::kExploring && m.state != PfState::kReturnToNest &&
                       m.state != PfState::kResting && m.state != PfState::kRecovery;
  if (m.single_child && chained && cmd.tag != kNobody) {
    TaMessage claim = claim_message(static_cast<std::uint8_t>(in.id), cmd.tag);
    // recruit_call: a subgoal nobody has claimed for T_starve calls resting robots
    if (m.state == PfState::kSubgoal && static_cast<double>(m.unclaimed) >= p.t_starve && m.call_links)
      claim.flags = static_cast<std::uint8_t>(claim.flags | kFlagNeed);
    cmd.rab_send = true;
    cmd.rab = encode(claim);
  } else if (m.state == PfState::kExploring && m.answering >= 0) {
    // ... and a robot answering the call claims it on its way, so that no other robot answers
    cmd.rab_send = true;
    cmd.rab = encode(claim_message(static_cast<std::uint8_t>(in.id), m.answering));
  }
  // guided departure: a guide's light carries its hop count to the founder instead
  if (cmd.led == Led::kCyan) cmd.tag = m.guide ? 0 : m.guide_hops;
  return cmd;
}

}  // namespace swarmpath::sim
