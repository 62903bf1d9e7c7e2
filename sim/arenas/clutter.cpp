// SPDX-License-Identifier: MIT
// clutter: cylinders and rotated boxes scattered at a density (the share of the floor they
// cover), each keeping a free gap around it so that no passage closes; nest and goal as in open.
#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"coverage", 0.08, 0.0, 0.25, false, "", "share of the floor the obstacles cover"},
    {"radius_min", 0.2, 0.1, 1.5, false, "m", "smallest cylinder radius (boxes: half the smallest side)"},
    {"radius_max", 0.6, 0.1, 1.5, false, "m", "largest cylinder radius (boxes: half the largest side)"},
    {"box_fraction", 0.4, 0.0, 1.0, false, "", "share of rotated boxes among the obstacles"},
    {"gap", 0.6, 0.3, 3.0, false, "m", "free gap kept around every obstacle"},
    {"distance_min", 10.0, 2.5, 28.0, false, "m", "shortest nest-goal distance"},
    {"distance_max", 16.0, 2.5, 28.0, false, "m", "longest nest-goal distance"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  if (!draw_nest_goal(rng, d.arena_size, p("distance_min"), p("distance_max"), d.nest, d.goal)) return false;
  d.deployment = square_at(d.nest, kDeploySide);
  scatter_clutter(d, rng, {p("coverage"), p("radius_min"), p("radius_max"), p("box_fraction"), p("gap"), 0});
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "radius_min", "radius_max", key);
  return e.empty() ? ordered(p, "distance_min", "distance_max", key) : e;
}

}  // namespace

const Family& clutter_family() {
  static const Family f{"clutter", "cylinders and rotated boxes at a density, each with a free gap around it",
                        kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
