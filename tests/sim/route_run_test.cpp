// SPDX-License-Identifier: MIT
// route_to_sighting [R] (docs/detours.md, row #2 with site fidelity): a robot travelling back to where
// it saw the chain that the field traps against a wall retraces the way of the trip that saw it. In a
// small arena whose doorway lies far off the nest-goal line (tests/data/far_door.toml), the straight
// line from the nest to the goal's room runs into the wall; the robots' own ways lead to the doorway.
// walk_way and share_way walk such ways from the start of a trip, in task allocation (far_door) and,
// told at the nest, in path formation (tests/data/small_serpentine.toml: two walls on the way);
// lead_way, the founder's way told at the nest to the robots it allocates (tests/data/wallfar_11.toml).
#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Travel {
  bool formed = false;
  std::int64_t ticks = -1;      ///< ticks to form (-1: not formed)
  std::int64_t travelling = 0;  ///< robot-ticks spent travelling to a sighting (or leading there)
  std::int64_t on_route = 0;    ///< ... of them, walking a kept way (its own, or one heard)
  std::int64_t on_told = 0;     ///< ... of them, walking a way heard from another robot (share_way)
};

Travel run_arena(const char* file, const Params& p, Mode mode, std::uint64_t seed) {
  const Scenario s = load_scenario(test::source_path(file));
  Travel t;
  const auto observe = [&t](const World& w) {
    for (const RobotMemory& mem : w.memory) {
      const bool travel =
          mem.pf.state == PfState::kExploring &&
          (mem.pf.explore_leg == ExploreLeg::kToSighting || mem.pf.explore_leg == ExploreLeg::kLead);
      if (!travel) continue;
      ++t.travelling;
      if (mem.route.walking()) ++t.on_route;
      if (mem.route.walking() && mem.pf.told.complete()) ++t.on_told;
    }
    return false;
  };
  const Metrics m = run(p, s, mode, seed, observe);
  t.formed = m.success;
  t.ticks = m.ticks_to_form;
  return t;
}

Travel run_far_door(const Params& p, Mode mode, std::uint64_t seed) {
  return run_arena("tests/data/far_door.toml", p, mode, seed);
}

// far_door, 50 robots, path formation, seeds 1-8 (off -> on: formed; robot-ticks travelling to a
// sighting): off forms seeds 2, 3, 4, 8, on every seed but 8. Seed 1: no -> yes, 142 836 -> 44 534;
// seed 5: no -> yes, 196 444 -> 30 517; seed 6: 142 669 -> 50 393; seed 7: 150 578 -> 32 467. Without
// the rule the robots that saw the chain press against the wall on their way back to it, until
// travel_cap ends their trips; with it they turn along the way they came once the field traps them.
// Task allocation: 7 -> 8 formed (seed 7).
TEST(RouteToSighting, RobotsTrappedOnTheirWayBackToTheChainRetraceTheWayTheyCame) {
  Params off;  // the default: route_to_sighting = false
  test::far_door_as_measured(off);
  Params on = off;
  on.route_to_sighting = true;
  for (const std::uint64_t seed : {1, 5, 6, 7}) {
    const Travel without = run_far_door(off, Mode::kPathFormation, seed);
    const Travel with = run_far_door(on, Mode::kPathFormation, seed);
    EXPECT_EQ(without.on_route, 0) << seed;  // off: nobody walks a kept way
    EXPECT_FALSE(without.formed) << seed;
    EXPECT_GT(with.on_route, 0) << seed;
    EXPECT_LT(2 * with.travelling, without.travelling) << seed;  // less than half the travel
    EXPECT_TRUE(with.formed) << seed;
  }
}

// walk_way, share_way [R] (docs/detours.md): ways walked from the start of a trip.

