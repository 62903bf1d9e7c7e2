// SPDX-License-Identifier: MIT
// The path-formation table (SPEC §2.3): one test per row, each a reading that meets the row's
// guard and the state it must lead to; the table's structure; and the optimisation geometry.
#include "sim/controllers/path_formation.hpp"

#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/controllers/alignment.hpp"
#include "sim/controllers/forming.hpp"
#include "sim/controllers/ta_protocol.hpp"

namespace swarmpath::sim {
namespace {

constexpr Vec2 kNest{-5.0, 0.0};
constexpr int kMe = 3;

// the robot at the origin facing +x; blobs are given in the robot frame
struct Reading {
  std::vector<Blob> blobs;
  std::vector<RabMessage> rab;
  Vec2 at{0.0, 0.0};
  std::int64_t tick = 100;

  Blob& add(Led c, int emitter, double bearing_deg, double distance_cm, int tag = kNobody) {
    blobs.push_back({c, emitter, unit(deg2rad(bearing_deg)), distance_cm, tag});
    return blobs.back();
  }

  Percept percept() const {
    Percept in;
    in.tick = tick;
    in.id = kMe;
    in.pose = {at, 1.0, 0.0};
    in.blobs = blobs;
    in.rab = rab;
    return in;
  }
};

Tracked tracked(int id, Vec2 at) {
  Tracked t;
  t.id = id;
  t.last_seen = at;
  t.visible = true;
  return t;
}

// perceive, then apply the table; returns the row that fired ("" for none)
std::string fire(PfMemory& m, const Reading& r, const Params& p = {}, bool on_trail = false,
                 bool went_round = false) {
  const Percept in = r.percept();
  PfSight sight;
  pf_perceive(in, p, kNest, m, sight);
  if (m.state == PfState::kSubgoalForming) next_form_leg(in, p, m);
  const PfContext c{in, p, m, sight, kNest, on_trail, went_round};
  const PfTransition* row = pf_transition(c, m);
  return row ? std::string(row->row) : std::string();
}

PfMemory in_state(PfState s) {
  PfMemory m;
  pf_init(m, Params{});
  m.state = s;
  return m;
}

TEST(PfTable, Row1FindsTheGoalWithinDetectRange) {  // label c
  PfMemory m = in_state(PfState::kExploring);
  Reading r;
  r.add(Led::kYellow, kGoalEmitter, 10, 25);
  r.add(Led::kRed, 7, -20, 20);
  EXPECT_EQ(fire(m, r), "#1");
  EXPECT_EQ(m.state, PfState::kSubgoalForming);
  EXPECT_EQ(m.target.id, kGoalEmitter);  // the goal is preferred
}

TEST(PfTable, Row1FindsARedSubgoal) {
  PfMemory m = in_state(PfState::kExploring);
  Reading r;
  r.add(Led::kRed, 7, 45, 28);
  r.add(Led::kYellow, kGoalEmitter, 0, 60);  // seen, but beyond d_detect
  EXPECT_EQ(fire(m, r), "#1");
  EXPECT_EQ(m.target.id, 7);
  PfMemory far = in_state(PfState::kExploring);
  Reading out;
  out.add(Led::kRed, 7, 45, 35);  // 35 cm > d_detect = 30
  EXPECT_EQ(fire(far, out), "");
}

// R: single_child (task allocation): an allocated explorer attaches only to what no robot claims
TEST(PfTable, Row1SingleChildSkipsAClaimedGoalOrSubgoal) {
  PfMemory m = in_state(PfState::kExploring);
  m.role = PfRole::kAllocated;  // single_child applies to allocated robots
  Reading r;
  r.add(Led::kYellow, kGoalEmitter, 10, 25);
  r.add(Led::kWhite, 9, 180, 60, kGoalEmitter);  // robot 9 forms from the goal: claimed by sight
  r.add(Led::kRed, 7, -20, 20);
  r.add(Led::kRed, 8, 90, 90, 7);  // robot 8 is chained to 7: claimed by sight
  EXPECT_EQ(fire(m, r), "");
  // seen without its claimants, the subgoal claimed on the medium only (3 m, past the camera)
  Reading heard;
  heard.add(Led::kRed, 7, -20, 20);
  RabMessage msg;
  msg.sender = 8;
  msg.data = encode(claim_message(8, 7));
  heard.rab.push_back(msg);
  EXPECT_EQ(fire(m, heard), "");
  heard.rab.clear();
  EXPECT_EQ(fire(m, heard), "#1");  // unclaimed: attaches
  EXPECT_EQ(m.target.id, 7);
  // without single_child the claims do not matter (SPEC row 1)
  PfMemory plain = in_state(PfState::kExploring);
  EXPECT_EQ(fire(plain, r), "#1");
  EXPECT_EQ(plain.target.id, kGoalEmitter);
}

// R: chain_bypass. A RED subgoal with the option on and `parent` 70 cm ahead
PfMemory bypassing_subgoal(int parent) {
  PfMemory m = in_state(PfState::kSubgoal);
  m.role = PfRole::kAllocated;
  m.parent = tracked(parent, {0.7, 0.0});
  return m;
}

Params with_bypass() {
  Params p;
  p.chain_bypass = true;
  return p;
}

// R: chain_bypass. Subgoal 3 (me) has parent 7, whose light names 5 as its parent; 5 stands 60 cm
// from me (<= bypass_reach): 7 is redundant, and I take 5 as my parent (row 15)
TEST(PfTable, Row15ASubgoalSkipsAParentWhoseParentIsWithinReach) {
  PfMemory m = bypassing_subgoal(7);
  Reading r;
  r.add(Led::kRed, 7, 0, 70, 5);
  r.add(Led::kRed, 5, 60, 60, 2);
  EXPECT_EQ(fire(m, r, with_bypass()), "#15");
  EXPECT_EQ(m.state, PfState::kSubgoal);
  EXPECT_EQ(m.parent.id, 5);
  // beyond bypass_reach, or without the option, the chain stays as it is
  PfMemory far = bypassing_subgoal(7);
  Reading out;
  out.add(Led::kRed, 7, 0, 70, 5);
  out.add(Led::kRed, 5, 60, 85, 2);
  Params near = with_bypass();
  near.bypass_reach = 80;  // d_sub + 10 cm: only where the chain folds back
  EXPECT_EQ(fire(far, out, near), "");
  PfMemory off = bypassing_subgoal(7);
  Params without;
  without.chain_bypass = false;
  EXPECT_EQ(fire(off, r, without), "");
  // 5 names 7 as its parent: 7 and 5 form a loop, and following it would flip for ever
  PfMemory loop = bypassing_subgoal(7);
  Reading cycle;
  cycle.add(Led::kRed, 7, 0, 70, 5);
  cycle.add(Led::kRed, 5, 60, 60, 7);
  cycle.add(Led::kRed, 11, 180, 70, kMe);  // my child: I am not left out (row 16)
  EXPECT_EQ(fire(loop, cycle, with_bypass()), "");
}

// R: chain_bypass is task allocation's (allocated robots and scouts alike); chain_bypass_pf the same
// for path formation's subgoals. The parent's parent 90 cm off: within the default reach (95 cm)
TEST(PfTable, Row15InEachModeByItsOwnSwitch) {
  Reading r;
  r.add(Led::kRed, 7, 0, 70, 5);
  r.add(Led::kRed, 5, 40, 90, 2);
  const Params defaults;
  ASSERT_TRUE(defaults.chain_bypass);
  ASSERT_TRUE(defaults.chain_bypass_pf);
  ASSERT_EQ(defaults.bypass_reach, 95);
  PfMemory scout = bypassing_subgoal(7);
  scout.role = PfRole::kScout;
  EXPECT_EQ(fire(scout, r, defaults), "#15");
  Params ta_off = defaults;  // task allocation's switch off: path formation's subgoal still bypasses
  ta_off.chain_bypass = false;
  scout = bypassing_subgoal(7);
  scout.role = PfRole::kScout;
  EXPECT_EQ(fire(scout, r, ta_off), "");
  PfMemory swarm = bypassing_subgoal(7);
  swarm.role = PfRole::kSwarm;
  Params pf_off = defaults;  // path formation's switch off: it keeps every link
  pf_off.chain_bypass_pf = false;
  EXPECT_EQ(fire(swarm, r, pf_off), "");
  EXPECT_EQ(fire(swarm, r, ta_off), "#15");
  EXPECT_EQ(swarm.parent.id, 5);
  // the reach is the camera's distance to the parent's parent: 100 cm is beyond 95
  Reading edge;
  edge.add(Led::kRed, 7, 0, 70, 5);
  edge.add(Led::kRed, 5, 40, 100, 2);
  PfMemory beyond = bypassing_subgoal(7);
  beyond.role = PfRole::kSwarm;
  EXPECT_EQ(fire(beyond, edge, defaults), "");
}

// R: chain_bypass. I (3) am RED with parent 5; my child 8 now names 5 as its parent and nobody
// names me: I was skipped, and go back to the nest (row 16). A robot that still has a child, or
// that has not seen what became of every robot that named it, stays.
TEST(PfTable, Row16ASkippedSubgoalLeavesTheChain) {
  PfMemory m = bypassing_subgoal(5);
  m.claimants.add(8);
  Reading r;
  r.add(Led::kRed, 5, 0, 70, 2);
  r.add(Led::kRed, 8, 90, 70, 5);
  r.add(Led::kRed, 9, 90, 95, 8);
  PfMemory two = m;
  two.claimants.add(12);  // a second child, out of sight this tick
  EXPECT_EQ(fire(two, r, with_bypass()), "");
  PfMemory stranger = bypassing_subgoal(5);  // 8 was never my child: a sibling, not a bypass
  EXPECT_EQ(fire(stranger, r, with_bypass()), "");
  EXPECT_EQ(fire(m, r, with_bypass()), "#16");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  EXPECT_FALSE(m.parent.valid());
  PfMemory kept = bypassing_subgoal(5);
  kept.claimants.add(8);
  Reading child = r;
  child.add(Led::kRed, 11, 180, 70, kMe);  // robot 11 names me as its parent
  EXPECT_EQ(fire(kept, child, with_bypass()), "");
}

TEST(PfTable, Row2ExplorationBudgetSpent) {  // label b
  PfMemory m = in_state(PfState::kExploring);
  m.t_state = 999;
  EXPECT_EQ(fire(m, Reading{}), "");
  m.t_state = 1000;  // T_explore0
  EXPECT_EQ(fire(m, Reading{}), "#2");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
}

// R return_finds: a robot going home that passes within d_detect of the goal takes it (env8: the
// first robots there arrive with their budget spent); a RED subgoal it passes it leaves alone
TEST(PfTable, Row1hARobotGoingHomeStillFindsTheGoal) {
  PfMemory m = in_state(PfState::kReturnToNest);
  Reading goal;
  goal.add(Led::kYellow, kGoalEmitter, 10, 25);
  Params off;
  off.return_finds = false;
  EXPECT_EQ(fire(m, goal, off), "");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  Reading red;
  red.add(Led::kRed, 7, -20, 20);
  EXPECT_EQ(fire(m, red), "");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  EXPECT_EQ(fire(m, goal), "#1h");
  EXPECT_EQ(m.state, PfState::kSubgoalForming);
  EXPECT_EQ(m.target.id, kGoalEmitter);
}

TEST(PfTable, Row3ReachedTheNest) {  // label d
  PfMemory m = in_state(PfState::kReturnToNest);
  Reading r;
  r.at = kNest + Vec2{0.5, 0.0};  // within R_nest_reach
  m.nest_ticks = 48;
  EXPECT_EQ(fire(m, r), "");  // 49 < T_nest_search
  EXPECT_EQ(fire(m, r), "#3");
  EXPECT_EQ(m.state, PfState::kResting);
}

TEST(PfTable, Row4RestOverGrowsTheBudget) {  // label i
  PfMemory m = in_state(PfState::kResting);
  m.t_state = 50;
  EXPECT_EQ(fire(m, Reading{}), "#4");
  EXPECT_EQ(m.state, PfState::kExploring);
  EXPECT_DOUBLE_EQ(m.t_explore, 1500.0);  // T_explore0 + dT_explore
}

// a forming robot at the origin; its target, red robot 7, lies 75 cm away from the nest
PfMemory forming(Vec2 target_at) {
  PfMemory m = in_state(PfState::kSubgoalForming);
  m.target = tracked(7, target_at);
  m.form_leg = FormLeg::kBackOff;  // it has been at its target
  return m;
}

TEST(PfTable, Row5SubgoalAtDsubFromTheTarget) {
  PfMemory m = forming({0.75, 0.0});
  Reading r;
  r.add(Led::kRed, 7, 0, 75);
  EXPECT_EQ(fire(m, r), "#5");
  EXPECT_EQ(m.state, PfState::kSubgoal);
  EXPECT_EQ(m.parent.id, 7);
  // not yet 70 cm away: keeps forming
  PfMemory near = forming({0.60, 0.0});
  Reading r2;
  r2.add(Led::kRed, 7, 0, 60);
  EXPECT_EQ(fire(near, r2), "");
}

// R: trail_slack. Row 5's "in between the starting point and the detected subgoal": a robot
// retracing its own way home may stop up to trail_slack (45 cm) farther from the nest than its
// target (round an obstacle's end), not anywhere on the way (where the chains knotted by the goal)
TEST(PfTable, Row5OnTheTrailStopsAtMostTrailSlackFartherFromTheNest) {
  const Vec2 behind{-0.75, 0.0};  // the target 75 cm nearer the nest than the robot
  const Vec2 aside{0.75 * std::cos(deg2rad(120)), 0.75 * std::sin(deg2rad(120))};  // 33 cm nearer
  const auto sees = [](double bearing_deg) {
    Reading r;
    r.add(Led::kRed, 7, bearing_deg, 75);
    return r;
  };
  const Params p;
  PfMemory m = forming(behind);
  EXPECT_EQ(fire(m, sees(180), p, true), "");  // 75 cm > trail_slack
  m = forming(aside);
  EXPECT_EQ(fire(m, sees(120), p, true), "#5");  // 33 cm <= trail_slack
  m = forming(aside);
  EXPECT_EQ(fire(m, sees(120), p, false), "");  // off the trail the target must be farther
  Params anywhere;
  anywhere.trail_slack = 3000;  // no bound: anywhere on its way
  m = forming(behind);
  EXPECT_EQ(fire(m, sees(180), anywhere, true), "#5");
}

// R: anywhere_after_edge (on for task allocation; anywhere_after_edge_pf, on, for path formation;
// docs/detours.md). Retracing a way that followed an obstacle's edge on this trip, a robot may stop
// as a subgoal however far from the nest; a way that never followed one keeps trail_slack, and off
// its trail the target must be farther as before.
TEST(PfTable, Row5AfterAnEdgeStopsAnywhereOnTheWayItCameInEachModeByItsOwnSwitch) {
  const Vec2 behind{-0.75, 0.0};  // the target 75 cm nearer the nest than the robot
  Reading r;
  r.add(Led::kRed, 7, 180, 75);
  const Params defaults;
  ASSERT_TRUE(defaults.anywhere_after_edge);
  ASSERT_TRUE(defaults.anywhere_after_edge_pf);
  const auto forming_as = [&](PfRole role) {
    PfMemory m = forming(behind);
    m.role = role;
    return m;
  };
  Params pf_off = defaults;
  pf_off.anywhere_after_edge_pf = false;
  PfMemory m = forming_as(PfRole::kSwarm);
  EXPECT_EQ(fire(m, r, pf_off, true, true), "");  // path formation without it: 75 cm > trail_slack
  m = forming_as(PfRole::kAllocated);
  EXPECT_EQ(fire(m, r, pf_off, true, true), "#5");  // task allocation's robot: its own switch
  m = forming_as(PfRole::kAllocated);
  EXPECT_EQ(fire(m, r, defaults, true, false), "");  // a way that never followed an edge
  m = forming_as(PfRole::kAllocated);
  EXPECT_EQ(fire(m, r, defaults, false, true), "");  // not on its way
  m = forming_as(PfRole::kAllocated);
  EXPECT_EQ(fire(m, r, defaults, true, true), "#5");
  EXPECT_EQ(m.parent.id, 7);
  Params off = defaults;
  off.anywhere_after_edge = false;
  m = forming_as(PfRole::kAllocated);
  EXPECT_EQ(fire(m, r, off, true, true), "");
  m = forming_as(PfRole::kSwarm);
  EXPECT_EQ(fire(m, r, off, true, true), "#5");  // path formation's robot: its own switch, on
  m = forming_as(PfRole::kSwarm);
  EXPECT_EQ(fire(m, r, defaults, true, false), "");  // a way that never followed an edge
}

// R: link_outward (task allocation's robots) and link_outward_pf (path formation's), both off by
// default (docs/detours.md). Retracing its own way home, a robot may stop as a subgoal however far
// from the nest, provided its target is the nearest chain light in view: round a doorway off the
// nest-goal line the way home first leads away from the nest.
TEST(PfTable, Row5LinkOutwardStopsOnTheTrailWhereTheTargetIsTheNearestChainLight) {
  const Vec2 behind{-0.75, 0.0};  // the target 75 cm nearer the nest than the robot
  Reading r;
  r.add(Led::kRed, 7, 180, 75);
  const Params off;
  ASSERT_FALSE(off.link_outward);
  ASSERT_FALSE(off.link_outward_pf);
  PfMemory m = forming(behind);
  EXPECT_EQ(fire(m, r, off, true), "");  // 75 cm > trail_slack
  Params ta = off;
  ta.link_outward = true;  // task allocation's switch leaves path formation's robots as they were
  m = forming(behind);
  EXPECT_EQ(fire(m, r, ta, true), "");
  m = forming(behind);
  m.role = PfRole::kAllocated;
  EXPECT_EQ(fire(m, r, ta, true), "#5");
  Params on = off;
  on.link_outward_pf = true;
  m = forming(behind);
  m.role = PfRole::kAllocated;  // and path formation's leaves task allocation's robots
  EXPECT_EQ(fire(m, r, on, true), "");
  m = forming(behind);
  EXPECT_EQ(fire(m, r, on, true), "#5");
  EXPECT_EQ(m.parent.id, 7);
  m = forming(behind);
  EXPECT_EQ(fire(m, r, on, false), "");  // off its trail: nearer the nest than the target, as before
  // another chain light nearer than the target: the new link would fold back beside the chain
  Reading beside = r;
  beside.add(Led::kRed, 9, 90, 40);
  m = forming(behind);
  EXPECT_EQ(fire(m, beside, on, true), "");
}

// R: spot_on_way (task allocation's robots) and spot_on_way_pf (path formation's; off by default;
// docs/detours.md). A robot backing off to the spot on the way it came (round a wall's end, farther
// from the nest in a straight line than its target) stops as the subgoal there, d_sub from its
// target, where the straight-line rule would keep it forming.
TEST(PfTable, Row5SpotOnWayStopsAtTheSpotOnTheWayItCame) {
  const Vec2 behind{-0.75, 0.0};  // the target 75 cm nearer the nest than the robot
  Reading r;
  r.add(Led::kRed, 7, 180, 75);
  const auto at_spot = [&](Vec2 spot) {
    PfMemory m = forming(behind);
    m.way_spot_for = 7;
    m.has_way_spot = true;
    m.way_spot = spot;
    return m;
  };
  Params off;
  off.spot_on_way = false;
  off.spot_on_way_pf = false;
  PfMemory m = at_spot({0.05, 0.0});
  EXPECT_EQ(fire(m, r, off), "");  // the straight line: farther from the nest than its target
  Params ta = off;
  ta.spot_on_way = true;  // task allocation's switch leaves path formation's robots as they were
  m = at_spot({0.05, 0.0});
  EXPECT_EQ(fire(m, r, ta), "");
  m = at_spot({0.05, 0.0});
  m.role = PfRole::kAllocated;
  EXPECT_EQ(fire(m, r, ta), "#5");
  Params on = off;
  on.spot_on_way_pf = true;
  m = at_spot({0.05, 0.0});
  m.role = PfRole::kAllocated;  // and path formation's leaves task allocation's robots
  EXPECT_EQ(fire(m, r, on), "");
  m = at_spot({0.05, 0.0});
  EXPECT_EQ(fire(m, r, on), "#5");
  EXPECT_EQ(m.parent.id, 7);
  m = at_spot({0.0, 0.60});  // d_sub from the target, but not yet at the spot: keeps forming
  EXPECT_EQ(fire(m, r, on), "");
  m = at_spot({0.05, 0.0});
  m.way_spot_for = 9;  // the spot of another target
  EXPECT_EQ(fire(m, r, on), "");
}

// R: tip_by_links (off by default; docs/detours.md). A forming robot walks down the chain by its
// links: it re-targets to the target's child (the RED whose light names the target as parent), even
// when the child lies farther from the nest, and not to an unrelated RED nearer the nest.
TEST(PfTable, Row5rTipByLinksRetargetsToTheTargetsChild) {
  const auto reading = [] {
    Reading r;
    r.add(Led::kRed, 7, 0, 30);             // the target
    r.add(Led::kRed, 8, 0, 90, 7);          // its child, 60 cm farther from the nest
    r.add(Led::kRed, 9, 180, 60, kNobody);  // another RED, 0.9 m nearer the nest
    return r;
  };
  Params off;
  PfMemory m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(), off), "#5r");
  EXPECT_EQ(m.target.id, 9);  // by distance to the nest
  Params on;
  on.tip_by_links = true;
  m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(), on), "#5r");
  EXPECT_EQ(m.target.id, 8);  // by the chain's links
  EXPECT_EQ(m.form_leg, FormLeg::kToTarget);
}

