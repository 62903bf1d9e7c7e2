// SPDX-License-Identifier: MIT
// corridor: a long narrow passage, straight or with one right-angle bend, the goal beyond its far
// end. The nest either sits inside it at a dead end (the robots deploy along the corridor) or
// outside, off to one side of its entrance.
#include <algorithm>

#include "draw_support.hpp"
#include "family_list.hpp"
#include "sim/robot_model.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"width_min", 1.5, 0.8, 4.0, false, "m", "narrowest corridor (inside width)"},
    {"width_max", 2.5, 0.8, 4.0, false, "m", "widest corridor"},
    {"length_min", 8.0, 4.0, 20.0, false, "m", "shortest corridor (along its centre line)"},
    {"length_max", 14.0, 4.0, 20.0, false, "m", "longest corridor (a straight one must fit the arena)"},
    {"thickness", 0.2, 0.1, 0.5, false, "m", "wall thickness"},
    {"nest_inside", 0.5, 0.0, 1.0, false, "", "probability that the nest sits inside the corridor, at a dead end"},
    {"bend", 0.5, 0.0, 1.0, false, "", "probability of one right-angle bend"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  const Aabb in = interior(d.arena_size);
  const double w = mm(rng.uniform(p("width_min"), p("width_max")));
  const double length = rng.uniform(p("length_min"), p("length_max"));
  const double t = p("thickness");
  const bool bent = rng.bernoulli(p("bend"));
  const bool inside = rng.bernoulli(p("nest_inside"));
  // inside, the deployment strip must hold the robots (the loader's capacity rule, with 15 % spare)
  const double free_width = w - 0.04 - 2.0 * kRobotRadius;
  const double per_robot = kPi * 0.01 / 0.45;  // min_spacing 0.2 m, 45 % packing
  const double strip = inside ? p("robots") * per_robot * 1.15 / free_width + 2.0 * kRobotRadius + 0.04 : 0.0;
  const double first =
      mm(bent ? std::max(inside ? strip + 2.0 : 2.0, length * rng.uniform(0.5, 0.8)) : length);
  const double second = mm(bent ? length - first : 0.0);
  if (bent && second < 2.0) return false;
  if (inside && first < strip + 2.0) return false;

  double x0 = 0.0;  // the corridor's west end (centre line from (x0, yc))
  if (inside) {
    x0 = mm(in.lo.x + rng.uniform(0.4 + t, 2.0));
  } else {
    const Aabb nests = nest_region(d.arena_size);
    d.nest.x = mm(nests.lo.x + rng.uniform(0.0, 1.5));
    x0 = mm(d.nest.x + 0.5 * kDeploySide + rng.uniform(0.8, 2.0));
  }
  const double xc = x0 + first;  // where the centre line ends or turns north
  const double y_lo = in.lo.y + 1.0 + 0.5 * w + t;
  const double y_hi = in.hi.y - 1.0 - 0.5 * w - t - (bent ? second + 1.5 : 0.0);
  if (y_lo > y_hi) return false;
  const double yc = mm(rng.uniform(y_lo, y_hi));
  const double s = yc - 0.5 * w - 0.5 * t, n = yc + 0.5 * w + 0.5 * t;  // wall centre lines
  if (bent) {
    add_wall(d, {x0, s}, {xc + 0.5 * w + t, s}, t);  // south, outer
    add_wall(d, {xc + 0.5 * w + 0.5 * t, yc - 0.5 * w - t}, {xc + 0.5 * w + 0.5 * t, yc + second},
             t);                                 // east
    add_wall(d, {x0, n}, {xc - 0.5 * w, n}, t);  // north, inner
    add_wall(d, {xc - 0.5 * w - 0.5 * t, yc + 0.5 * w}, {xc - 0.5 * w - 0.5 * t, yc + second}, t);  // west
    d.goal = mm(Vec2{xc + rng.uniform(-2.0, 2.0), yc + second + rng.uniform(1.0, 2.5)});
  } else {
    add_wall(d, {x0, s}, {xc, s}, t);
    add_wall(d, {x0, n}, {xc, n}, t);
    d.goal = mm(Vec2{xc + rng.uniform(1.0, 2.5), yc + rng.uniform(-2.0, 2.0)});
  }
  if (inside) {
    add_wall(d, {x0 - 0.5 * t, yc - 0.5 * w - t}, {x0 - 0.5 * t, yc + 0.5 * w + t}, t);  // the dead end
    d.deployment = {mm(Vec2{x0 + 0.5 * strip, yc}), mm(Vec2{strip - 0.04, w - 0.04})};
    d.nest = d.deployment.center;
  } else {
    d.nest.y = mm(std::clamp(yc + rng.uniform(-2.5, 2.5), nest_region(d.arena_size).lo.y,
                             nest_region(d.arena_size).hi.y));
    d.deployment = square_at(d.nest, kDeploySide);
  }
  const Aabb walls = shrink(in, 0.3);
  for (const BoxObstacle& b : d.boxes) {
    const Aabb a{b.center - 0.5 * b.size, b.center + 0.5 * b.size};
    if (!contains(walls, a)) return false;
  }
  return shrink(in, kGoalMargin).contains(d.goal);
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "width_min", "width_max", key);
  return e.empty() ? ordered(p, "length_min", "length_max", key) : e;
}

}  // namespace

const Family& corridor_family() {
  static const Family f{"corridor",
                        "a long narrow passage (straight or with one bend), the nest inside it or off its "
                        "entrance, the goal beyond its far end",
                        kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
