// SPDX-License-Identifier: MIT
#include "scenario_identity.hpp"

#include "hash.hpp"

namespace swarmpath::sim {

namespace {

void add(Fnv1a& h, Vec2 v) {
  h.add(v.x);
  h.add(v.y);
}

}  // namespace

std::uint64_t arena_fingerprint(const Scenario& s) {
  Fnv1a h;
  h.add(static_cast<int>(s.env_class));
  add(h, s.arena_size);
  h.add(s.wall_thickness);
  h.add(static_cast<std::int64_t>(s.boxes.size()));
  for (const BoxObstacle& b : s.boxes) {
    add(h, b.center);
    add(h, b.size);
    h.add(b.yaw);
  }
  h.add(static_cast<std::int64_t>(s.cylinders.size()));
  for (const CylinderObstacle& c : s.cylinders) {
    add(h, c.center);
    h.add(c.radius);
  }
  add(h, s.nest);
  add(h, s.goal);
  add(h, s.deployment.center);
  add(h, s.deployment.size);
  h.add(s.min_spacing);
  return h.value();
}

std::uint64_t experiment_fingerprint(const Scenario& s) {
  Fnv1a h;
  h.add(arena_fingerprint(s));
  h.add(s.robots);
  h.add(s.sim.ticks_per_second);
  h.add(s.sim.max_ticks);
  h.add(s.sim.velocity_iterations);
  h.add(s.sim.position_iterations);
  h.add(static_cast<int>(s.sim.occlude_by_robots));
  h.add(static_cast<int>(s.sim.stop_when_complete));
  h.add(s.sim.grid_cell);
  h.add(s.sim.physics_regions_x);
  h.add(s.sim.physics_regions_y);
  return h.value();
}

}  // namespace swarmpath::sim