// R: retarget_tip (docs/detours.md). Where the chain bends away from the nest (round a wall's end) a
// link inside it lies nearer the nest than its tip: a forming robot re-targets only to a RED that no
// RED light in view names as its parent, so that it is not drawn back into the chain from its tip.
TEST(PfTable, Row5rRetargetTipSkipsALinkInsideTheChain) {
  const auto reading = [](bool tip_in_view) {
    Reading r;
    r.add(Led::kRed, 7, 0, 30, 8);                     // the target, a tip: its light names 8 as its parent
    r.add(Led::kRed, 8, 180, 60, 6);                   // 0.9 m nearer the nest, inside the chain (7 names it)
    if (tip_in_view) r.add(Led::kRed, 9, 135, 60, 8);  // another tip, 0.7 m nearer the nest
    return r;
  };
  Params off;
  off.retarget_tip = false;
  PfMemory m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(false), off), "#5r");
  EXPECT_EQ(m.target.id, 8);  // drawn back into the chain
  Params on;                  // the default
  ASSERT_TRUE(on.retarget_tip);
  m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(false), on), "");  // keeps its tip
  EXPECT_EQ(m.target.id, 7);
  m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(true), on), "#5r");
  EXPECT_EQ(m.target.id, 9);                   // a tip nearer the nest still draws it
  on.neighbour_id = NeighbourId::kVisionOnly;  // without ids no light names a parent: as off
  m = forming({0.30, 0.0});
  EXPECT_EQ(fire(m, reading(false), on), "#5r");
  EXPECT_EQ(m.target.id, 8);
}

