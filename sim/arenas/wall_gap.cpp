// SPDX-License-Identifier: MIT
// wall-gap: one or more walls across the arena between the nest (west) and the goal (east), each
// with one doorway of a drawn width anywhere along it; offset_min keeps the doorways away from the
// straight nest-goal line (the detour a purely reactive controller finds hardest).
#include <algorithm>
#include <cmath>

#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"walls", 1, 1, 4, true, "", "walls across the arena, each with one doorway"},
    {"door_min", 1.0, 0.4, 5.0, false, "m", "narrowest doorway"},
    {"door_max", 2.0, 0.4, 5.0, false, "m", "widest doorway"},
    {"thickness", 0.2, 0.1, 0.5, false, "m", "wall thickness"},
    {"offset_min", 0.0, 0.0, 0.9, false, "",
     "a doorway's distance from the nest-goal line, at least this share of the farthest it could be"},
};

// clang-format on

// a doorway centre in [lo, hi], at least `away` from `line`; false when there is no room
bool draw_door(Rng& rng, double lo, double hi, double line, double away, double& y) {
  const double below = std::max(0.0, std::min(hi, line - away) - lo);  // [lo, line - away]
  const double above = std::max(0.0, hi - std::max(lo, line + away));  // [line + away, hi]
  if (below + above <= 0.0) return false;
  const double u = rng.uniform(0.0, below + above);
  y = u < below ? lo + u : std::max(lo, line + away) + (u - below);
  return true;
}

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  const Aabb in = interior(d.arena_size);
  const double t = p("thickness");
  const int walls = p.integer("walls");
  const auto [x_lo, x_hi] = draw_west_to_east(rng, d, 2.0);
  const double spacing = (x_hi - x_lo) / walls;
  if (spacing < 1.0 + t) return false;
  for (int i = 0; i < walls; ++i) {
    const double x = mm(x_lo + spacing * (i + 0.5 + rng.uniform(-0.25, 0.25)));
    const double w = mm(rng.uniform(p("door_min"), p("door_max")));
    const double line = d.nest.y + (d.goal.y - d.nest.y) * (x - d.nest.x) / (d.goal.x - d.nest.x);
    const double lo = in.lo.y + 0.5 * w, hi = in.hi.y - 0.5 * w;
    const double farthest = std::max(std::abs(lo - line), std::abs(hi - line));
    double y = 0.0;
    if (!draw_door(rng, lo, hi, line, p("offset_min") * farthest, y)) return false;
    y = mm(y);
    // the wall runs into the boundary walls so that no crack is left
    if (y - 0.5 * w > in.lo.y) add_wall(d, {x, in.lo.y - 0.05}, {x, y - 0.5 * w}, t);
    if (y + 0.5 * w < in.hi.y) add_wall(d, {x, y + 0.5 * w}, {x, in.hi.y + 0.05}, t);
  }
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "door_min", "door_max", key);
  if (!e.empty()) return e;
  if (p("door_max") > p("height") - 1.0) {
    key = "door_max";
    return "a doorway must be shorter than the arena's height less 1 m (height " + toml_number(p("height")) +
           " m)";
  }
  return {};
}

}  // namespace

const Family& wall_gap_family() {
  static const Family f{
      "wall-gap", "walls across the arena between nest and goal, each with one doorway anywhere along it",
      kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
