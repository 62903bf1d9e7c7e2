// SPDX-License-Identifier: MIT
// Simulator throughput: robot-ticks per second of the diffusion controller in env4, and the cost
// per robot-tick as the swarm grows from 100 to 10,000 robots at constant density; whole
// path-formation and task-allocation runs.
//
//   build/release/bench/sim_bench --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true
//       --benchmark_report_aggregates_only=true   (one line)
//
// (interleaving the repetitions makes the 100 / 10,000-robot ratio robust to a shared machine's
// slow and fast minutes, which move the 10,000-robot figure most)
//
// items_per_second is robot-ticks per second; time_per_robot_tick is its inverse.
#include <benchmark/benchmark.h>

#include "bench_scenarios.hpp"
#include "sim/params.hpp"
#include "sim/step.hpp"

namespace swarmpath::bench {
namespace {

constexpr int kWarmupTicks = 300;

void run_ticks(benchmark::State& state, const sim::Scenario& s) {
  const sim::Params p;
  sim::World w = sim::make_world(s, p, sim::Mode::kDiffusion, 1);
  sim::MetricsAccumulator m;
  m.begin(w.robot_count());
  for (int t = 0; t < kWarmupTicks; ++t) sim::step(s, p, w, m);  // leave the start-up transient
  for (auto _ : state) sim::step(s, p, w, m);
  const double robot_ticks = static_cast<double>(state.iterations()) * w.robot_count();
  state.SetItemsProcessed(static_cast<std::int64_t>(robot_ticks));
  state.counters["robots"] = w.robot_count();
  // seconds per robot-tick, printed with an SI prefix (e.g. 310n = 310 ns)
  state.counters["time_per_robot_tick"] =
      benchmark::Counter(robot_ticks, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// env4 as the paper runs it: 100 robots starting in the 3 m square around the nest
void BM_Env4Nest(benchmark::State& state) {
  run_ticks(state, sim::with_robots(env4(), state.range(0), "bench"));
}

BENCHMARK(BM_Env4Nest)->Arg(100)->Iterations(3000)->Unit(benchmark::kMicrosecond);

// env4 with the robots spread over the whole arena (1,000 do not fit in the nest square)
void BM_Env4Spread(benchmark::State& state) {
  run_ticks(state, env4_spread(static_cast<int>(state.range(0))));
}

BENCHMARK(BM_Env4Spread)->Arg(100)->Arg(1000)->Iterations(2000)->Unit(benchmark::kMicrosecond);

// k x k tiles of env4, 100 robots per tile: constant density, 100 -> 10,000 robots; one Box2D
// world per tile (`simulation.physics_regions = [k, k]`)
void BM_Env4Tiled(benchmark::State& state) { run_ticks(state, env4_tiled(static_cast<int>(state.range(0)))); }

BENCHMARK(BM_Env4Tiled)->Arg(1)->Arg(3)->Arg(10)->Iterations(400)->Unit(benchmark::kMillisecond);

// the same tiles in a single Box2D world, for comparison
void BM_Env4TiledOneWorld(benchmark::State& state) {
  sim::Scenario s = env4_tiled(static_cast<int>(state.range(0)));
  s.sim.physics_regions_x = 1;
  s.sim.physics_regions_y = 1;
  run_ticks(state, s);
}

BENCHMARK(BM_Env4TiledOneWorld)->Arg(10)->Iterations(400)->Unit(benchmark::kMillisecond);

// one whole run per iteration, from deployment to path completion; items are robot-ticks
void run_to_completion(benchmark::State& state, const sim::Params& p, const sim::Scenario& s, sim::Mode mode,
                       std::uint64_t seed) {
  sim::Metrics m;
  for (auto _ : state) {
    m = sim::evaluate(p, s, mode, seed);
    benchmark::DoNotOptimize(m.state_hash);
  }
  const double robot_ticks =
      static_cast<double>(state.iterations()) * m.robots * static_cast<double>(m.ticks);
  state.SetItemsProcessed(static_cast<std::int64_t>(robot_ticks));
  state.counters["ticks_to_form"] = static_cast<double>(m.ticks_to_form);
  state.counters["success"] = m.success ? 1 : 0;
}

// path formation, 100 robots in env4, from deployment to path completion (seed 3), with the
// robots at state.range(0) cm/s: 10 = genomes/paper-v10.toml (SPEC's assumption), 20 = the default
void BM_PathFormationEnv4ToCompletion(benchmark::State& state) {
  const sim::Params p = state.range(0) == 10
                            ? sim::load_params(std::string(SWARMPATH_SOURCE_DIR) + "/genomes/paper-v10.toml")
                            : sim::Params{};
  run_to_completion(state, p, env4(), sim::Mode::kPathFormation, 3);
}

BENCHMARK(BM_PathFormationEnv4ToCompletion)
    ->Arg(10)
    ->Arg(20)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// task allocation, 100 robots in env4 with genomes/default.toml (the defaults), from deployment to
// path completion (seed 3): the crowd at the nest makes the range-and-bearing medium the load
void BM_TaskAllocationEnv4ToCompletion(benchmark::State& state) {
  run_to_completion(state, sim::Params{}, env4(), sim::Mode::kTaskAllocation, 3);
}

BENCHMARK(BM_TaskAllocationEnv4ToCompletion)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace swarmpath::bench

BENCHMARK_MAIN();