TEST(PfTable, Row5rRetargetsToTheSubgoalNearerTheNest) {  // label c while forming
  PfMemory m = forming({0.30, 0.0});
  Reading r;
  r.add(Led::kRed, 7, 0, 30);
  r.add(Led::kRed, 8, 180, 60);  // at (-0.6, 0): 0.9 m nearer the nest
  EXPECT_EQ(fire(m, r), "#5r");
  EXPECT_EQ(m.state, PfState::kSubgoalForming);
  EXPECT_EQ(m.target.id, 8);
  EXPECT_EQ(m.form_leg, FormLeg::kToTarget);  // walks to it first
}

TEST(PfTable, Row6aReachedTheNestBeforeDsub) {
  PfMemory m = forming({-4.5, 0.0});
  Reading r;
  r.at = kNest + Vec2{0.2, 0.0};
  r.add(Led::kRed, 7, 0, 30);
  EXPECT_EQ(fire(m, r), "#6a");
  EXPECT_EQ(m.state, PfState::kSubgoal);
}

TEST(PfTable, Row6bStopsInTheRecoveryRange) {
  PfMemory m = forming({0.40, 0.0});
  Reading r;
  r.add(Led::kRed, 7, 0, 40);
  r.add(Led::kOrange, 9, 170, 15);  // within r_rec = 20
  EXPECT_EQ(fire(m, r), "#6b");
  EXPECT_EQ(m.state, PfState::kSubgoal);
  Params off;
  off.early_stop_in_rec = false;
  PfMemory m2 = forming({0.40, 0.0});
  EXPECT_EQ(fire(m2, r, off), "");
}