// far_door, 50 robots, task allocation, seeds 1-8 (off -> on: ticks to form; robot-ticks travelling
// to a sighting): off forms every seed but 7; on every seed, seed 7 at 9 054 ticks with its travel
// 105 043 -> 45 355 robot-ticks (the robots that saw the chain, sent back to it by the field, press
// against the wall until travel_cap ends their trips); the other seeds form within 1 200 ticks of
// off, six of them walking a kept way for 500-4 000 robot-ticks.
TEST(WalkWay, RobotsOfTaskAllocationWalkTheWayTheyCameBackToTheChain) {
  Params off;                       // the default: walk_way = false
  test::hasty_along_walls(off);     // as measured
  off.lead_way = false;             // as measured: no robot walks the founder's way either
  off.away_decay = 1.0;             // ... and every trip under the full away field
  off.resume_search = false;        // ... explored from the nest
  off.chain_bypass = false;         // ... every link kept (with it seed 7 forms without the rule)
  off.anywhere_after_edge = false;  // ... and subgoals only near the target's distance from the nest
  test::ta_spot_straight(off);      // ... backing off to the straight-line spot
  ASSERT_FALSE(off.walk_way);
  Params on = off;
  on.walk_way = true;
  int formed_off = 0;
  int formed_on = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Travel without = run_far_door(off, Mode::kTaskAllocation, seed);
    const Travel with = run_far_door(on, Mode::kTaskAllocation, seed);
    EXPECT_EQ(without.on_route, 0) << seed;  // off: nobody walks a kept way
    formed_off += without.formed ? 1 : 0;
    formed_on += with.formed ? 1 : 0;
    if (seed == 7) {
      EXPECT_FALSE(without.formed);
      EXPECT_TRUE(with.formed);
      EXPECT_GT(with.on_route, 0);
      EXPECT_LT(2 * with.travelling, without.travelling);  // less than half the travel
    }
  }
  EXPECT_EQ(formed_off, 7);
  EXPECT_EQ(formed_on, 8);
  // path formation without task allocation is not touched: the same run, bit for bit
  const Scenario s = load_scenario(test::source_path("tests/data/far_door.toml"));
  EXPECT_EQ(evaluate(off, s, Mode::kPathFormation, 1).state_hash,
            evaluate(on, s, Mode::kPathFormation, 1).state_hash);
}

// small_serpentine, 40 robots, path formation, telling from the start of the run (share_after = 0),
// seeds 1-8 (off -> on: robot-ticks travelling to a sighting): every seed forms either way; the
// travel falls to 13-63 % of off's on every seed (seed 1: 120 279 -> 16 279; seed 5: 145 937 ->
// 22 925; all eight 859 073 -> 198 661), most of it along ways heard from other robots, and the
// path forms sooner on six seeds (seed 5: 19 812 -> 8 172 ticks; all eight 92 001 -> 77 273).
TEST(ShareWay, ToldRobotsWalkTheWayTheTellerCameAndTravelFarLess) {
  Params off;
  test::hasty_along_walls(off);  // as measured
  off.share_after = 0;
  off.away_decay = 1.0;                // as measured: every trip under the full away field
  off.resume_search = false;           // ... explored from the nest
  test::pf_links_by_trail_slack(off);  // ... and links laid by trail_slack alone
  ASSERT_FALSE(off.share_way);
  Params on = off;
  on.share_way = true;
  std::int64_t travel_off = 0;
  std::int64_t travel_on = 0;
  std::int64_t ticks_off = 0;
  std::int64_t ticks_on = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Travel without = run_arena("tests/data/small_serpentine.toml", off, Mode::kPathFormation, seed);
    const Travel with = run_arena("tests/data/small_serpentine.toml", on, Mode::kPathFormation, seed);
    EXPECT_TRUE(without.formed) << seed;
    EXPECT_TRUE(with.formed) << seed;
    EXPECT_EQ(without.on_route, 0) << seed;  // off: the field toward the sighting, no way
    EXPECT_GT(with.on_told, 0) << seed;      // on: robots walk ways they heard
    EXPECT_LT(with.travelling, without.travelling) << seed;
    travel_off += without.travelling;
    travel_on += with.travelling;
    ticks_off += without.ticks;
    ticks_on += with.ticks;
  }
  EXPECT_LT(3 * travel_on, travel_off);
  EXPECT_LT(ticks_on, ticks_off);
}

