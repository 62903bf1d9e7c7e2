// SPDX-License-Identifier: MIT
// What the simulator tests share: paths into the source tree and small inline scenarios.
#pragma once

#include <string>

#include "sim/controllers/trail.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::test {

inline std::string source_path(const std::string& relative) {
  return std::string(SWARMPATH_SOURCE_DIR) + "/" + relative;
}

inline std::string paper_env(int k) {
  return source_path("configs/scenarios/paper/env" + std::to_string(k) + ".toml");
}

/// A 6 m x 4 m open arena, nest at (-2, 0), goal at (2, 0); extra TOML appended.
inline std::string small_arena_toml(const std::string& extra = "", int robots = 10) {
  return "name = \"small\"\nclass = \"open\"\nnest = [-2.0, 0.0]\ngoal = [2.0, 0.0]\n\n"
         "[arena]\nsize = [6.0, 4.0]\n\n"
         "[deployment]\nsize = [1.0, 1.0]\nrobots = " +
         std::to_string(robots) + "\n" + extra;
}

/// Walks trail `t` from `from` to `to` in 1 cm steps.
inline void walk(sim::Trail& t, sim::Vec2 from, sim::Vec2 to) {
  const double len = dist(from, to);
  const int steps = static_cast<int>(len / 0.01);
  for (int k = 1; k <= steps; ++k) t.record(from + (static_cast<double>(k) / steps) * (to - from));
}

/// A trip from the nest at (-3, 0) down to a doorway at (0, -3) in a wall along x = 0, through it and
/// up to (3, 0), where the robot saw the chain at (3.5, 0.3); then on, exploring, to (3, 3).
inline sim::Trail trip_through_the_doorway() {
  sim::Trail t;
  t.reset({-3.0, 0.0});
  walk(t, {-3.0, 0.0}, {-0.5, -3.0});
  walk(t, {-0.5, -3.0}, {0.5, -3.0});
  walk(t, {0.5, -3.0}, {3.0, 0.0});
  walk(t, {3.0, 0.0}, {3.0, 3.0});
  return t;
}

/// The wall patience of the runs measured before `dead_end_traps = 20` (docs/detours.md, "Patience
/// along walls"): an edge following that made no progress turned back after 5 T_trap.
inline void hasty_along_walls(sim::Params& p) { p.dead_end_traps = 5; }

/// Path formation's links as measured before `anywhere_after_edge_pf` and `chain_bypass_pf` joined
/// the default (docs/detours.md, "The validation screen"): a forming robot stops within trail_slack
/// on any way it retraces, and a subgoal keeps its parent however near the parent's parent is.
inline void pf_links_by_trail_slack(sim::Params& p) {
  p.anywhere_after_edge_pf = false;
  p.chain_bypass_pf = false;
}

/// Task allocation's spot as measured before `spot_on_way` and `way_after_edge` joined the default
/// (docs/detours.md, "Rule B"): a forming robot backs off to the straight-line spot (a crumb of its
/// way near it, else the point toward the nest), whatever way it came.
inline void ta_spot_straight(sim::Params& p) {
  p.spot_on_way = false;
  p.way_after_edge = false;
}

/// The far_door runs of the rules for robots trapped on their way (route_to_sighting, spot_on_way) as
/// they were measured: hasty along walls, row #5r by the distance to the nest alone (with retarget_tip
/// far_door forms those seeds without either rule), every trip under the full away field and from
/// the nest, links laid by trail_slack alone.
inline void far_door_as_measured(sim::Params& p) {
  hasty_along_walls(p);
  p.retarget_tip = false;
  p.away_decay = 1.0;
  p.resume_search = false;
  pf_links_by_trail_slack(p);
}

inline sim::Scenario small_arena(const std::string& extra = "", int robots = 10) {
  return sim::parse_scenario(small_arena_toml(extra, robots), "small.toml");
}

}  // namespace swarmpath::test
