// SPDX-License-Identifier: MIT
// route_to_sighting [R] (docs/detours.md): the way of the trip that saw the chain, kept for the next
// trip to it. The way must lead round the wall the robot went round (not straight at the sighting),
// end where the sighting was seen from, and be none when the sighting was not seen from it.
#include "sim/controllers/route.hpp"

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

}  // namespace
}  // namespace swarmpath::sim