// SPEC's rows #7 and #8b: RECOVERY at once (form_retries = 0; with retries left, row #7h below)
Params no_retries() {
  Params p;
  p.form_retries = 0;
  return p;
}

TEST(PfTable, Row7TargetLostInTheVisibleRange) {  // label f
  PfMemory m = forming({1.05, 0.0});
  m.target.unseen = 2;  // lost after this tick's miss (T_lost = 3)
  EXPECT_EQ(fire(m, Reading{}, no_retries()), "#7");
  EXPECT_EQ(m.state, PfState::kRecovery);
}

TEST(PfTable, Row8StallGuard) {
  PfMemory seen = forming({0.40, 0.0});
  seen.t_state = 600;  // T_form_timeout
  Reading r;
  r.add(Led::kRed, 7, 0, 40);
  EXPECT_EQ(fire(seen, r), "#8a");
  EXPECT_EQ(seen.state, PfState::kSubgoal);
  PfMemory unseen = forming({0.40, 0.0});
  unseen.t_state = 600;
  EXPECT_EQ(fire(unseen, Reading{}, no_retries()), "#8b");
  EXPECT_EQ(unseen.state, PfState::kRecovery);
}

// R: form_retries (3 by default; docs/detours.md). A forming robot that loses its target (row #7,
// or row #8b's time-out with the target out of view) goes home instead of standing ORANGE for the
// rest of the run, at most form_retries times; a time-out with the target in view still stops (#8a).
TEST(PfTable, Row7hLostTargetGoesHomeWhileRetriesLast) {
  const auto lost_it = [] {
    PfMemory m = forming({1.05, 0.0});
    m.target.unseen = 2;  // lost after this tick's miss (T_lost = 3)
    return m;
  };
  Params p;
  p.form_retries = 2;
  PfMemory m = lost_it();
  EXPECT_EQ(fire(m, Reading{}, p), "#7h");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  EXPECT_EQ(m.form_retries, 1);
  m = lost_it();
  m.form_retries = 2;  // none left: RECOVERY, as SPEC
  EXPECT_EQ(fire(m, Reading{}, p), "#7");
  EXPECT_EQ(m.state, PfState::kRecovery);
  m = lost_it();
  EXPECT_EQ(fire(m, Reading{}, no_retries()), "#7");  // off (0): RECOVERY at once
  m = lost_it();
  EXPECT_EQ(fire(m, Reading{}), "#7h");  // the default: form_retries = 3
  PfMemory timed_out = forming({0.40, 0.0});
  timed_out.t_state = 600;
  EXPECT_EQ(fire(timed_out, Reading{}, p), "#7h");
  PfMemory seen = forming({0.40, 0.0});
  seen.t_state = 600;
  Reading r;
  r.add(Led::kRed, 7, 0, 40);
  EXPECT_EQ(fire(seen, r, p), "#8a");
}

// R: T_leaf (row #21; docs/detours.md). A RED subgoal that no robot in view names as its parent or
// target for T_leaf ticks in a row leaves the chain and goes home; a child's light (or a forming
// robot's) naming it restarts the count; allocated robots (task allocation, T_leaf_allocated = 0) and
// T_leaf = 0 never leave.
TEST(PfTable, Row21ALeafNobodyNamesForTLeafLeavesTheChain) {
  Params p;
  p.t_leaf = 3;
  PfMemory m = in_state(PfState::kSubgoal);
  m.parent = tracked(5, {0.7, 0.0});
  Reading alone;
  alone.add(Led::kRed, 5, 0, 70, 2);  // my parent, in view
  Reading named = alone;
  named.add(Led::kWhite, 11, 180, 40, kMe);  // robot 11 forms from me
  EXPECT_EQ(fire(m, alone, p), "");
  EXPECT_EQ(fire(m, alone, p), "");
  EXPECT_EQ(fire(m, named, p), "");  // named: the count starts again
  EXPECT_EQ(m.childless, 0);
  PfMemory off = m;
  PfMemory allocated = m;
  allocated.role = PfRole::kAllocated;
  EXPECT_EQ(fire(m, alone, p), "");
  EXPECT_EQ(fire(m, alone, p), "");
  EXPECT_EQ(fire(m, alone, p), "#21");
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  EXPECT_FALSE(m.parent.valid());
  Params never = p;
  never.t_leaf = 0;
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(fire(off, alone, never), "");
    EXPECT_EQ(fire(allocated, alone, p), "");
  }
}

