// SPDX-License-Identifier: MIT
// u-trap: a U of three walls on the nest-goal line. Opening toward the nest, it is a trap in the
// way: the goal sits behind its base and a swarm that heads straight for the goal drives into
// the U. Opening away from the nest, the goal sits inside it and the way in is from the far side.
#include <cmath>

#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"width_min", 3.0, 1.2, 8.0, false, "m", "narrowest inside width of the U"},
    {"width_max", 5.0, 1.2, 8.0, false, "m", "widest inside width of the U"},
    {"depth_min", 2.5, 1.0, 6.0, false, "m", "shallowest U (length of its arms)"},
    {"depth_max", 4.0, 1.0, 6.0, false, "m", "deepest U"},
    {"thickness", 0.2, 0.1, 0.5, false, "m", "wall thickness"},
    {"toward_nest", 0.5, 0.0, 1.0, false, "",
     "probability that the U opens toward the nest (a trap in the way; else the goal sits inside it)"},
    {"tilt_max", 20.0, 0.0, 90.0, false, "deg", "largest turn of the U's axis away from the nest-goal line"},
    {"distance_min", 10.0, 5.0, 28.0, false, "m", "shortest nest-goal distance"},
    {"distance_max", 16.0, 5.0, 28.0, false, "m", "longest nest-goal distance"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  if (!draw_nest_goal(rng, d.arena_size, p("distance_min"), p("distance_max"), d.nest, d.goal)) return false;
  d.deployment = square_at(d.nest, kDeploySide);
  const double w = mm(rng.uniform(p("width_min"), p("width_max")));
  const double depth = mm(rng.uniform(p("depth_min"), p("depth_max")));
  const double t = p("thickness");
  const bool toward = rng.bernoulli(p("toward_nest"));
  const double tilt = rng.uniform(-p("tilt_max"), p("tilt_max"));
  // the U's axis in 0.1 degree steps (the file stores degrees), e1 from the nest's side to the goal's
  const double deg = std::round((rad2deg(angle_of(d.goal - d.nest)) + tilt) * 10.0) / 10.0;
  const Vec2 e1 = unit(deg2rad(deg));
  const Vec2 e2{-e1.y, e1.x};
  // the base's centre; the arms run from it toward the nest (toward) or away from it
  const Vec2 base = toward ? d.goal - rng.uniform(0.8, 1.5) * e1 - 0.5 * t * e1
                           : d.goal - rng.uniform(0.3, 0.7) * depth * e1;
  const double arms = toward ? -1.0 : 1.0;
  const double side = 0.5 * w + 0.5 * t;
  const Vec2 tip_l = base + arms * depth * e1 + side * e2;
  const Vec2 tip_r = base + arms * depth * e1 - side * e2;
  add_wall(d, base - (side + 0.5 * t) * e2, base + (side + 0.5 * t) * e2, t);
  add_wall(d, base + side * e2, tip_l, t);
  add_wall(d, base - side * e2, tip_r, t);
  // room to walk around the U on every side
  const Aabb room = shrink(interior(d.arena_size), 0.8);
  for (const Vec2 c : {base + (side + t) * e2, base - (side + t) * e2, tip_l, tip_r}) {
    if (!room.contains(c)) return false;
  }
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "width_min", "width_max", key);
  if (e.empty()) e = ordered(p, "depth_min", "depth_max", key);
  return e.empty() ? ordered(p, "distance_min", "distance_max", key) : e;
}

}  // namespace

const Family& u_trap_family() {
  static const Family f{"u-trap",
                        "a U on the nest-goal line, opening toward the nest (a trap) or away (goal inside)",
                        kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
