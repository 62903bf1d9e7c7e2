// SPDX-License-Identifier: MIT
// The breadcrumb trail [R] must never join the two sides of a wall: a robot retracing it is told
// to walk through the wall, presses against it and wanders (env8, the founder going home from the
// goal, commit 68e9317). The thinnest wall in the paper's arenas is 30 cm, so two robot centres on its
// two faces are at least 47 cm apart.
#include "sim/controllers/trail.hpp"

#include <initializer_list>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

using test::walk;

// the first crumb on the way home from `p`
Vec2 first_crumb(Trail& t, Vec2 p) {
  Vec2 c{};
  EXPECT_TRUE(t.next_home(p, c));
  return c;
}

// whether the way home from `p` ever steps from one side of the wall to the other below its end
bool crosses_the_wall(Trail t, Vec2 p) {
  Vec2 c{};
  while (t.next_home(p, c)) {
    if ((c.x > 0.0) != (p.x > 0.0)) {
      const double y_at_wall = p.y + (c.y - p.y) * (0.0 - p.x) / (c.x - p.x);
      if (y_at_wall < 3.0) return true;
    }
    p = c;
  }
  return false;
}

// a wall 30 cm thick along x = 0 from y = -1 up to y = 3: the robot goes up its west face
// (x = -0.235), round its end and down its east face (x = +0.235)
void round_the_wall(Trail& t) {
  walk(t, {-0.235, -1.0}, {-0.235, 3.3});
  walk(t, {-0.235, 3.3}, {0.235, 3.3});
  walk(t, {0.235, 3.3}, {0.235, -1.0});
}

TEST(Trail, LoopErasureNeverCutsAcrossAWall) {
  Trail t;
  // 90 m of zigzag first (rows 1.5 m apart), so that the trail has thinned its crumbs to 1 m
  // spacing (under the old rule the loop erasure radius grew with the spacing, and the 47 cm
  // across the wall then counted as "back near a crumb")
  Vec2 at{-12.0, -2.0};
  t.reset(at);
  for (int row = 0; row < 14; ++row) {
    const Vec2 end{row % 2 == 0 ? -7.0 : -12.0, at.y};
    walk(t, at, end);
    at = row < 13 ? Vec2{end.x, end.y - 1.5} : end;
    walk(t, end, at);
  }
  walk(t, at, {at.x, -24.0});
  walk(t, {at.x, -24.0}, {-0.235, -24.0});
  walk(t, {-0.235, -24.0}, {-0.235, -1.0});
  const double before = t.remaining({-0.235, -1.0});
  round_the_wall(t);
  // the way round is 9.07 m long (a cut across the wall: under a metre)
  EXPECT_GT(t.remaining({0.235, -1.0}), before + 8.5) << "the way round the wall was cut";
  t.start_home({0.235, -1.0});
  EXPECT_FALSE(crosses_the_wall(t, {0.235, -1.0}));
}

TEST(Trail, LoopErasureStillCutsARealLoop) {
  Trail t;
  t.reset({0.0, 0.0});
  walk(t, {0.0, 0.0}, {2.0, 0.0});
  const int straight = t.size();
  walk(t, {2.0, 0.0}, {2.0, 1.0});
  walk(t, {2.0, 1.0}, {3.0, 1.0});
  walk(t, {3.0, 1.0}, {3.0, 0.0});
  walk(t, {3.0, 0.0}, {1.9, 0.0});  // back at the loop's start: the loop is a detour
  EXPECT_LE(t.size(), straight);
}

TEST(Trail, ARobotSentAcrossAWallFallsBackToACrumbItHasBeenAt) {
  // up the west face of the wall, round its end, then away from it and down, 2 m east of it
  const auto lay = [](Trail& t) {
    t.reset({-0.235, -1.0});
    walk(t, {-0.235, -1.0}, {-0.235, 3.3});
    walk(t, {-0.235, 3.3}, {2.0, 3.3});
    walk(t, {2.0, 3.3}, {2.0, -1.0});
  };
  // going home by the field from the trail's end (2, -1): west, into the wall's east face, where
  // the nearest crumbs are across the wall (47 cm) and its own side has none within 2 m
  Trail t;
  lay(t);
  const Vec2 stuck{0.235, -1.0};
  for (double x = 2.0; x >= stuck.x; x -= 0.01) t.touch({x, -1.0});
  t.start_home(stuck);
  EXPECT_LT(first_crumb(t, stuck).x, 0.0);  // the nearest crumb: across the wall
  ASSERT_TRUE(t.fall_back());
  const Vec2 c = first_crumb(t, stuck);
  EXPECT_GT(c.x, 1.9) << "still sent across the wall, to (" << c.x << ", " << c.y << ")";
  EXPECT_FALSE(crosses_the_wall(t, stuck));
  // a robot that walked up along the trail's last leg touched its crumbs; the nearest crumb is one
  // of them, and there is nothing to fall back to
  Trail u;
  lay(u);
  for (double y = -1.0; y <= 2.0; y += 0.01) u.touch({2.0, y});
  u.start_home({2.0, 2.0});
  EXPECT_FALSE(u.fall_back());
  const Vec2 d = first_crumb(u, {2.0, 2.0});
  EXPECT_GT(d.x, 1.9);
  EXPECT_GT(d.y, 1.9);
}