// leaf_in_fan [R] (row #21): the lone tip of a single chain sees only its own links and stays; a leaf
// that also sees another branch's light counts its unnamed ticks
TEST(PfTable, Row21WithLeafInFanOnlyALeafThatSeesAnotherBranchLeaves) {
  Params p;
  p.t_leaf = 3;
  p.leaf_in_fan = true;
  p.chain_bypass_pf = false;  // the parent's parent in view at 95 cm: row #15 would skip the parent
  PfMemory tip_memory = in_state(PfState::kSubgoal);
  tip_memory.parent = tracked(5, {0.7, 0.0});
  PfMemory m = tip_memory;
  Reading tip;
  tip.add(Led::kRed, 5, 0, 70, 2);   // my parent, whose light names robot 2
  tip.add(Led::kRed, 2, 10, 95, 1);  // my parent's parent: still my own chain
  for (int i = 0; i < 6; ++i) EXPECT_EQ(fire(m, tip, p), "");
  EXPECT_EQ(m.childless, 0);
  Reading fan = tip;
  fan.add(Led::kRed, 9, 90, 60, 2);  // another branch from robot 2
  EXPECT_EQ(fire(m, fan, p), "");
  EXPECT_EQ(fire(m, fan, p), "");
  EXPECT_EQ(fire(m, fan, p), "#21");
  Params plain = p;
  plain.leaf_in_fan = false;
  PfMemory lone = tip_memory;
  EXPECT_EQ(fire(lone, tip, plain), "");
  EXPECT_EQ(fire(lone, tip, plain), "");
  EXPECT_EQ(fire(lone, tip, plain), "#21");
}

// T_leaf_allocated [R] (row #21, task allocation): an allocated subgoal counts its unnamed ticks only
// while it sees another branch (leaf_in_fan's test, whatever leaf_in_fan says), and leaves at
// T_leaf_allocated; the lone tip of a single chain, waiting for the robots its end fetches, stays
TEST(PfTable, Row21WithTLeafAllocatedAnAllocatedLeafInAFanLeaves) {
  Params p;
  p.t_leaf = 100;
  p.t_leaf_allocated = 3;
  p.chain_bypass = false;  // the parent's parent stands within bypass_reach: row #15 would take it
  PfMemory tip_memory = in_state(PfState::kSubgoal);
  tip_memory.role = PfRole::kAllocated;
  tip_memory.parent = tracked(5, {0.7, 0.0});
  Reading tip;
  tip.add(Led::kRed, 5, 0, 70, 2);   // my parent, whose light names robot 2
  tip.add(Led::kRed, 2, 10, 95, 1);  // my parent's parent: still my own chain
  Reading fan = tip;
  fan.add(Led::kRed, 9, 90, 60, 2);  // another branch from robot 2
  PfMemory m = tip_memory;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(fire(m, tip, p), "");
  EXPECT_EQ(m.childless, 0);
  EXPECT_EQ(fire(m, fan, p), "");
  EXPECT_EQ(fire(m, fan, p), "");
  EXPECT_EQ(fire(m, fan, p), "#21");  // at T_leaf_allocated, not T_leaf
  EXPECT_EQ(m.state, PfState::kReturnToNest);
  Params off = p;
  off.t_leaf_allocated = 0;
  PfMemory stays = tip_memory;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(fire(stays, fan, off), "");
  EXPECT_EQ(stays.childless, 0);
}

TEST(PfTable, Row9aSubgoalSeesTheNest) {  // label g
  PfMemory m = in_state(PfState::kSubgoal);
  m.parent = tracked(7, {0.7, 0.0});
  Reading r;
  r.add(Led::kRed, 7, 0, 70);
  r.add(Led::kBlue, kNestEmitter, 180, 90);
  EXPECT_EQ(fire(m, r), "#9a");
  EXPECT_EQ(m.state, PfState::kOpt1);
  EXPECT_EQ(m.child.id, kNestEmitter);
}

TEST(PfTable, Row9bSubgoalSeesItsOwnSubNest) {  // label g
  PfMemory m = in_state(PfState::kSubgoal);
  m.parent = tracked(7, {0.7, 0.0});
  Reading r;
  r.add(Led::kRed, 7, 0, 70);
  r.add(Led::kBlue, 11, 170, 70, /*tag=*/12);  // someone else's sub-nest
  EXPECT_EQ(fire(m, r), "");
  r.add(Led::kBlue, 12, 180, 70, /*tag=*/kMe);  // mine
  EXPECT_EQ(fire(m, r), "#9b");
  EXPECT_EQ(m.child.id, 12);
}

// an aligning robot exactly between its parent (ahead) and child (behind)
PfMemory aligning(PfState s, Reading& r) {
  PfMemory m = in_state(s);
  m.parent = tracked(7, {0.7, 0.0});
  m.child = tracked(12, {-0.7, 0.0});
  r.add(Led::kRed, 7, 0, 70);
  r.add(Led::kBlue, 12, 180, 70);
  return m;
}

TEST(PfTable, Row10Opt1DoneWhenAligned) {
  Reading r;
  PfMemory m = aligning(PfState::kOpt1, r);
  EXPECT_EQ(fire(m, r), "#10");
  EXPECT_EQ(m.state, PfState::kSubNest);
  // off the line by 40 degrees of error: still aligning
  Reading bent;
  PfMemory m2 = aligning(PfState::kOpt1, bent);
  bent.blobs[0].dir = unit(deg2rad(40));
  m2.parent.last_seen = 0.7 * unit(deg2rad(40));
  EXPECT_EQ(fire(m2, bent), "");
}

TEST(PfTable, Row11LastSubgoalOrParentDone) {  // label h
  PfMemory last = in_state(PfState::kSubNest);
  last.parent = tracked(kGoalEmitter, {0.7, 0.0});
  EXPECT_EQ(fire(last, Reading{}), "#11");
  EXPECT_EQ(last.state, PfState::kOpt2);
  PfMemory mid = in_state(PfState::kSubNest);
  mid.parent = tracked(7, {0.7, 0.0});
  Reading red;
  red.add(Led::kRed, 7, 0, 70);
  EXPECT_EQ(fire(mid, red), "");
  Reading brown;
  brown.add(Led::kBrown, 7, 0, 70);
  EXPECT_EQ(fire(mid, brown), "#11");
}

TEST(PfTable, Row12Opt2DoneWhenAligned) {  // label a
  Reading r;
  PfMemory m = aligning(PfState::kOpt2, r);
  EXPECT_EQ(fire(m, r), "#12");
  EXPECT_EQ(m.state, PfState::kPathDone);
}

TEST(PfTable, Row13ReferenceLostWhileAligning) {  // label f
  Params literal;  // SPEC §2.3 as written: a lost reference is the end of the alignment
  literal.seek_hidden_reference = false;
  for (const PfState s : {PfState::kOpt1, PfState::kOpt2}) {
    Reading r;
    PfMemory m = aligning(s, r);
    r.blobs.erase(r.blobs.begin());  // the parent is gone
    m.parent.unseen = 2;
    EXPECT_EQ(fire(m, r, literal), s == PfState::kOpt1 ? "#13a" : "#13b");
    EXPECT_EQ(m.state, PfState::kRecovery);
  }
}