// lead_way [R] (docs/detours.md): the founder tells the way of the trip that found the goal at the
// nest, and the allocated robots walk it. tests/data/wallfar_11.toml (the training arena
// wall-gap-11: a wall across the arena, its one doorway 7.4 m off the nest-goal line), 60 robots, seed 21,
// task allocation: without the rule the allocated robots that lose their guide head for the goal by
// the field, into the wall, and the path does not form within T_max; with it they walk the
// founder's way through the doorway and the path forms.
TEST(LeadWay, AllocatedRobotsWalkTheWayTheFounderFoundTheGoalBy) {
  Params on;                    // the default
  test::hasty_along_walls(on);  // as measured
  ASSERT_TRUE(on.lead_way);
  on.resume_search = false;  // as measured: every trip explores from the nest
  Params off = on;
  off.lead_way = false;
  const Travel without = run_arena("tests/data/wallfar_11.toml", off, Mode::kTaskAllocation, 21);
  const Travel with = run_arena("tests/data/wallfar_11.toml", on, Mode::kTaskAllocation, 21);
  EXPECT_EQ(without.on_told, 0);  // off: nobody walks a way it was told
  EXPECT_FALSE(without.formed);
  // on: most of the travel to the goal is along the founder's way (59 108 of 88 559 robot-ticks), and
  // the travel is a fifth of off's (456 485 robot-ticks pressing against the wall)
  EXPECT_GT(2 * with.on_told, with.travelling);
  EXPECT_LT(2 * with.travelling, without.travelling);
  EXPECT_TRUE(with.formed);
  // path formation without task allocation is not touched: the same run, bit for bit
  const Scenario s = load_scenario(test::source_path("tests/data/far_door.toml"));
  EXPECT_EQ(evaluate(off, s, Mode::kPathFormation, 1).state_hash,
            evaluate(on, s, Mode::kPathFormation, 1).state_hash);
}

// way_home_leg [R] (docs/detours.md): a founder that found the goal on its way home (return_finds)
// keeps a way out that ends where its trip turned home, 4 m from the goal; no crumb of it lies within
// R_vis + 0.5 m of the goal, so no way is told, and the allocated robots head for the goal by the
// field, into the wall under the goal's room. tests/data/rooms_1.toml (the training arena rooms-1:
// the goal's room above the nest's, its door three rooms round), 100 robots, seed 23, task allocation,
// the first 13 000 ticks: with the rule the way goes on along the founder's leg home to the goal.
TEST(WayHomeLeg, AFounderThatFoundTheGoalOnItsWayHomeTellsAWayThatReachesIt) {
  Params off;                    // the default
  test::hasty_along_walls(off);  // as measured
  ASSERT_FALSE(off.way_home_leg);
  Params on = off;
  on.way_home_leg = true;
  const Scenario s = with_max_ticks(load_scenario(test::source_path("tests/data/rooms_1.toml")), 13000);

  struct Seen {
    std::int64_t on_told = 0;  ///< robot-ticks walking a way heard from the founder
    int in_goal_room = 0;      ///< allocated robots in the goal's room at the last tick
  };

  const auto watch = [&s](const Params& p) {
    Seen seen;
    const auto observe = [&seen](const World& w) {
      seen.in_goal_room = 0;
      for (std::size_t i = 0; i < w.memory.size(); ++i) {
        const RobotMemory& mem = w.memory[i];
        if (mem.route.walking() && mem.pf.told.complete()) ++seen.on_told;
        const Vec2 at = w.positions[i];
        const bool goal_room = at.x < -4.1 && at.y > 0.1;  // west of x = -4, north of y = 0
        if (mem.ta.state == TaState::kPathFormation && goal_room) ++seen.in_goal_room;
      }
      return false;
    };
    run(p, s, Mode::kTaskAllocation, 23, observe);
    return seen;
  };
  const Seen without = watch(off);
  const Seen with = watch(on);
  EXPECT_EQ(without.on_told, 0);  // off: no way told, nobody walks one
  EXPECT_EQ(without.in_goal_room, 0);
  // on: 97 391 robot-ticks along the founder's way, 13 allocated robots in the goal's room
  EXPECT_GT(with.on_told, 50000);
  EXPECT_GE(with.in_goal_room, 10);
}

}  // namespace
}  // namespace swarmpath::sim
