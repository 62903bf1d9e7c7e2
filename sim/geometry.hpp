// SPDX-License-Identifier: MIT
// Static obstacle shapes (oriented boxes and circles) and the exact queries the sensors,
// the A* rasteriser and the scenario validator need: distance, containment, ray casts.
#pragma once

#include <cstdint>
#include <limits>

#include "vec2.hpp"

namespace swarmpath::sim {

struct Aabb {
  Vec2 lo;
  Vec2 hi;

  bool overlaps(const Aabb& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
  }

  bool contains(Vec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

inline Aabb aabb_around(Vec2 c, double r) { return {{c.x - r, c.y - r}, {c.x + r, c.y + r}}; }

enum class ShapeKind : std::uint8_t { kBox, kCircle };

/// An immovable obstacle: an oriented box (walls too) or a circle (cylinders).
struct Shape {
  ShapeKind kind = ShapeKind::kBox;
  Vec2 center;
  Vec2 half;            ///< box half extents [m] (boxes)
  double c = 1.0;       ///< cos(yaw) (boxes)
  double s = 0.0;       ///< sin(yaw) (boxes)
  double radius = 0.0;  ///< circles [m]
  Aabb bounds;

  static Shape box(Vec2 center, Vec2 size, double yaw);
  static Shape circle(Vec2 center, double radius);
};

/// Signed distance from p to the shape's surface [m]: negative inside.
double signed_distance(const Shape& shape, Vec2 p);

/// Distance along the ray o + t*d (d a unit vector) to the first point of the shape, for t in
/// [0, max_t]; 0 if o is inside; +infinity when missed.
double ray_cast(const Shape& shape, Vec2 o, Vec2 d, double max_t);

/// Same for a circle of radius r at c.
double ray_cast_circle(Vec2 c, double r, Vec2 o, Vec2 d, double max_t);

/// True when the segment a-b touches the shape.
bool segment_hits(const Shape& shape, Vec2 a, Vec2 b);

/// True when the segment a-b passes within r of c.
bool segment_hits_circle(Vec2 c, double r, Vec2 a, Vec2 b);

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

}  // namespace swarmpath::sim