TEST(PfTable, Row13CountsALossOnceBackWhereTheAlignmentBegan) {
  Params literal;
  literal.seek_hidden_reference = false;
  const auto parent_hidden_away_from_start = [](PfMemory& m, Reading& r, Vec2 start) {
    m = aligning(PfState::kOpt2, r);
    r.blobs.erase(r.blobs.begin());
    m.parent.unseen = 2;
    m.align_leg = AlignLeg::kBackToStart;
    m.safe_pos = start;
  };
  Reading r;
  PfMemory m;
  parent_hidden_away_from_start(m, r, {0.30, 0.0});  // on its way back: not yet
  m.t_state = static_cast<std::int64_t>(literal.t_align_max);
  EXPECT_EQ(fire(m, r, literal), "");
  Reading r2;
  PfMemory near;  // back within d_tol (where align() stops) counts as back
  parent_hidden_away_from_start(near, r2, {0.028, 0.0});
  EXPECT_EQ(fire(near, r2, literal), "#13b");
  Reading r3;
  PfMemory stuck;  // stall guard: cannot get back in another T_align_max
  parent_hidden_away_from_start(stuck, r3, {0.30, 0.0});
  stuck.t_state = static_cast<std::int64_t>(2.0 * literal.t_align_max);
  EXPECT_EQ(fire(stuck, r3, literal), "#13b");
}

TEST(PfTable, Row13WaitsWhileAHiddenReferenceIsLookedFor) {  // R: seek_hidden_reference (default)
  const Params p;
  // the parent, last seen 70 cm ahead, is out of view; the child is in view
  const auto parent_hidden = [](PfMemory& m, Reading& r) {
    m = aligning(PfState::kOpt1, r);
    r.blobs.erase(r.blobs.begin());
    m.parent.unseen = 2;
  };
  Reading r;
  PfMemory m;
  parent_hidden(m, r);
  EXPECT_EQ(fire(m, r, p), "");  // first drive toward where it was seen
  EXPECT_EQ(m.state, PfState::kOpt1);
  Reading r2;
  PfMemory there;  // at the place it was last seen (within d_detect) and not there: lost
  parent_hidden(there, r2);
  there.parent.last_seen = {0.25, 0.0};
  EXPECT_EQ(fire(there, r2, p), "#13a");
  Reading r3;
  PfMemory late;  // out of time: lost
  parent_hidden(late, r3);
  late.t_state = static_cast<std::int64_t>(p.t_align_max);
  EXPECT_EQ(fire(late, r3, p), "#13a");
  Reading r4;
  PfMemory both;  // both out of view: lost
  parent_hidden(both, r4);
  r4.blobs.clear();
  both.child.unseen = 2;
  EXPECT_EQ(fire(both, r4, p), "#13a");
}

TEST(PfTable, Row14RevertOrphansOnlyWithTheOption) {
  Params p;
  for (const PfState s : {PfState::kSubNest, PfState::kPathDone}) {
    PfMemory m = in_state(s);
    m.parent = tracked(7, {0.7, 0.0});
    m.parent.unseen = 5;
    EXPECT_EQ(fire(m, Reading{}, p), "") << to_string(s);
    p.revert_orphans = true;
    EXPECT_EQ(fire(m, Reading{}, p), s == PfState::kSubNest ? "#14a" : "#14b");
    EXPECT_EQ(m.state, PfState::kSubgoal);
    p.revert_orphans = false;
  }
}

TEST(PfTable, RecoveryIsForever) {  // SPEC §2.3 row 14 [I]
  PfMemory m = in_state(PfState::kRecovery);
  m.t_state = 100000;
  Reading r;
  r.add(Led::kYellow, kGoalEmitter, 0, 10);
  r.add(Led::kBlue, kNestEmitter, 0, 10);
  EXPECT_EQ(fire(m, r), "");
}

TEST(PfTable, StructureEveryRowCitedOnceAndEveryActiveStateHasAnExit) {
  std::set<std::string> rows;
  std::set<PfState> from;
  for (const PfTransition& t : pf_transitions()) {
    EXPECT_TRUE(rows.insert(std::string(t.row)).second) << "duplicate row " << t.row;
    from.insert(t.from);
    EXPECT_NE(t.when, nullptr);
  }
  for (int s = 0; s < kPfStateCount; ++s) {
    const auto state = static_cast<PfState>(s);
    const bool terminal = state == PfState::kRecovery || state == PfState::kPathDone;
    if (!terminal) {
      EXPECT_TRUE(from.count(state)) << to_string(state) << " has no exit";
    }
  }
  // the paper's Table 2 labels that apply to path formation all appear
  std::set<std::string> labels;
  for (const PfTransition& t : pf_transitions()) labels.insert(std::string(t.label));
  for (const char* l : {"a", "b", "c", "d", "f", "g", "h", "i"}) EXPECT_TRUE(labels.count(l)) << l;
}

TEST(PfLeds, ColoursOfSpec22) {  // SPEC §2.2: white forming, red subgoal, blue sub-nest [P]
  EXPECT_EQ(led_of(PfState::kSubgoalForming), Led::kWhite);
  EXPECT_EQ(led_of(PfState::kSubgoal), Led::kRed);
  EXPECT_EQ(led_of(PfState::kSubNest), Led::kBlue);
  EXPECT_EQ(led_of(PfState::kRecovery), Led::kOrange);
  EXPECT_EQ(led_of(PfState::kResting), Led::kBlack);
}

// ---- optimisation geometry (SPEC §2.4) ----

TEST(Alignment, ErrorAngleIsZeroOnTheSegment) {
  EXPECT_NEAR(error_angle(deg2rad(10), deg2rad(-170)), 0.0, 1e-12);  // A and B opposite
  EXPECT_NEAR(error_angle(deg2rad(90), deg2rad(-90)), 0.0, 1e-12);
  EXPECT_NEAR(error_angle(deg2rad(0), deg2rad(90)), kPi / 2, 1e-12);  // a right angle
  EXPECT_NEAR(error_angle(deg2rad(30), deg2rad(30)), kPi, 1e-12);     // both on one side
}

TEST(Alignment, TargetIsTheFootOfThePerpendicular) {
  const Params p;
  const Vec2 t = alignment_target({-50, 40}, {50, 40}, p);  // robot 40 cm below A-B
  EXPECT_NEAR(t.x, 0.0, 1e-12);
  EXPECT_NEAR(t.y, 40.0, 1e-12);
  // the foot is clamped to the segment
  const Vec2 end = alignment_target({20, 10}, {80, 10}, p);
  EXPECT_NEAR(end.x, 20.0, 1e-12);
}

TEST(Alignment, TargetKeepsBothReferencesWithinRkeep) {
  const Params p;  // R_keep = 90
  const Vec2 a{0, 10};
  const Vec2 b{170, 10};
  const Vec2 t = alignment_target(a, b, p);  // the foot (0, 10) is 170 cm from B
  EXPECT_LE(dist(t, b), p.r_keep + 1e-9);
  EXPECT_LE(dist(t, a), p.r_keep + 1e-9);
  const Vec2 mid = alignment_target({0, 10}, {200, 10}, p);  // no point within 90 of both
  EXPECT_NEAR(mid.x, 100.0, 1e-12);
}

TEST(Alignment, MidpointBlend) {
  Params p;
  p.lambda_mid = 1.0;
  const Vec2 t = alignment_target({-50, 40}, {70, 40}, p);
  EXPECT_NEAR(t.x, 10.0, 1e-12);
}

