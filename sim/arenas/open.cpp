// SPDX-License-Identifier: MIT
// open: no obstacles; the nest anywhere its deployment square fits, the goal at a distance drawn
// from a range in a uniform direction (the paper's env1-3 are 10.0-12.3 m apart).
#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"distance_min", 8.0, 2.5, 28.0, false, "m", "shortest nest-goal distance"},
    {"distance_max", 14.0, 2.5, 28.0, false, "m", "longest nest-goal distance"},
};

// clang-format on

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  if (!draw_nest_goal(rng, d.arena_size, p("distance_min"), p("distance_max"), d.nest, d.goal)) return false;
  d.deployment = square_at(d.nest, kDeploySide);
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  return ordered(p, "distance_min", "distance_max", key);
}

}  // namespace

const Family& open_family() {
  static const Family f{"open", "no obstacles; the nest-goal distance drawn from a range", kParams, draw,
                        check};
  return f;
}

}  // namespace swarmpath::sim::arenas
