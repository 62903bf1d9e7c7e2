// SPDX-License-Identifier: MIT
// walk_way, share_way [R] (docs/detours.md): a robot whose trip saw the chain keeps that trip's way
// and walks it on its next trip there; with share_way it tells that way at the nest, corner by corner
// over the range-and-bearing medium (10 bytes a message), and a robot that took its sighting walks
// the way it heard instead of heading straight at the sighting, into whatever wall lies between.
#include <array>
#include <cstdint>

#include <gtest/gtest.h>

#include "sim/controllers/route.hpp"
#include "sim/controllers/sighting_share.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

using test::trip_through_the_doorway;

// whether the polyline p[0..n) crosses the wall x = 0 anywhere but in the doorway (y < -2.5)
bool crosses_the_wall(const Vec2* p, int n) {
  for (int i = 1; i < n; ++i) {
    const Vec2 a = p[i - 1];
    const Vec2 b = p[i];
    if ((a.x > 0.0) == (b.x > 0.0)) continue;
    const double y_at_wall = a.y + (b.y - a.y) * (0.0 - a.x) / (b.x - a.x);
    if (y_at_wall > -2.5) return true;
  }
  return false;
}

TEST(Route, CornersKeepTheTurnsOfTheWayAndDropItsStraightStretches) {
  Route r;
  r.keep(trip_through_the_doorway());
  const Vec2 sighting{3.5, 0.3};
  // from where the trip began to where it saw the chain, not up the exploring after it
  const auto ends_right = [&](const Vec2* c, int n) {
    return dist(c[0], {-3.0, 0.0}) < 0.01 && dist(c[n - 1], sighting) < 1.0 && c[n - 1].y < 1.0;
  };
  std::array<Vec2, ToldWay::kMax> out{};
  const int n = r.corners(sighting, 1.0, out);
  ASSERT_GE(n, 4);  // the start, both sides of the doorway, the end
  EXPECT_LT(n, r.size() / 4);
  EXPECT_TRUE(ends_right(out.data(), n));
  EXPECT_FALSE(crosses_the_wall(out.data(), n));
  // fewer corners allowed: the straight stretches go first, the ends stay
  std::array<Vec2, 3> few{};
  EXPECT_EQ(r.corners(sighting, 1.0, few), 3);
  EXPECT_TRUE(ends_right(few.data(), 3));
  // a sighting the way never came near: no way
  EXPECT_EQ(r.corners({-2.0, 3.0}, 1.0, out), 0);
}

TEST(Route, AWayOfCornersIsWalkedAsTheCrumbsAre) {
  Route kept;
  kept.keep(trip_through_the_doorway());
  const Vec2 sighting{3.5, 0.3};
  std::array<Vec2, ToldWay::kMax> corners{};
  const int n = kept.corners(sighting, 1.0, corners);
  Route r;
  r.assign(std::span<const Vec2>(corners.data(), static_cast<std::size_t>(n)));
  ASSERT_TRUE(r.begin({-3.0, 0.1}, sighting, 1.0 + kWaySlack));
  std::array<Vec2, 64> walked{};
  walked[0] = {-3.0, 0.1};
  int m = 1;
  Vec2 crumb{};
  while (m < 64 && r.next(walked[static_cast<std::size_t>(m - 1)], crumb))
    walked[static_cast<std::size_t>(m++)] = crumb;
  EXPECT_EQ(m, n);  // every corner after the first (the robot stands at it)
  EXPECT_FALSE(crosses_the_wall(walked.data(), m));
  EXPECT_LT(dist(walked[static_cast<std::size_t>(m - 1)], sighting), 1.0);
}

TEST(ShareWay, ATellerTellsItsWayCornerByCornerAndTheListenerHearsItWhole) {
  Params p;
  p.share_sighting = 300;
  p.share_after = 0;
  p.share_way = true;
  const Vec2 nest{-3.0, 0.0};
  Route route;
  route.keep(trip_through_the_doorway());
  PfMemory teller;
  teller.state = PfState::kResting;
  teller.sighting = {3.5, 0.3};
  teller.has_sighting = true;
  // a teller that knows no way to its sighting (it was told the place alone) tells nothing
  EXPECT_FALSE(tells_sighting(p, teller, 100.0, 10));
  teller.knows_way = true;
  work_out_way(p, route, teller);
  ASSERT_GE(teller.tell_count, 4);
  EXPECT_TRUE(tells_sighting(p, teller, 100.0, 10));
  // the sighting on even ticks, a corner of the way on odd ones
  Command even;
  EXPECT_FALSE(tell_way(7, nest, p, route, teller, 10, even));
  EXPECT_FALSE(even.rab_send);
  tell_sighting(7, nest, teller, even);

  PfMemory listener;
  listener.state = PfState::kResting;
  std::array<RabMessage, 1> inbox{};
  inbox[0].sender = 7;
  inbox[0].range_cm = 150;
  inbox[0].data = even.rab;
  EXPECT_FALSE(listens_for_way(p, listener));  // no teller taken yet
  ASSERT_TRUE(hear_sighting(inbox, nest, listener));
  EXPECT_EQ(listener.told.teller, 7);
  EXPECT_FALSE(listener.knows_way);
  // another robot's corners are not this way's
  PfMemory stranger = teller;
  Command other;
  ASSERT_TRUE(tell_way(8, nest, p, route, stranger, 11, other));
  inbox[0].sender = 8;
  inbox[0].data = other.rab;
  EXPECT_FALSE(hear_way(inbox, nest, listener));
  // every corner, heard over 2 * count ticks
  inbox[0].sender = 7;
  for (std::int64_t tick = 11; !listener.told.complete() && tick < 11 + 2 * ToldWay::kMax; tick += 2) {
    ASSERT_TRUE(listens_for_way(p, listener));
    Command cmd;
    ASSERT_TRUE(tell_way(7, nest, p, route, teller, tick, cmd));
    inbox[0].data = cmd.rab;
    EXPECT_TRUE(hear_way(inbox, nest, listener));
  }
  ASSERT_TRUE(listener.told.complete());
  EXPECT_EQ(listener.told.count, teller.tell_count);
  for (int i = 0; i < teller.tell_count; ++i)  // 1 cm on the medium; both signs travel
    EXPECT_LT(dist(listener.told.corners[static_cast<std::size_t>(i)],
                   teller.tell_corners[static_cast<std::size_t>(i)]),
              0.01);
  EXPECT_FALSE(listens_for_way(p, listener));  // heard whole
  // a corner 500 m from the nest (an arena of that size) travels to the decimetre, not clamped
  PfMemory far_teller = teller;
  far_teller.tell_corners[0] = nest + Vec2{500.0, -0.3};
  far_teller.tell_for = far_teller.sighting;  // the corners as worked out, with the far one
  Command far_cmd;
  ASSERT_TRUE(tell_way(7, nest, p, route, far_teller, 2 * teller.tell_count + 1, far_cmd));  // corner 0
  PfMemory far_listener = listener;
  far_listener.told = ToldWay{};
  far_listener.told.teller = 7;
  inbox[0].data = far_cmd.rab;
  ASSERT_TRUE(hear_way(inbox, nest, far_listener));
  EXPECT_LT(dist(far_listener.told.corners[0], far_teller.tell_corners[0]), 0.1);
  // without share_way the sighting alone is told, as before
  p.share_way = false;
  PfMemory plain = teller;
  plain.knows_way = false;
  EXPECT_TRUE(tells_sighting(p, plain, 100.0, 11));
  Command none;
  EXPECT_FALSE(tell_way(7, nest, p, route, plain, 11, none));
}

}  // namespace
}  // namespace swarmpath::sim