TEST(PfTable, OneAtATimeWaitsWhileARobotIsForming) {  // [R] form_one_at_a_time
  Params p;
  p.form_one_at_a_time = true;
  Reading r;
  r.add(Led::kRed, 7, 45, 28);     // a subgoal within d_detect
  r.add(Led::kWhite, 8, -30, 80);  // another robot forming, in view
  PfMemory waiting = in_state(PfState::kExploring);
  EXPECT_EQ(fire(waiting, r, p), "");
  PfMemory eager = in_state(PfState::kExploring);
  EXPECT_EQ(fire(eager, r), "#1");  // the default (false) forms at once
  Reading clear;
  clear.add(Led::kRed, 7, 45, 28);
  PfMemory alone = in_state(PfState::kExploring);
  EXPECT_EQ(fire(alone, clear, p), "#1");
}

// guided departure [R]: an allocated robot's first trip follows the CYAN lights
RobotMemory follower() {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.explore_leg = ExploreLeg::kFollowThenWalk;
  return mem;
}

TEST(GuidedDeparture, FollowsTheLightFewestHopsFromTheFounder) {
  RobotMemory mem = follower();
  Reading r;
  r.add(Led::kCyan, 20, 90, 90, 3);   // left, 3 hops from the founder
  r.add(Led::kCyan, 21, -90, 90, 0);  // right: the founder itself
  const Command cmd = path_formation_step(r.percept(), Params{}, mem);
  EXPECT_EQ(cmd.led, Led::kCyan);
  EXPECT_EQ(cmd.tag, 1);                     // one hop behind the founder
  EXPECT_GT(cmd.left_cm_s, cmd.right_cm_s);  // turning right, toward the founder
  EXPECT_EQ(mem.pf.state, PfState::kExploring);
  EXPECT_EQ(mem.pf.travel_ticks, 1);  // following is travel, not budget
}

TEST(GuidedDeparture, KeepsItsGapAndStopsAtIt) {
  RobotMemory mem = follower();
  Reading r;
  r.add(Led::kCyan, 21, 0, Params{}.guide_gap, 0);  // straight ahead, exactly guide_gap away
  const Command cmd = path_formation_step(r.percept(), Params{}, mem);
  EXPECT_NEAR(cmd.left_cm_s, 0.0, 1e-9);
  EXPECT_NEAR(cmd.right_cm_s, 0.0, 1e-9);
}

TEST(GuidedDeparture, ExploresAloneAfterTGuideLostOrOnSeeingTheGoal) {
  const Params p;
  RobotMemory mem = follower();
  for (int t = 0; t + 1 < static_cast<int>(p.t_guide_lost); ++t) {
    EXPECT_EQ(path_formation_step(Reading{}.percept(), p, mem).led, Led::kCyan) << t;
  }
  EXPECT_EQ(path_formation_step(Reading{}.percept(), p, mem).led, Led::kGreen);
  EXPECT_EQ(mem.pf.explore_leg, ExploreLeg::kWalk);
  RobotMemory lured = follower();
  Reading r;
  r.add(Led::kCyan, 21, 0, 60, 0);
  r.add(Led::kYellow, kGoalEmitter, 30, 80);  // the goal in view beats the guide
  EXPECT_EQ(path_formation_step(r.percept(), p, lured).led, Led::kGreen);
  EXPECT_EQ(lured.pf.explore_leg, ExploreLeg::kWalk);
}

// R: seek_tip (task allocation). An allocated explorer that sees a robot forming the next link
// and no free subgoal walks to it and waits tip_hover away for the free subgoal it will become.
RobotMemory tip_seeker() {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.role = PfRole::kAllocated;  // single_child and seek_tip apply to allocated robots
  return mem;
}

TEST(SeekTip, WalksToTheRobotFormingTheNextLinkAndWaitsBesideIt) {
  const Params p;
  Reading left;
  left.add(Led::kWhite, 9, 90, 90, 8);  // robot 9 forms from subgoal 8, on the left
  left.add(Led::kRed, 8, 60, 95, 7);    // claimed by 9: no lure
  RobotMemory walker = tip_seeker();
  const Command walk = path_formation_step(left.percept(), p, walker);
  EXPECT_EQ(walker.pf.state, PfState::kExploring);
  EXPECT_GT(walk.right_cm_s, walk.left_cm_s);  // turning left, toward robot 9
  Reading beside;
  beside.add(Led::kWhite, 9, 0, p.tip_hover, 8);  // straight ahead, tip_hover away
  RobotMemory waiter = tip_seeker();
  const Command wait = path_formation_step(beside.percept(), p, waiter);
  EXPECT_NEAR(wait.left_cm_s, 0.0, 1e-9);
  EXPECT_NEAR(wait.right_cm_s, 0.0, 1e-9);
  RobotMemory explorer = tip_seeker();  // without seek_tip it explores on (SPEC row 2)
  Params no_tip;
  no_tip.seek_tip = false;
  const Command on = path_formation_step(beside.percept(), no_tip, explorer);
  EXPECT_GT(std::abs(on.left_cm_s) + std::abs(on.right_cm_s), 1.0);
}

// R: recruit_call (task allocation). A RED subgoal, its parent 7 ahead, that no robot forms from or
// names as parent calls resting robots on the medium once T_starve ticks have passed.
RobotMemory calling_subgoal() {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.state = PfState::kSubgoal;
  mem.pf.role = PfRole::kAllocated;  // single_child, rest_recruit and recruit_call: it calls
  mem.pf.parent = tracked(7, {0.7, 0.0});
  return mem;
}

// the first tick (from 1) whose message calls for a link; 0: none within `limit`
int first_call(RobotMemory& mem, const Reading& r, const Params& p, int limit) {
  Reading at = r;
  for (int t = 1; t <= limit; ++t, ++at.tick) {
    const Command cmd = path_formation_step(at.percept(), p, mem);
    EXPECT_EQ(mem.pf.state, PfState::kSubgoal);
    if (cmd.rab_send && decode(cmd.rab).needs_link()) return t;
  }
  return 0;
}

TEST(RecruitCall, ASubgoalNobodyClaimsCallsAfterTStarve) {
  Params p;
  p.recruit_call = true;
  const int limit = static_cast<int>(p.t_starve) + 50;
  Reading alone;
  alone.add(Led::kRed, 7, 0, 70, 6);
  RobotMemory a = calling_subgoal();
  EXPECT_EQ(first_call(a, alone, p, limit), static_cast<int>(p.t_starve));
  Reading claimed = alone;  // a robot forming from it names it on its light
  claimed.add(Led::kWhite, 9, 180, 60, kMe);
  RobotMemory b = calling_subgoal();
  EXPECT_EQ(first_call(b, claimed, p, limit), 0);
  Reading heard = alone;  // ... or a robot answering a call claims it on the medium
  RabMessage msg;
  msg.sender = 12;
  msg.data = encode(claim_message(12, kMe));
  heard.rab.push_back(msg);
  RobotMemory c = calling_subgoal();
  EXPECT_EQ(first_call(c, heard, p, limit), 0);
  RobotMemory d = calling_subgoal();  // without the option it never calls
  Params quiet = p;
  quiet.recruit_call = false;
  EXPECT_EQ(first_call(d, alone, quiet, limit), 0);
}

