// SPDX-License-Identifier: MIT
// route_to_sighting [R] (docs/detours.md): the way of the trip that saw the chain, kept for the next
// trip to it. The way must lead round the wall the robot went round (not straight at the sighting),
// end where the sighting was seen from, and be none when the sighting was not seen from it.
#include "sim/controllers/route.hpp"

#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

using test::trip_through_the_doorway;

TEST(Route, TheWayLeadsThroughTheDoorwayItCameByAndEndsWhereTheSightingWasSeen) {
  Route r;
  r.keep(trip_through_the_doorway());
  const Vec2 sighting{3.5, 0.3};
  ASSERT_TRUE(r.begin({-3.0, 0.1}, sighting, 1.0));
  Vec2 at{-3.0, 0.1};
  Vec2 crumb{};
  bool through_the_doorway = false;
  int steps = 0;
  while (r.next(at, crumb) && steps++ < 1000) {
    // the way crosses x = 0 only in the doorway (y = -3), never through the wall above it
    if ((crumb.x > 0.0) != (at.x > 0.0)) {
      const double y_at_wall = at.y + (crumb.y - at.y) * (0.0 - at.x) / (crumb.x - at.x);
      EXPECT_LT(y_at_wall, -2.5);
      through_the_doorway = true;
    }
    at = crumb;
  }
  EXPECT_TRUE(through_the_doorway);
  EXPECT_LT(dist(at, sighting), 1.0);  // the way ends where the sighting was seen from
  EXPECT_LT(at.y, 1.0);                // not up the exploring after it
  EXPECT_FALSE(r.walking());
}

TEST(Route, ASightingNotSeenFromTheWayHasNone) {
  Route r;
  r.keep(trip_through_the_doorway());
  EXPECT_FALSE(r.begin({-3.0, 0.0}, {-2.0, 3.0}, 1.0));  // 2.2 m from the nearest crumb
  Vec2 crumb{};
  EXPECT_FALSE(r.next({-3.0, 0.0}, crumb));
  EXPECT_FALSE(r.walking());
}

TEST(Route, ARobotAlreadyOnTheWayStartsWhereItStandsAndCutsShort) {
  Route r;
  r.keep(trip_through_the_doorway());
  ASSERT_TRUE(r.begin({0.0, -3.0}, {3.5, 0.3}, 1.0));  // in the doorway
  Vec2 crumb{};
  ASSERT_TRUE(r.next({0.0, -3.0}, crumb));
  EXPECT_GT(crumb.x, -0.3);  // not back toward the nest
  const double left = r.remaining({0.0, -3.0});
  EXPECT_GT(left, 3.0);
  EXPECT_LT(left, 5.0);  // about 0.5 + 3.9 m through the doorway and up to (3, 0)
  // a robot that finds itself near a crumb further on passes those before it
  ASSERT_TRUE(r.next({1.0, -2.4}, crumb));
  EXPECT_GT(crumb.x, 1.0);
  const double on = r.remaining({1.0, -2.4});
  EXPECT_LT(on, left - 1.0);
  r.skip();  // a crumb it cannot reach: the next one on
  Vec2 after{};
  ASSERT_TRUE(r.next({1.0, -2.4}, after));
  EXPECT_GT(after.x, crumb.x);
}

// way_home_leg [R]: the trip through the doorway turns home at (3, 3); the robot heads home by the
// field, straight at the nest (-3, 0), and finds the goal at (1, 2) on its way (return_finds), 2 m
// from the nearest crumb of its way out.
Trail turned_home_and_found_the_goal() {
  Trail t = test::trip_through_the_doorway();
  const auto home = [&t](Vec2 from, Vec2 to) {
    const int steps = static_cast<int>(dist(from, to) / 0.01);
    for (int k = 1; k <= steps; ++k) t.record_home(from + (static_cast<double>(k) / steps) * (to - from));
  };
  home({3.0, 3.0}, {1.2, 2.1});
  return t;
}

