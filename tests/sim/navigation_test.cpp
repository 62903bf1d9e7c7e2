// SPDX-License-Identifier: MIT
// The navigator's trap rule [R]: a robot against an obstacle that has not gained trap_progress
// toward its point for T_trap ticks starts following the obstacle's edge. Robots queueing at a
// wall creep a few cm at a time as they jostle; such creeping must not keep resetting the count.
#include "sim/controllers/navigation.hpp"

#include <array>

#include <gtest/gtest.h>

#include "sim/controllers/trail.hpp"
#include "sim/controllers/units.hpp"

namespace swarmpath::sim {
namespace {

// a robot with a wall straight ahead (the front proximity sensor reads)
Percept against_a_wall() {
  Percept in;
  in.pose = Pose{{0.0, 0.0}, 1.0, 0.0};
  in.proximity[0] = 0.6;
  return in;
}

// ticks until nav_update says "follow the edge", for a robot that creeps `creep_cm` per tick
// toward its point (-1 if it never does within `limit` ticks)
int ticks_until_following(const Params& p, double creep_cm, int limit) {
  NavMemory nav;
  Rng rng(1);
  const Percept in = against_a_wall();
  double progress = -500.0;  // 5 m from the point
  for (int t = 1; t <= limit; ++t) {
    progress += creep_cm;
    if (nav_update(nav, p, rng, progress, in, Vec2{1.0, 0.0})) return t;
  }
  return -1;
}

TEST(Navigator, CreepingLessThanTrapProgressPerTTrapStillCountsAsTrapped) {
  Params p;  // T_trap 100, trap_progress 30 cm
  // 0.25 cm a tick: 25 cm in T_trap ticks, less than trap_progress
  EXPECT_EQ(ticks_until_following(p, 0.25, 1000), static_cast<int>(p.t_trap) + 1);
  // standing still: the same
  EXPECT_EQ(ticks_until_following(p, 0.0, 1000), static_cast<int>(p.t_trap) + 1);
  // moving on (1 cm a tick, 100 cm per T_trap): never trapped
  EXPECT_EQ(ticks_until_following(p, 1.0, 1000), -1);
}

TEST(Navigator, WithTheOldFiveCmThresholdACreepingQueueNeverFollowsTheEdge) {
  Params p;
  p.trap_progress = 5;  // the rule before trap_progress was a key (a fixed 5 cm)
  EXPECT_EQ(ticks_until_following(p, 0.25, 1000), -1);
  EXPECT_EQ(ticks_until_following(p, 0.0, 1000), static_cast<int>(p.t_trap) + 1);
}

// A following that makes no progress for dead_end_traps T_trap ticks turns back along the edge
// (a screen of env7-8 at commit ede714c: docs/CHOICES.md "Exploring"). Returns the tick
// the side flips for a robot that follows a wall and loses `lose_cm` of progress a tick.
int ticks_until_turning_back(const Params& p, double lose_cm) {
  NavMemory nav;
  Rng rng(1);
  const Percept in = against_a_wall();
  double progress = -500.0;
  int side = 0;
  for (int t = 1; t <= 20000; ++t) {
    if (nav.following > 0) progress -= lose_cm;
    const bool following = nav_update(nav, p, rng, progress, in, Vec2{1.0, 0.0});
    if (following && side == 0) side = nav.side;
    if (following && nav.side != side) return t;
  }
  return -1;
}

TEST(Navigator, AFollowingWithoutProgressTurnsBackAfterDeadEndTrapsTTrap) {
  Params p;  // T_trap 100, T_follow 2 000
  p.dead_end_traps = 5;
  const int start = static_cast<int>(p.t_trap) + 1;  // the following begins
  EXPECT_EQ(ticks_until_turning_back(p, 0.1), start + static_cast<int>(5 * p.t_trap));
  p.dead_end_traps = 10;
  EXPECT_EQ(ticks_until_turning_back(p, 0.1), start + static_cast<int>(10 * p.t_trap));
}

// The default, dead_end_traps 20 (docs/detours.md, "Patience along walls"): 20 T_trap is T_follow,
// so a following that loses ground turns back only when T_follow runs out, and a robot walks the
// whole of a long wall to its end, though the wall's end lies where the robot loses ground
TEST(Navigator, InTheDefaultAFollowingThatLosesGroundTurnsBackOnlyWhenTFollowRunsOut) {
  const Params p;
  ASSERT_EQ(p.dead_end_traps * p.t_trap, p.t_follow);
  const int start = static_cast<int>(p.t_trap) + 1;
  EXPECT_EQ(ticks_until_turning_back(p, 0.1), start + static_cast<int>(p.t_follow));
}

// A robot going home along its breadcrumbs, 25 cm from the next crumb, with a robot standing on that
// crumb (chain robots stop where explorers walked): env8, TA, seed 2 (commit ab76562) had five allocated
// robots circling such crumbs in RETURN_TO_NEST for 17 000-25 000 ticks, while the chain's tip
// waited one link short of the nest. Returns the crumbs left after `ticks` ticks of not moving.
int crumbs_left_when_blocked(const Params& p, int ticks) {
  Trail trail;
  trail.reset({0.0, 0.0});
  for (int k = 1; k <= 12; ++k) trail.record({0.25 * k, 0.0});  // out to (3, 0)
  Percept in;
  in.pose = Pose{{2.0, 0.0}, -1.0, 0.0};  // facing home, the blocked crumb at (1.75, 0) ahead
  in.proximity[0] = 0.6;                  // the robot standing on it
  NavMemory nav;
  nav.on_trail = true;
  nav.fell_back = true;  // its one fall-back already spent
  trail.start_home(in.pose.p);
  Rng rng(1);
  for (int t = 0; t < ticks; ++t) nav_home(in, p, nav, rng, trail, {0.0, 0.0}, 0.0, nullptr);
  return trail.size();
}

TEST(Navigator, ARobotGoingHomePassesOverACrumbItCannotReach) {
  Params p;
  ASSERT_TRUE(p.skip_blocked_crumbs);
  const int t_trap = static_cast<int>(p.t_trap);
  const int at_start = crumbs_left_when_blocked(p, 1);
  EXPECT_EQ(at_start, 8);  // crumbs at 0 ... 1.75 m (the one at 2 m consumed: within 15 cm)
  EXPECT_EQ(crumbs_left_when_blocked(p, t_trap - 2), at_start);
  EXPECT_EQ(crumbs_left_when_blocked(p, t_trap + t_trap / 2), at_start - 1);
  Params off = p;
  off.skip_blocked_crumbs = false;  // edge following, the crumb still ahead
  EXPECT_EQ(crumbs_left_when_blocked(off, 5 * t_trap), at_start);
}

// A forming robot backing off to its spot (ta_backoff_spot, backoff_far_spot) retraces its own way
// from the nest once it has made no progress toward the spot for a quarter of T_trap. That window
// asks for trap_progress pro rata (7.5 cm in 25 ticks, the rate of 30 cm in T_trap): asking for the
// whole 30 cm in 25 ticks (60 % of v_max, turning round included) sent robots that were on their way
// to the spot back along their trail, and their links stood beside their targets (env1, 100
// robots, seed 1: 20 of 21 links). Returns the tick the robot takes to its trail, given `window`
// ticks, when it gains `step_cm` a tick toward the spot (-1: not within `limit` ticks).
int ticks_until_trail_from_spot(const Params& p, double window, double step_cm, int limit) {
  Trail trail;
  trail.reset({0.0, 0.0});
  for (int k = 1; k <= 10; ++k) trail.record({0.25 * k, 0.0});  // its way out, to (2.5, 0)
  NavMemory nav;
  Rng rng(1);
  const Vec2 spot{1.4, 0.0};
  Percept in;
  in.pose = Pose{{2.1, 0.0}, -1.0, 0.0};  // facing the spot, nothing on the proximity ring
  for (int t = 1; t <= limit; ++t) {
    nav_home(in, p, nav, rng, trail, {0.0, 0.0}, window, &spot);
    if (nav.on_trail) return t;
    in.pose.p.x -= step_cm / kCmPerM;
  }
  return -1;
}

TEST(Navigator, ARobotOnItsWayToTheSpotAtTheRateTTrapAsksForKeepsGoing) {
  const Params p;  // T_trap 100, trap_progress 30 cm: a quarter of T_trap asks for 7.5 cm
  const double quarter = 0.25 * p.t_trap;
  const int q = static_cast<int>(quarter) + 1;  // the tick after the window
  EXPECT_EQ(ticks_until_trail_from_spot(p, quarter, 0.0, 200), q) << "standing still";
  EXPECT_EQ(ticks_until_trail_from_spot(p, quarter, 0.2, 200), q) << "5 cm in 25 ticks: too slow";
  // 10 cm in 25 ticks, 40 cm per T_trap: on its way (asked for 30 cm in 25 ticks: the trail at 25)
  EXPECT_EQ(ticks_until_trail_from_spot(p, quarter, 0.4, 150), -1);
  // the whole of T_trap asks for the whole of trap_progress, as it always has
  const int t_trap = static_cast<int>(p.t_trap) + 1;
  EXPECT_EQ(ticks_until_trail_from_spot(p, p.t_trap, 0.25, 300), t_trap) << "25 cm in T_trap: too slow";
  EXPECT_EQ(ticks_until_trail_from_spot(p, p.t_trap, 0.4, 150), -1);
}

}  // namespace
}  // namespace swarmpath::sim