// R: sighting_returns (task allocation). An allocated explorer back where it saw the chain's tip
// (its sighting follows the nest-most RED robot in view) with nothing free in view there ends its
// trip: the tip has moved nestward, past it.
RobotMemory at_the_sighting() {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.role = PfRole::kAllocated;
  mem.pf.sighting = {0.2, 0.0};
  mem.pf.has_sighting = true;
  mem.pf.explore_leg = ExploreLeg::kToSighting;
  mem.pf.t_explore = 5000;
  return mem;
}

TEST(SightingReturns, NothingFreeWhereTheTipWasEndsTheTrip) {
  Params p;
  p.sighting_returns = true;
  p.seek_tip = false;    // (with it, the robot forming from the subgoal would hold it there)
  Reading claimed_only;  // the subgoal it saw there is claimed now: robot 9 forms from it
  claimed_only.add(Led::kRed, 7, 0, 40, 6);
  claimed_only.add(Led::kWhite, 9, 180, 60, 7);
  RobotMemory mem = at_the_sighting();
  Reading r = claimed_only;
  path_formation_step(r.percept(), p, mem);
  EXPECT_EQ(mem.pf.explore_leg, ExploreLeg::kTripOver);
  ++r.tick;
  path_formation_step(r.percept(), p, mem);
  EXPECT_EQ(mem.pf.state, PfState::kReturnToNest);
  EXPECT_EQ(mem.pf.last_row, pf_row_number("#2"));
  // a free subgoal in view there lures it instead; without the option it explores on
  Reading free_end;
  free_end.add(Led::kRed, 7, 0, 40, 6);
  RobotMemory lured = at_the_sighting();
  path_formation_step(free_end.percept(), p, lured);
  ++free_end.tick;
  path_formation_step(free_end.percept(), p, lured);
  EXPECT_EQ(lured.pf.state, PfState::kExploring);
  Params no = p;
  no.sighting_returns = false;
  RobotMemory off = at_the_sighting();
  Reading r2 = claimed_only;
  path_formation_step(r2.percept(), no, off);
  ++r2.tick;
  path_formation_step(r2.percept(), no, off);
  EXPECT_EQ(off.pf.state, PfState::kExploring);
}

// a SUB_NEST robot that has waited `ticks` ticks, its parent ahead and its child behind
RobotMemory sub_nest_for(std::int64_t ticks) {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.state = PfState::kSubNest;
  mem.pf.t_state = ticks;
  mem.pf.parent = tracked(7, {0.7, 0.0});
  mem.pf.child = tracked(12, {-0.7, 0.0});
  return mem;
}

// [R relink_recovery] a SUB_NEST robot whose parent turned RECOVERY (ORANGE, row 13) closes in on it
// (even with its own child out of view) until it sees the parent's parent, which the RECOVERY
// robot's light names (its tag); row 17 then makes that robot its parent. Env8, 90 robots, seed 9
// (paper.toml then, now paper-single.toml; TA): the chain stood complete from tick 16 989 and never formed
// without it
TEST(RelinkRecovery, ASubNestTakesTheParentOfItsRecoveryParent) {
  struct Outcome {
    double wheels;
    int parent;
    std::uint8_t row;
  };

  const auto step = [](double parent_cm, bool heir_seen, Led heir_led, bool child_seen, const Params& p) {
    RobotMemory mem = sub_nest_for(0);
    mem.pf.parent.last_seen = {parent_cm / 100.0, 0.0};
    Reading r;
    r.add(Led::kOrange, 7, 0, parent_cm, 5);       // the broken link names robot 5
    if (heir_seen) r.add(heir_led, 5, 40, 90, 3);  // robot 5, beyond it
    if (child_seen) r.add(Led::kBlue, 12, 180, 70, kMe);
    const Command cmd = path_formation_step(r.percept(), p, mem);
    EXPECT_EQ(mem.pf.state, PfState::kSubNest);
    return Outcome{cmd.left_cm_s + cmd.right_cm_s, mem.pf.parent.id, mem.pf.last_row};
  };
  const Params p;
  const Outcome closing = step(70, false, Led::kRed, true, p);
  EXPECT_GT(closing.wheels, 0.0);  // forward, toward the ORANGE parent
  EXPECT_EQ(closing.parent, 7);
  EXPECT_GT(step(70, false, Led::kRed, false, p).wheels, 0.0);                    // its child out of view too
  EXPECT_NEAR(step(0.9 * p.r_rec, false, Led::kRed, true, p).wheels, 0.0, 1e-9);  // at the repulsion's edge
  const Outcome relinked = step(70, true, Led::kRed, true, p);
  EXPECT_EQ(relinked.parent, 5);
  EXPECT_EQ(relinked.row, pf_row_number("#17"));
  EXPECT_EQ(step(70, true, Led::kBrown, true, p).parent, 5);   // optimisation 2's wave: the heir is done
  EXPECT_EQ(step(70, true, Led::kOrange, true, p).parent, 7);  // a RECOVERY heir is no link
  Params off = p;
  off.relink_recovery = false;
  const Outcome waits = step(70, true, Led::kRed, true, off);
  EXPECT_NEAR(waits.wheels, 0.0, 1e-9);
  EXPECT_EQ(waits.parent, 7);
}

// [R seek_hidden_reference] a SUB_NEST robot right under a wall's tip sees neither its parent (done,
// past the tip) nor its child: it still goes round toward where it last saw the parent (env8, 100
// robots, seed 6, paper.toml then, now paper-single.toml: robot 32 under wall 2's tip waited from tick 22 300
// to the end)
TEST(SeekHiddenReference, ASubNestSeeingNeitherReferenceLooksForItsParent) {
  const auto wheels = [](const Params& p) {
    RobotMemory mem = sub_nest_for(500);
    mem.pf.parent.unseen = static_cast<int>(2 * p.t_lost);
    mem.pf.child.unseen = static_cast<int>(2 * p.t_lost);
    const Command cmd = path_formation_step(Reading{}.percept(), p, mem);
    EXPECT_EQ(mem.pf.state, PfState::kSubNest);
    return cmd.left_cm_s + cmd.right_cm_s;
  };
  const Params p;
  EXPECT_GT(wheels(p), 0.0);  // the parent's last sighting lies ahead, 70 cm
  Params off = p;
  off.seek_hidden_reference = false;
  EXPECT_NEAR(wheels(off), 0.0, 1e-9);
}

// [R return_lured] a task-allocation scout going home that sees the goal turns to it (then T2 at
// d_detect); an allocated robot going home, or a scout without the option, keeps to its way home
TEST(ReturnLured, AScoutGoingHomeTurnsToTheGoalInView) {
  const auto turn = [](bool scout, const Params& p) {
    RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, -1.0, 0.0}, kNest, p, 1);
    mem.pf.state = PfState::kReturnToNest;
    mem.pf.role = scout ? PfRole::kScout : PfRole::kAllocated;
    Reading r;
    r.add(Led::kYellow, kGoalEmitter, -60, 80);  // on its right; the nest straight ahead
    Percept in = r.percept();
    in.pose = {{0.0, 0.0}, -1.0, 0.0};
    const Command cmd = path_formation_step(in, p, mem);
    return cmd.left_cm_s - cmd.right_cm_s;  // > 0: turning right
  };
  const Params p;
  EXPECT_GT(turn(true, p), 1.0);
  EXPECT_NEAR(turn(false, p), 0.0, 1e-9);
  Params off = p;
  off.return_lured = false;
  EXPECT_NEAR(turn(true, off), 0.0, 1e-9);
}

}  // namespace
}  // namespace swarmpath::sim
