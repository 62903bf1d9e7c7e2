// SPDX-License-Identifier: MIT
#include "sim/geometry.hpp"

#include <gtest/gtest.h>

namespace swarmpath::sim {
namespace {

TEST(Geometry, SignedDistanceToARotatedBox) {
  const Shape box = Shape::box({1.0, 0.0}, {2.0, 1.0}, deg2rad(90.0));  // now 1 wide (x), 2 tall (y)
  EXPECT_NEAR(signed_distance(box, {2.0, 0.0}), 0.5, 1e-12);
  EXPECT_NEAR(signed_distance(box, {1.0, 1.5}), 0.5, 1e-12);
  EXPECT_NEAR(signed_distance(box, {1.0, 0.0}), -0.5, 1e-12);
  EXPECT_NEAR(signed_distance(box, {2.5, 2.0}), std::hypot(1.0, 1.0), 1e-12);
}

TEST(Geometry, RayCastHitsTheNearFace) {
  const Shape box = Shape::box({2.0, 0.0}, {1.0, 1.0}, 0.0);
  EXPECT_NEAR(ray_cast(box, {0.0, 0.0}, {1.0, 0.0}, 10.0), 1.5, 1e-12);
  EXPECT_EQ(ray_cast(box, {0.0, 0.0}, {1.0, 0.0}, 1.4), kNoHit);    // too short
  EXPECT_EQ(ray_cast(box, {0.0, 0.0}, {-1.0, 0.0}, 10.0), kNoHit);  // facing away
  EXPECT_EQ(ray_cast(box, {2.0, 0.0}, {1.0, 0.0}, 10.0), 0.0);      // starts inside
  const Shape cyl = Shape::circle({0.0, 3.0}, 1.0);
  EXPECT_NEAR(ray_cast(cyl, {0.0, 0.0}, {0.0, 1.0}, 10.0), 2.0, 1e-12);
  EXPECT_EQ(ray_cast(cyl, {1.5, 0.0}, {0.0, 1.0}, 10.0), kNoHit);
}

TEST(Geometry, SegmentTests) {
  const Shape wall = Shape::box({0.0, 0.0}, {0.1, 2.0}, 0.0);
  EXPECT_TRUE(segment_hits(wall, {-1.0, 0.0}, {1.0, 0.0}));
  EXPECT_FALSE(segment_hits(wall, {-1.0, 1.2}, {1.0, 1.2}));
  EXPECT_FALSE(segment_hits(wall, {0.2, -1.0}, {0.2, 1.0}));
  EXPECT_TRUE(segment_hits_circle({0.0, 0.0}, 0.1, {-1.0, 0.05}, {1.0, 0.05}));
  EXPECT_FALSE(segment_hits_circle({0.0, 0.0}, 0.1, {-1.0, 0.15}, {1.0, 0.15}));
  EXPECT_FALSE(segment_hits_circle({2.0, 0.0}, 0.1, {-1.0, 0.0}, {1.0, 0.0}));  // beyond the end
}

TEST(Geometry, WrapAngle) {
  EXPECT_NEAR(wrap_angle(3.0 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-0.5 * kPi - 4.0 * kPi), -0.5 * kPi, 1e-12);
}

}  // namespace
}  // namespace swarmpath::sim