TEST(Route, AGoalFoundOnTheWayHomeLiesOffTheWayOutButOnTheWayWithItsHomeLeg) {
  const Trail t = turned_home_and_found_the_goal();
  const Vec2 goal{1.0, 2.0};
  ASSERT_GE(t.home_size(), 7);
  Route out;
  out.keep(t);  // the way out alone: it ends where the trip turned home
  std::array<Vec2, 16> corners{};
  EXPECT_EQ(out.corners(goal, 1.5, corners), 0);
  EXPECT_FALSE(out.begin({-3.0, 0.0}, goal, 1.5));
  Route with_leg;
  with_leg.keep(t, true);
  const int n = with_leg.corners(goal, 1.5, corners);
  ASSERT_GT(n, 2);  // the way out's corners, then the leg home
  EXPECT_LT(dist(corners[static_cast<std::size_t>(n - 1)], goal), 0.5);  // the way reaches the goal
  ASSERT_TRUE(with_leg.begin({-3.0, 0.0}, goal, 1.5));
  // walked from the nest: through the doorway (the wall along x = 0 is crossed only at y = -3), and
  // up to where the trip turned home and back west (the way the robot walked)
  Vec2 at{-3.0, 0.0};
  Vec2 crumb{};
  int steps = 0;
  double highest = -1e9;
  while (with_leg.next(at, crumb) && steps++ < 1000) {
    if ((crumb.x > 0.0) != (at.x > 0.0)) {
      const double y_at_wall = at.y + (crumb.y - at.y) * (0.0 - at.x) / (crumb.x - at.x);
      EXPECT_LT(y_at_wall, -2.5);
    }
    highest = std::max(highest, crumb.y);
    at = crumb;
  }
  EXPECT_LT(dist(at, goal), 0.5);
  EXPECT_GT(highest, 2.5);
}

// A leg home that comes back along the way out erases the loop: the way is the way out up to where
// the leg met it, then on from there.
TEST(Route, AHomeLegBackAlongTheWayOutErasesTheLoop) {
  Trail t = test::trip_through_the_doorway();                           // ... up to (3, 3)
  for (int k = 1; k <= 200; ++k) t.record_home({3.0, 3.0 - 0.01 * k});  // back down to (3, 1)
  for (int k = 1; k <= 100; ++k) t.record_home({3.0 - 0.01 * k, 1.0});  // then west to (2, 1)
  Route with_leg;
  with_leg.keep(t, true);
  ASSERT_TRUE(with_leg.begin({-3.0, 0.0}, {2.0, 1.0}, 0.3));
  // from (3, 1) on the way out the way goes west: never back up to (3, 3)
  Vec2 at{-3.0, 0.0};
  Vec2 crumb{};
  int steps = 0;
  while (with_leg.next(at, crumb) && steps++ < 1000) {
    EXPECT_LT(crumb.y, 1.3);
    at = crumb;
  }
  EXPECT_LT(dist(at, {2.0, 1.0}), 0.3);
  EXPECT_LT(with_leg.size(), t.size() + 5);  // the loop's crumbs are gone
}

// Taking the trail home (the field trapped the robot) ends the leg: the way is the way out alone.
TEST(Trail, TakingTheTrailHomeClearsTheHomeLeg) {
  Trail t = turned_home_and_found_the_goal();
  ASSERT_GT(t.home_size(), 0);
  t.start_home({1.2, 2.1});
  EXPECT_EQ(t.home_size(), 0);
  t = turned_home_and_found_the_goal();
  t.start_home_within({1.2, 2.1}, {-3.0, 0.0}, Trail::kEverywhere);
  EXPECT_EQ(t.home_size(), 0);
  t.reset({-3.0, 0.0});
  EXPECT_EQ(t.home_size(), 0);
}

}  // namespace
}  // namespace swarmpath::sim
