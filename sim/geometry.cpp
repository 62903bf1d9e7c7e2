// SPDX-License-Identifier: MIT
#include "geometry.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::sim {

Shape Shape::box(Vec2 center, Vec2 size, double yaw) {
  Shape sh;
  sh.kind = ShapeKind::kBox;
  sh.center = center;
  sh.half = 0.5 * size;
  sh.c = std::cos(yaw);
  sh.s = std::sin(yaw);
  const double ex = std::fabs(sh.c) * sh.half.x + std::fabs(sh.s) * sh.half.y;
  const double ey = std::fabs(sh.s) * sh.half.x + std::fabs(sh.c) * sh.half.y;
  sh.bounds = {{center.x - ex, center.y - ey}, {center.x + ex, center.y + ey}};
  return sh;
}

Shape Shape::circle(Vec2 center, double radius) {
  Shape sh;
  sh.kind = ShapeKind::kCircle;
  sh.center = center;
  sh.radius = radius;
  sh.bounds = aabb_around(center, radius);
  return sh;
}

double signed_distance(const Shape& shape, Vec2 p) {
  if (shape.kind == ShapeKind::kCircle) return dist(p, shape.center) - shape.radius;
  const Vec2 q = unrotate(p - shape.center, shape.c, shape.s);
  const double dx = std::fabs(q.x) - shape.half.x;
  const double dy = std::fabs(q.y) - shape.half.y;
  const double outside = std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
  return outside + std::min(std::max(dx, dy), 0.0);
}

double ray_cast_circle(Vec2 c, double r, Vec2 o, Vec2 d, double max_t) {
  const Vec2 oc = o - c;
  const double c2 = norm2(oc) - r * r;
  if (c2 <= 0.0) return 0.0;  // starts inside
  const double b = dot(oc, d);
  if (b >= 0.0) return kNoHit;  // pointing away
  const double disc = b * b - c2;
  if (disc < 0.0) return kNoHit;
  const double t = -b - std::sqrt(disc);
  return t <= max_t ? t : kNoHit;
}

namespace {

// slab test in the box frame; returns the entry distance or kNoHit
double ray_cast_box(const Shape& box, Vec2 o, Vec2 d, double max_t) {
  const Vec2 lo = unrotate(o - box.center, box.c, box.s);
  const Vec2 ld = unrotate(d, box.c, box.s);
  double t0 = 0.0;
  double t1 = max_t;
  const double origin[2] = {lo.x, lo.y};
  const double dir[2] = {ld.x, ld.y};
  const double half[2] = {box.half.x, box.half.y};
  for (int a = 0; a < 2; ++a) {
    if (std::fabs(dir[a]) < 1e-15) {
      if (std::fabs(origin[a]) > half[a]) return kNoHit;
      continue;
    }
    const double inv = 1.0 / dir[a];
    double ta = (-half[a] - origin[a]) * inv;
    double tb = (half[a] - origin[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kNoHit;
  }
  return t0;
}

}  // namespace

double ray_cast(const Shape& shape, Vec2 o, Vec2 d, double max_t) {
  if (shape.kind == ShapeKind::kCircle) return ray_cast_circle(shape.center, shape.radius, o, d, max_t);
  return ray_cast_box(shape, o, d, max_t);
}

bool segment_hits(const Shape& shape, Vec2 a, Vec2 b) {
  // a segment whose box misses the shape's cannot touch it: the sensors' line-of-sight tests, most
  // of which pass far from the obstacles near them, skip the ray cast (the margin is far above the
  // ray cast's rounding, so no answer changes)
  constexpr double kMargin = 1e-6;  // [m]
  const Aabb seg{{std::min(a.x, b.x) - kMargin, std::min(a.y, b.y) - kMargin},
                 {std::max(a.x, b.x) + kMargin, std::max(a.y, b.y) + kMargin}};
  if (!seg.overlaps(shape.bounds)) return false;
  const Vec2 ab = b - a;
  const double len = norm(ab);
  if (len <= 0.0) return signed_distance(shape, a) <= 0.0;
  return ray_cast(shape, a, (1.0 / len) * ab, len) != kNoHit;
}

bool segment_hits_circle(Vec2 c, double r, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = norm2(ab);
  const double t = l2 > 0.0 ? std::clamp(dot(c - a, ab) / l2, 0.0, 1.0) : 0.0;
  return norm2(a + t * ab - c) <= r * r;
}

}  // namespace swarmpath::sim
