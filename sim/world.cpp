// SPDX-License-Identifier: MIT
#include "world.hpp"

#include <algorithm>
#include <cmath>

#include "config_error.hpp"
#include "hash.hpp"
#include "robot_model.hpp"

namespace swarmpath::sim {

namespace {

// Box2D keeps bodies b2_polygonRadius (1 cm) off box faces: spawn at least that far away
constexpr double kSpawnClearance = kRobotRadius + 0.012;

Aabb grid_bounds(const Scenario& s) {
  const Aabb a = s.arena_bounds();
  return {a.lo - Vec2{1.0, 1.0}, a.hi + Vec2{1.0, 1.0}};
}

}  // namespace

std::vector<Pose> deploy(const Scenario& s, std::span<const Shape> shapes, std::uint64_t seed) {
  const Aabb region = s.deployment.bounds();
  const Aabb arena = s.arena_bounds();
  Rng rng(mix_seed(seed, 0x6465706c6f79ULL /* "deploy" */));

  // a bucket grid of side min_spacing over the region: a conflict can only come from 3x3 cells
  const double cell = s.min_spacing;
  const int nx = std::max(1, static_cast<int>(std::ceil(s.deployment.size.x / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil(s.deployment.size.y / cell)));
  std::vector<std::vector<int>> buckets(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  const auto bucket = [&](Vec2 p, int& i, int& j) {
    i = std::clamp(static_cast<int>(std::floor((p.x - region.lo.x) / cell)), 0, nx - 1);
    j = std::clamp(static_cast<int>(std::floor((p.y - region.lo.y) / cell)), 0, ny - 1);
  };

  const ShapeBins bins(shapes, grid_bounds(s), 0.5, kSpawnClearance);
  std::vector<Pose> poses;
  poses.reserve(static_cast<std::size_t>(s.robots));
  const std::int64_t max_trials = 2000LL * s.robots + 100000;
  std::int64_t trials = 0;
  const double spacing2 = s.min_spacing * s.min_spacing;
  while (static_cast<int>(poses.size()) < s.robots) {
    if (++trials > max_trials) {
      throw ConfigError(s.file, 0, "deployment",
                        "could only place " + std::to_string(poses.size()) + " of " +
                            std::to_string(s.robots) + " robots in the deployment region after " +
                            std::to_string(max_trials) + " attempts");
    }
    const Vec2 p{rng.uniform(region.lo.x, region.hi.x), rng.uniform(region.lo.y, region.hi.y)};
    const double yaw = rng.uniform(-kPi, kPi);
    // inside the arena and clear of every obstacle and wall
    if (p.x - kSpawnClearance < arena.lo.x || p.x + kSpawnClearance > arena.hi.x ||
        p.y - kSpawnClearance < arena.lo.y || p.y + kSpawnClearance > arena.hi.y) {
      continue;
    }
    bool clear = true;
    for (const int k : bins.near(p)) {
      if (signed_distance(shapes[static_cast<std::size_t>(k)], p) < kSpawnClearance) {
        clear = false;
        break;
      }
    }
    if (!clear) continue;
    // no other robot closer than min_spacing
    int bi, bj;
    bucket(p, bi, bj);
    for (int j = std::max(0, bj - 1); clear && j <= std::min(ny - 1, bj + 1); ++j) {
      for (int i = std::max(0, bi - 1); clear && i <= std::min(nx - 1, bi + 1); ++i) {
        for (const int other : buckets[static_cast<std::size_t>(j * nx + i)]) {
          if (norm2(poses[static_cast<std::size_t>(other)].p - p) < spacing2) {
            clear = false;
            break;
          }
        }
      }
    }
    if (!clear) continue;
    buckets[static_cast<std::size_t>(bj * nx + bi)].push_back(static_cast<int>(poses.size()));
    poses.push_back({p, std::cos(yaw), std::sin(yaw)});
  }
  // Number the robots along a Z-order (Morton) curve over 1 m cells, so that robots that start
  // close together have close ids: the Box2D bodies and sensor data of neighbours then sit close
  // in memory, which keeps large swarms cache-friendly. Ties keep the sampling order.
  const auto morton = [&](Vec2 p) {
    const auto cx = static_cast<std::uint32_t>(std::clamp((p.x - arena.lo.x), 0.0, 65535.0));
    const auto cy = static_cast<std::uint32_t>(std::clamp((p.y - arena.lo.y), 0.0, 65535.0));
    std::uint64_t key = 0;
    for (int b = 0; b < 16; ++b) {
      key |= static_cast<std::uint64_t>((cx >> b) & 1u) << (2 * b);
      key |= static_cast<std::uint64_t>((cy >> b) & 1u) << (2 * b + 1);
    }
    return key;
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> order(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) order[i] = {morton(poses[i].p), i};
  std::sort(order.begin(), order.end());
  std::vector<Pose> sorted(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) sorted[i] = poses[order[i].second];
  return sorted;
}

World make_world(const Scenario& s, const Params& p, Mode mode, std::uint64_t seed) {
  return make_world(s, p, mode, seed, deploy(s, obstacle_shapes(s), seed));
}

World make_world(const Scenario& s, const Params& p, Mode mode, std::uint64_t seed,
                 std::span<const Pose> start) {
  if (mode == Mode::kTaskAllocation && start.size() > static_cast<std::size_t>(kMaxTaRobots)) {
    throw ConfigError(s.file, 0, "deployment.robots",
                      "task allocation addresses robots with one byte (SPEC §2.6 framing): at most " +
                          std::to_string(kMaxTaRobots) + " robots, got " + std::to_string(start.size()));
  }
  World w;
  w.mode = mode;
  w.seed = seed;
  w.shapes = obstacle_shapes(s);
  PhysicsLayout layout;
  layout.bounds = s.arena_bounds();
  layout.nx = s.sim.physics_regions_x;
  layout.ny = s.sim.physics_regions_y;
  w.physics = std::make_unique<Physics>(w.shapes, layout);
  w.needs = sensor_needs(mode, p);
  const Aabb bounds = grid_bounds(s);
  const double cell = s.sim.grid_cell;
  w.touch_bins = ShapeBins(w.shapes, bounds, cell, kRobotRadius + kProximityRange);
  w.camera_bins = ShapeBins(w.shapes, bounds, cell, p.r_vis / 100.0);
  w.rab_bins = ShapeBins(w.shapes, bounds, cell, kRabRange);

  const auto n = start.size();
  w.poses.resize(n);
  w.positions.resize(n);
  w.leds.assign(n, initial_led(mode));
  w.tags.assign(n, kNobody);
  w.rab_sending.assign(n, 0);
  w.rab_out.assign(n, RabPayload{});
  w.rab_kinds.assign(n, 0);
  w.commands.assign(n, Command{});
  w.memory.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.physics->add_robot(start[i].p, start[i].yaw());
    w.memory.push_back(init_memory(mode, static_cast<int>(i), start[i], s.nest, p, seed));
    w.memory.back().env_class = static_cast<std::uint8_t>(s.env_class);
    w.memory.back().swarm = static_cast<int>(n);
  }
  // poses as Box2D stores them (single precision), so that tick 0 senses what physics holds
  w.physics->read_poses(w.poses);
  for (std::size_t i = 0; i < n; ++i) w.positions[i] = w.poses[i].p;
  w.faults = make_fault_state(s.faults, static_cast<int>(n), seed);
  // packet loss draws once per message a robot is handed: the medium hands it every message
  w.rab_by_kind = !(w.faults.model.packet_loss > 0);
  w.grid.reset(grid_bounds(s), s.sim.grid_cell, n);
  w.grid.build(w.positions);
  w.rab_cell_kinds.assign(w.grid.cells(), 0);  // nobody has sent yet
  w.rab_row_kinds.assign(w.grid.cells() / w.grid.columns(), 0);

  // step() senses one robot at a time (sense_all sizes the per-robot buffers when first called)
  if (w.needs.camera) w.blobs.reserve(64);
  if (w.needs.rab) w.rab_inbox.reserve(64);
  return w;
}

void fail_robot(World& w, int id) {
  const auto i = static_cast<std::size_t>(id);
  if (w.faults.failed[i] != 0) return;
  w.faults.failed[i] = 1;
  ++w.faults.failures;
  if (is_chain_light(w.leds[i])) ++w.faults.chain_failures;
  w.commands[i] = Command{};  // wheels at zero (braked), LEDs off, nothing sent
  w.leds[i] = Led::kBlack;
  w.tags[i] = kNobody;
  w.rab_sending[i] = 0;
  w.physics->set_wheels(id, 0.0, 0.0);
}

std::uint64_t state_hash(const World& w) {
  Fnv1a h;
  h.add(w.tick);
  h.add(w.robot_count());
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    h.add(w.poses[i].p.x);
    h.add(w.poses[i].p.y);
    h.add(w.poses[i].c);
    h.add(w.poses[i].s);
    h.add(static_cast<int>(w.memory[i].state));
    h.add(static_cast<int>(w.memory[i].turn));
    h.add(static_cast<int>(w.leds[i]));
  }
  return h.value();
}

}  // namespace swarmpath::sim
