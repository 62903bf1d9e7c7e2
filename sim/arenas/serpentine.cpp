// SPDX-License-Identifier: MIT
// serpentine: parallel walls attached alternately to the south and north boundary, each leaving a
// gap at its tip, so that the way from the nest (west) to the goal (east) zigzags, as in env8
// (SPEC §3.3: two walls, 4.4 m gaps, seven cylinders and two boxes of clutter).
#include <algorithm>

#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"walls", 2, 1, 6, true, "", "parallel walls, attached alternately to the south and north"},
    {"gap_min", 2.5, 1.0, 8.0, false, "m", "narrowest gap between a wall's tip and the far boundary"},
    {"gap_max", 4.5, 1.0, 8.0, false, "m", "widest gap"},
    {"thickness", 0.3, 0.1, 0.5, false, "m", "wall thickness"},
    {"clutter", 0, 0, 30, true, "", "cylinders and boxes scattered between the walls (env8 has 9)"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  const Aabb in = interior(d.arena_size);
  const double t = p("thickness");
  const int walls = p.integer("walls");
  const auto [x_lo, x_hi] = draw_west_to_east(rng, d, 1.5);
  const double spacing = (x_hi - x_lo) / walls;
  if (spacing < 1.2 + t) return false;
  bool south = rng.bernoulli(0.5);
  for (int i = 0; i < walls; ++i, south = !south) {
    const double x = mm(x_lo + spacing * (i + 0.5 + rng.uniform(-0.15, 0.15)));
    const double gap = mm(rng.uniform(p("gap_min"), p("gap_max")));
    if (south) {
      add_wall(d, {x, in.lo.y - 0.05}, {x, in.hi.y - gap}, t);
    } else {
      add_wall(d, {x, in.lo.y + gap}, {x, in.hi.y + 0.05}, t);
    }
  }
  if (p.integer("clutter") > 0) scatter_clutter(d, rng, {1.0, 0.3, 0.5, 0.2, 0.8, p.integer("clutter")});
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "gap_min", "gap_max", key);
  if (!e.empty()) return e;
  if (p("gap_max") > p("height") - 1.2) {
    key = "gap_max";
    return "a wall must stay at least 1 m long: the gap must be below the arena's height less 1.2 m "
           "(height " +
           toml_number(p("height")) + " m)";
  }
  return {};
}

}  // namespace

const Family& serpentine_family() {
  static const Family f{"serpentine",
                        "parallel walls attached alternately to south and north, forcing a zigzag (as env8)",
                        kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
