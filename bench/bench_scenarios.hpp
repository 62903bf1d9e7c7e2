// SPDX-License-Identifier: MIT
// Scenarios for the benchmarks: the paper's env4, with robots spread over the whole arena, and
// k x k tiled copies of it, so that robot density stays constant as the robot count grows.
#pragma once

#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace swarmpath::bench {

inline sim::Scenario env4() {
  return sim::load_scenario(std::string(SWARMPATH_SOURCE_DIR) + "/configs/scenarios/paper/env4.toml");
}

/// env4 with the deployment region grown to the whole arena interior.
inline sim::Scenario env4_spread(int robots) {
  sim::Scenario s = env4();
  s.deployment = {{0.0, 0.0}, s.arena_size - sim::Vec2{0.4, 0.4}};
  return sim::with_robots(s, robots, "bench");
}

/// k x k copies of env4 side by side (one wall between neighbours), `robots_per_tile` robots per
/// copy on average, deployed over the whole arena.
inline sim::Scenario env4_tiled(int k, int robots_per_tile = 100) {
  const sim::Scenario one = env4();
  sim::Scenario s = one;
  s.name = "env4x" + std::to_string(k * k);
  s.arena_size = {one.arena_size.x * k, one.arena_size.y * k};
  s.wall_thickness = 0.0;
  s.boxes.clear();
  s.cylinders.clear();
  for (int ty = 0; ty < k; ++ty) {
    for (int tx = 0; tx < k; ++tx) {
      const sim::Vec2 off{(tx - 0.5 * (k - 1)) * one.arena_size.x, (ty - 0.5 * (k - 1)) * one.arena_size.y};
      // neighbouring copies share a wall: each keeps its south and west walls, and only the
      // last row and column their north and east ones (back-to-back walls would double the
      // walls a robot near a tile edge senses and touches, a cost the paper's arena lacks)
      const std::vector<sim::BoxObstacle> walls = sim::boundary_walls(one);  // north, south, east, west
      for (std::size_t w = 0; w < walls.size(); ++w) {
        if ((w == 0 && ty < k - 1) || (w == 2 && tx < k - 1)) continue;
        s.boxes.push_back({walls[w].center + off, walls[w].size, walls[w].yaw});
      }
      for (const sim::BoxObstacle& b : one.boxes) s.boxes.push_back({b.center + off, b.size, b.yaw});
      for (const sim::CylinderObstacle& c : one.cylinders) s.cylinders.push_back({c.center + off, c.radius});
    }
  }
  const sim::Vec2 tile0{-0.5 * (k - 1) * one.arena_size.x, -0.5 * (k - 1) * one.arena_size.y};
  s.nest = one.nest + tile0;
  s.goal = one.goal + tile0;
  s.deployment = {{0.0, 0.0}, s.arena_size - sim::Vec2{0.4, 0.4}};
  s.sim.physics_regions_x = k;  // one Box2D world per copy: robots never cross the walls between
  s.sim.physics_regions_y = k;
  return sim::with_robots(s, robots_per_tile * k * k, "bench");
}

}  // namespace swarmpath::bench
