// SPDX-License-Identifier: MIT
#include "draw_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmpath::sim::arenas {

double mm(double v) { return std::round(v * 1000.0) / 1000.0; }

Vec2 mm(Vec2 v) { return {mm(v.x), mm(v.y)}; }

double draw_yaw(Rng& rng) { return deg2rad(static_cast<double>(rng.below(1800)) / 10.0); }

Aabb interior(Vec2 arena_size) {
  const Vec2 h = 0.5 * arena_size - Vec2{kBoundary, kBoundary};
  return {-1.0 * h, h};
}

Aabb shrink(const Aabb& a, double m) { return {a.lo + Vec2{m, m}, a.hi - Vec2{m, m}}; }

bool empty(const Aabb& a) { return a.lo.x > a.hi.x || a.lo.y > a.hi.y; }

Vec2 uniform_in(Rng& rng, const Aabb& a) {
  return {rng.uniform(a.lo.x, a.hi.x), rng.uniform(a.lo.y, a.hi.y)};
}

bool contains(const Aabb& outer, const Aabb& inner) {
  return inner.lo.x >= outer.lo.x && inner.lo.y >= outer.lo.y && inner.hi.x <= outer.hi.x &&
         inner.hi.y <= outer.hi.y;
}

RectRegion square_at(Vec2 c, double side) { return {c, {side, side}}; }

void add_wall(Draft& d, Vec2 a, Vec2 b, double t) {
  const Vec2 c = mm(0.5 * (a + b));
  const double len = mm(dist(a, b));
  if (a.x == b.x) {
    d.boxes.push_back({c, {t, len}, 0.0});
  } else if (a.y == b.y) {
    d.boxes.push_back({c, {len, t}, 0.0});
  } else {
    // an oblique wall: yaw rounded to 0.1 degree (the file stores degrees)
    const double deg = std::round(rad2deg(std::atan2(b.y - a.y, b.x - a.x)) * 10.0) / 10.0;
    d.boxes.push_back({c, {len, t}, deg2rad(deg)});
  }
}

std::vector<Shape> draft_shapes(const Draft& d) {
  std::vector<Shape> out;
  out.reserve(d.boxes.size() + d.cylinders.size());
  for (const BoxObstacle& b : d.boxes) out.push_back(Shape::box(b.center, b.size, b.yaw));
  for (const CylinderObstacle& c : d.cylinders) out.push_back(Shape::circle(c.center, c.radius));
  return out;
}

double obstacle_clearance(const Draft& d, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Shape& s : draft_shapes(d)) best = std::min(best, signed_distance(s, p));
  return best;
}

Aabb nest_region(Vec2 arena_size) { return shrink(interior(arena_size), 0.5 * kDeploySide + kDeployMargin); }

bool draw_nest_goal(Rng& rng, Vec2 arena_size, double dmin, double dmax, Vec2& nest, Vec2& goal) {
  const Aabb nests = nest_region(arena_size);
  const Aabb goals = shrink(interior(arena_size), kGoalMargin);
  if (empty(nests) || empty(goals)) return false;
  for (int k = 0; k < 64; ++k) {
    const Vec2 n = mm(uniform_in(rng, nests));
    const double r = rng.uniform(dmin, dmax);
    const double a = rng.uniform(-kPi, kPi);
    const Vec2 g = mm(n + r * Vec2{std::cos(a), std::sin(a)});
    const Aabb keep_out = {n - Vec2{1.0, 1.0} * (0.5 * kDeploySide + kGoalMargin),
                           n + Vec2{1.0, 1.0} * (0.5 * kDeploySide + kGoalMargin)};
    if (!goals.contains(g) || keep_out.contains(g)) continue;
    nest = n;
    goal = g;
    return true;
  }
  return false;
}

std::pair<double, double> draw_west_to_east(Rng& rng, Draft& d, double band) {
  const Aabb in = interior(d.arena_size);
  const Aabb nests = nest_region(d.arena_size);
  d.nest = mm(Vec2{rng.uniform(nests.lo.x, std::min(nests.hi.x, nests.lo.x + band)),
                   rng.uniform(nests.lo.y, nests.hi.y)});
  d.goal = mm(Vec2{rng.uniform(in.hi.x - 2.5, in.hi.x - 0.6), rng.uniform(in.lo.y + 0.6, in.hi.y - 0.6)});
  d.deployment = square_at(d.nest, kDeploySide);
  return {d.nest.x + 0.5 * kDeploySide + 0.8, d.goal.x - 0.8};
}

void scatter_clutter(Draft& d, Rng& rng, const ClutterSpec& spec) {
  const Aabb in = interior(d.arena_size);
  const double target = spec.coverage * (in.hi.x - in.lo.x) * (in.hi.y - in.lo.y);
  const Aabb dep = d.deployment.bounds();
  std::vector<Shape> shapes = draft_shapes(d);
  double covered = 0.0;
  int misses = 0;
  int placed = 0;
  while (covered < target && misses < 400 && (spec.max_count == 0 || placed < spec.max_count)) {
    const bool box = rng.bernoulli(spec.box_fraction);
    double reach = 0.0, area = 0.0;
    Vec2 size;
    double radius = 0.0;
    if (box) {
      size = mm(Vec2{rng.uniform(2.0 * spec.r_min, 2.0 * spec.r_max),
                     rng.uniform(2.0 * spec.r_min, 2.0 * spec.r_max)});
      reach = 0.5 * norm(size);
      area = size.x * size.y;
    } else {
      radius = mm(rng.uniform(spec.r_min, spec.r_max));
      reach = radius;
      area = kPi * radius * radius;
    }
    const double yaw = box ? draw_yaw(rng) : 0.0;
    const Aabb centres = shrink(in, reach + spec.gap);
    if (empty(centres)) {
      ++misses;
      continue;
    }
    const Vec2 c = mm(uniform_in(rng, centres));
    bool ok = dist(c, d.goal) >= reach + spec.gap + kGoalMargin;
    // the deployment region grown by the gap and the obstacle's reach
    ok = ok && !(c.x > dep.lo.x - reach - spec.gap && c.x < dep.hi.x + reach + spec.gap &&
                 c.y > dep.lo.y - reach - spec.gap && c.y < dep.hi.y + reach + spec.gap);
    for (std::size_t i = 0; ok && i < shapes.size(); ++i)
      ok = signed_distance(shapes[i], c) >= reach + spec.gap;
    if (!ok) {
      ++misses;
      continue;
    }
    misses = 0;
    ++placed;
    covered += area;
    if (box) {
      d.boxes.push_back({c, size, yaw});
      shapes.push_back(Shape::box(c, size, yaw));
    } else {
      d.cylinders.push_back({c, radius});
      shapes.push_back(Shape::circle(c, radius));
    }
  }
}

}  // namespace swarmpath::sim::arenas
