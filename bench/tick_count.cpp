// SPDX-License-Identifier: MIT
// Runs k x k tiles of env4 (100 robots per tile) for 300 warm-up ticks plus T ticks, for
// instruction counting under valgrind (scripts/instructions_per_robot_tick.sh): the difference
// between two T values divided by robots x ticks is the instruction cost of one robot-tick.
#include <cstdio>
#include <cstdlib>

#include "bench_scenarios.hpp"
#include "sim/step.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: tick_count TILES TICKS\n");
    return 2;
  }
  using namespace swarmpath;
  const sim::Scenario s = bench::env4_tiled(std::atoi(argv[1]));
  const sim::Params p;
  sim::World w = sim::make_world(s, p, sim::Mode::kDiffusion, 1);
  sim::MetricsAccumulator m;
  m.begin(w.robot_count());
  for (int t = 0; t < 300 + std::atoi(argv[2]); ++t) sim::step(s, p, w, m);
  std::printf("%d robots, state_hash %llx\n", w.robot_count(),
              static_cast<unsigned long long>(sim::state_hash(w)));
  return 0;
}