// spot_crumb_tol: the spot a forming robot backs off to is the crumb of its way out
// d_sub + 5 cm from its target, among those nearer the nest than the target; trail_nestward: the way
// home from the tip starts at the nearest such crumb, not at one on the leg back from the goal.
// Nest at (0, 0); the robot walked east to (4, 0.5), past the tip at (3, 0), on to (4, -0.5)
// and back west to the tip.
Trail past_the_tip() {
  Trail t;
  t.reset({0.0, 0.0});
  walk(t, {0.0, 0.0}, {2.0, 0.0});
  walk(t, {2.0, 0.0}, {4.0, 0.5});
  walk(t, {4.0, 0.5}, {4.0, -0.5});
  walk(t, {4.0, -0.5}, {3.1, -0.1});
  return t;
}

TEST(Trail, TheSpotIsTheCrumbOfTheWayOutAtTheLinkLengthNearerTheNest) {
  const Trail t = past_the_tip();
  const Vec2 tip{3.0, 0.0};
  const Vec2 nest{0.0, 0.0};
  Vec2 c{};
  ASSERT_TRUE(t.crumb_at(tip, 0.75, 0.15, nest, dist(tip, nest), c));
  EXPECT_NEAR(dist(c, tip), 0.75, 0.15);
  EXPECT_LT(c.x, tip.x) << "a crumb on the goal side: (" << c.x << ", " << c.y << ")";
  // no crumb within 1 cm of 3 m from the tip nearer the nest: none
  EXPECT_FALSE(t.crumb_at(tip, 3.5, 0.01, nest, dist(tip, nest), c));
}

TEST(Trail, TheWayHomeFromTheTipStartsNearerTheNestThanTheTip) {
  const Vec2 at{3.1, -0.1};
  const Vec2 tip{3.0, 0.0};
  Trail t = past_the_tip();
  t.start_home(at);  // the nearest crumb: on the leg back from the goal side
  EXPECT_GT(first_crumb(t, at).x, tip.x);
  Trail u = past_the_tip();
  u.start_home_within(at, {0.0, 0.0}, dist(tip, Vec2{0.0, 0.0}));
  EXPECT_LT(first_crumb(u, at).x, tip.x);
}

// spot_on_way [R]: the way out went north round a wall's end (x = 1.5, up to y = 2) and came down to
// the tip from the north; the spot is where that way first came within the link's length of the tip
// (north of it), not a point nearer the nest in a straight line, which lies behind the wall
Trail walked(std::initializer_list<Vec2> corners) {
  Trail t;
  t.reset(*corners.begin());
  for (auto it = corners.begin(); it + 1 != corners.end(); ++it) walk(t, *it, *(it + 1));
  return t;
}

Trail round_a_wall() { return walked({{0.0, 0.0}, {0.0, 2.5}, {3.0, 2.5}, {3.0, 0.0}}); }

TEST(Trail, TheWaySpotIsWhereTheWayOutFirstCameThatNearRoundAWall) {
  const Vec2 tip{3.0, 0.0};
  Vec2 c{};
  const Trail t = round_a_wall();
  ASSERT_TRUE(t.first_within(tip, 0.75, c));
  EXPECT_NEAR(c.x, 3.0, 1e-9);
  EXPECT_NEAR(c.y, 0.75, 1e-9);  // on the leg down to the tip, farther from the nest than the tip
  // the straight-line spot: no crumb of the way 75 cm from the tip is nearer the nest than it
  EXPECT_FALSE(t.crumb_at(tip, 0.75, 0.15, Vec2{}, dist(tip, Vec2{}), c));  // the nest at (0, 0)
  // a way that passes the tip twice: the first time counts
  // (back within 75 cm of the tip from the south-east at the end)
  const Trail twice =
      walked({{0.0, 0.0}, {0.0, 2.5}, {3.0, 2.5}, {3.0, 0.0}, {4.0, 0.0}, {4.0, -1.0}, {3.5, -0.5}});
  ASSERT_TRUE(twice.first_within(tip, 0.75, c));
  EXPECT_NEAR(c.y, 0.75, 1e-9);
  // a way that starts within the distance, or never comes that near: none
  EXPECT_FALSE(t.first_within({0.2, 0.2}, 0.75, c));
  EXPECT_FALSE(t.first_within({6.0, 0.0}, 0.75, c));
}

// way_after_edge [R]: a trip on which the robot followed an obstacle's edge went round something;
// the next trip starts without it
TEST(Trail, ATripRemembersThatItFollowedAnEdgeUntilTheNextTrip) {
  Trail t = round_a_wall();
  EXPECT_FALSE(t.went_round());
  t.mark_edge();
  walk(t, {3.0, 0.0}, {4.0, 0.0});
  EXPECT_TRUE(t.went_round());
  t.reset({0.0, 0.0});
  EXPECT_FALSE(t.went_round());
}

}  // namespace
}  // namespace swarmpath::sim
