// SPDX-License-Identifier: MIT
// The speed workloads swarmpath is compared with ARGoS on: diffusion at 1 robot/m^2 in a walled
// square (100 and 1 000 robots), and whole path-formation and task-allocation runs (env4, 100
// robots, seed 3, to path completion). ARGoS's figures were measured with ARGoS 3 on the same
// kind of machine (one thread, 10 ticks/s, foot-bots); ARGoS takes 10 physics sub-steps a tick,
// swarmpath one Box2D step, which every ratio quoted against them has to say.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bench_scenarios.hpp"
#include "sim/controller.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"
#include "sim/step.hpp"

namespace swarmpath::bench {

/// ARGoS 3's robot-ticks per second on one core: diffusion with 100 and 1 000 foot-bots at
/// 1 robot/m^2, and the paper's controller with camera, range-and-bearing and proximity sensors.
inline constexpr double kArgosDiffusion100 = 49191.0;
inline constexpr double kArgosDiffusion1000 = 45589.0;
inline constexpr double kArgosPaperController = 23867.0;
/// What ARGoS does per tick that swarmpath does not: 10 physics sub-steps (swarmpath: one).
inline constexpr int kArgosPhysicsSubsteps = 10;

/// A walled square arena of side `side` metres with `robots` diffusing robots spread over its
/// whole interior (the boundary walls are 0.10 m thick, inside the edge).
inline sim::Scenario walled_square(double side, int robots) {
  sim::Scenario s;
  s.name = "square" + std::to_string(static_cast<int>(side)) + "m";
  s.file = "<bench>";
  s.arena_size = {side, side};
  s.wall_thickness = 0.1;
  s.nest = {-0.25 * side, 0.0};
  s.goal = {0.25 * side, 0.0};
  s.deployment = {{0.0, 0.0}, s.arena_size - sim::Vec2{0.4, 0.4}};
  return sim::with_robots(s, robots, "bench");
}

/// One workload: a scenario, a mode and a seed, run from deployment to `ticks` ticks (diffusion)
/// or to path completion (path formation, task allocation).
struct Workload {
  std::string name;
  std::string what;
  sim::Scenario scenario;
  sim::Mode mode = sim::Mode::kDiffusion;
  std::uint64_t seed = 1;
  double argos_robot_ticks_per_s = 0.0;  ///< ARGoS 3 on one core
  double target_seconds = 0.0;           ///< the whole run's CPU time to reach (0: see target_rate)
  double target_rate = 0.0;              ///< robot-ticks per second to reach (0: see target_seconds)
};

inline std::vector<Workload> workloads() {
  // both 5 000 ticks: robots deployed uniformly drift into contact with the walls and each other
  // over the first ~1 000 ticks (bench/growth.cpp), so equal lengths keep the growth honest
  sim::Scenario d100 = sim::with_max_ticks(walled_square(11.0, 100), 5000, "bench");
  sim::Scenario d1000 = sim::with_max_ticks(walled_square(33.0, 1000), 5000, "bench");
  const sim::Scenario e4 = env4();
  return {
      {"diffusion100", "diffusion, 100 robots at 1 robot/m^2 (11 x 11 m walled square), 5 000 ticks", d100,
       sim::Mode::kDiffusion, 1, kArgosDiffusion100, 0.0, 100.0 * kArgosDiffusion100},
      {"diffusion1000", "diffusion, 1 000 robots at 1 robot/m^2 (33 x 33 m walled square), 5 000 ticks",
       d1000, sim::Mode::kDiffusion, 1, kArgosDiffusion1000, 0.0, 100.0 * kArgosDiffusion1000},
      {"pf_env4", "whole path-formation run, env4, 100 robots, seed 3, to path completion", e4,
       sim::Mode::kPathFormation, 3, kArgosPaperController, 0.40, 0.0},
      {"ta_env4", "whole task-allocation run, env4, 100 robots, seed 3, to path completion", e4,
       sim::Mode::kTaskAllocation, 3, kArgosPaperController, 0.50, 0.0},
  };
}

/// The workload's whole run: make_world, every tick, finish (the default params). `rab_by_kind`
/// false: the same run with every message handed to every robot that listens (World::rab_by_kind),
/// as the medium did before it sorted messages by kind; the results are the same.
inline sim::Metrics run_workload(const Workload& w, bool rab_by_kind = true) {
  const sim::Params p;
  if (rab_by_kind) return sim::evaluate(p, w.scenario, w.mode, w.seed);
  sim::World world = sim::make_world(w.scenario, p, w.mode, w.seed);
  world.rab_by_kind = false;
  sim::MetricsAccumulator m;  // sim::run's loop
  m.begin(world.robot_count());
  while (world.tick < w.scenario.sim.max_ticks) {
    sim::step(w.scenario, p, world, m);
    if (w.scenario.sim.stop_when_complete && m.complete()) break;
  }
  return m.finish(world.tick, w.scenario.sim.dt(), sim::state_hash(world));
}

}  // namespace swarmpath::bench
