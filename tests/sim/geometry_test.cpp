// SPDX-License-Identifier: MIT
#include "sim/geometry.hpp"

#include <cmath>

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

// segment_hits skips the ray cast when the segment's box misses the shape's: over a fan of segments
// round a rotated box and a circle, grazing their corners, its answer is the ray cast's
TEST(Geometry, SegmentHitsAgreesWithTheRayCastEverywhere) {
  const Shape shapes[] = {Shape::box({0.3, -0.2}, {0.8, 2.0}, deg2rad(30.0)), Shape::circle({0.1, 0.4}, 0.5)};
  int hits = 0;
  int misses = 0;
  for (const Shape& shape : shapes) {
    for (int i = 0; i < 60; ++i) {
      const double ai = 2.0 * kPi * i / 60.0;
      const Vec2 a = shape.center + 1.6 * Vec2{std::cos(ai), std::sin(ai)};
      for (int j = 0; j < 240; ++j) {
        const double aj = 2.0 * kPi * j / 240.0;
        const Vec2 b = shape.center + (0.3 + 0.01 * j) * Vec2{std::cos(aj), std::sin(aj)};
        const Vec2 ab = b - a;
        const double len = norm(ab);
        const bool cast = ray_cast(shape, a, (1.0 / len) * ab, len) != kNoHit;
        EXPECT_EQ(segment_hits(shape, a, b), cast) << "a " << a.x << "," << a.y << " b " << b.x << "," << b.y;
        (cast ? hits : misses) += 1;
      }
    }
  }
  EXPECT_GT(hits, 1000);  // both answers are well represented
  EXPECT_GT(misses, 1000);
}

TEST(Geometry, WrapAngle) {
  EXPECT_NEAR(wrap_angle(3.0 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-0.5 * kPi - 4.0 * kPi), -0.5 * kPi, 1e-12);
}

}  // namespace
}  // namespace swarmpath::sim
