// SPDX-License-Identifier: MIT
// How the cost per robot-tick grows from 100 to 10,000 robots (the target: < 1.5x), measured
// so that a shared machine's slow and fast minutes cancel: two diffusion worlds, 100 robots (env4)
// and k x k tiles of env4 (100 robots a tile), both past their start-up transient, are stepped in
// K triples of adjacent stretches: 100 robots, the tiles, 100 robots again. Each triple gives one
// ratio, the tiles' cost over the mean of its two neighbours. Prints every triple and the median
// ratio with its quartiles.
//
//   build/release/bench/growth [TRIPLES=15] [TILES=10]
//
// (Google Benchmark's interleaved repetitions in sim_bench run each size in its own 15-20 ms
// slot; on a host whose speed drifts by 30 % from one minute to the next, the ratio of two
// medians taken minutes apart moved between 1.3 and 1.7 for the same build.)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench_scenarios.hpp"
#include "sim/params.hpp"
#include "sim/step.hpp"

namespace {

using namespace swarmpath;

// Robots deployed uniformly over the arena drift into contact with walls and each other: the
// 10 000-robot world's Box2D contacts grow from 32 to 81 a tile over its first 1 000 ticks, and
// its cost per robot-tick with them (490 -> 740 ns). Both worlds are timed after this many ticks.
constexpr int kWarmupTicks = 2000;

// One diffusion world, stepped on between measurements.
struct Run {
  sim::Scenario scenario;
  sim::Params params;
  sim::World world;
  sim::MetricsAccumulator metrics;

  explicit Run(const sim::Scenario& s)
      : scenario(s), world(sim::make_world(s, params, sim::Mode::kDiffusion, 1)) {
    metrics.begin(world.robot_count());
  }

  void advance(int ticks) {
    for (int t = 0; t < ticks; ++t) sim::step(scenario, params, world, metrics);
  }

  // nanoseconds per robot-tick of the next `ticks` ticks
  double time(int ticks) {
    const auto start = std::chrono::steady_clock::now();
    advance(ticks);
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(stop - start).count() /
           (static_cast<double>(ticks) * world.robot_count());
  }
};

// The q-quantile (0..1) of v, nearest rank.
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[k];
}

}  // namespace

int main(int argc, char** argv) {
  const int triples = argc > 1 ? std::atoi(argv[1]) : 15;
  const int tiles = argc > 2 ? std::atoi(argv[2]) : 10;
  if (argc > 3 || triples < 1 || tiles < 2) {
    std::fprintf(stderr, "usage: growth [TRIPLES >= 1, default 15] [TILES >= 2, default 10]\n");
    return 2;
  }
  Run small(bench::env4_tiled(1));
  Run large(bench::env4_tiled(tiles));
  small.advance(kWarmupTicks);
  large.advance(kWarmupTicks);
  // about 0.2 s a run at ~400 ns a robot-tick, 0.5 s for the tiled world
  const int small_ticks = 5000;
  const int large_ticks = std::max(10, 1000000 / (100 * tiles * tiles));
  std::vector<double> ratios;
  std::vector<double> smalls;
  std::vector<double> larges;
  std::printf("triple  100 robots [ns]  %d robots [ns]  ratio\n", 100 * tiles * tiles);
  for (int k = 0; k < triples; ++k) {
    const double before = small.time(small_ticks);
    const double big = large.time(large_ticks);
    const double after = small.time(small_ticks);
    const double base = 0.5 * (before + after);
    ratios.push_back(big / base);
    smalls.push_back(base);
    larges.push_back(big);
    std::printf("%6d  %15.1f  %14.1f  %5.3f\n", k + 1, base, big, big / base);
    std::fflush(stdout);
  }
  std::printf(
      "median: 100 robots %.1f ns, %d robots %.1f ns a robot-tick; growth %.3fx (quartiles %.3f-%.3f)\n",
      quantile(smalls, 0.5), 100 * tiles * tiles, quantile(larges, 0.5), quantile(ratios, 0.5),
      quantile(ratios, 0.25), quantile(ratios, 0.75));
  return 0;
}
