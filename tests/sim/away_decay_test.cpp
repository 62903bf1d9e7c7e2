// SPDX-License-Identifier: MIT
// away_decay [R] (docs/detours.md, row 18 and row #4): an explorer's away-from-nest weight is
// multiplied by away_decay each time one of its trips ends back home without a sighting of the goal
// or the chain, so that a robot that has searched in vain leans more on its random walk.
#include <algorithm>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

// w_away times away_decay once per fruitless trip, in the order the controller multiplies them
double expected_weight(const Params& p, int fruitless_trips) {
  double w = p.w_away;
  for (int k = 0; k < fruitless_trips; ++k) w *= p.away_decay;
  return w;
}

struct Weights {
  int most_trips = 0;  ///< the most fruitless trips any robot made
  int mismatches = 0;  ///< robot-ticks whose weight was not w_away times away_decay per trip
  int weakened = 0;    ///< robot-ticks with a weight below w_away
};

// far_door (a wall with one doorway far off the line), 50 robots, path formation, seed 1, 8 000 ticks:
// long enough for robots to come home from several trips that saw nothing
Weights watch_weights(const Params& p) {
  const Scenario s = load_scenario(test::source_path("tests/data/far_door.toml"));
  Weights out;
  run(
      p, s, Mode::kPathFormation, 1,
      [&](const World& w) {
        for (const RobotMemory& m : w.memory) {
          out.most_trips = std::max(out.most_trips, m.pf.fruitless_trips);
          if (m.pf.w_away != expected_weight(p, m.pf.fruitless_trips)) ++out.mismatches;
          if (m.pf.w_away < p.w_away) ++out.weakened;
        }
        return w.tick >= 8000;
      },
      nullptr);
  return out;
}

TEST(AwayDecay, EachTripHomeWithoutASightingWeakensTheAwayFieldByItsFactor) {
  Params on;  // the default
  ASSERT_DOUBLE_EQ(on.away_decay, 0.7);
  const Weights with = watch_weights(on);
  EXPECT_GE(with.most_trips, 2);  // the assertion below bites: robots came home empty twice or more
  EXPECT_EQ(with.mismatches, 0);
  EXPECT_GT(with.weakened, 0);
  Params off = on;
  off.away_decay = 1.0;  // as SPEC: w_away on every trip
  const Weights without = watch_weights(off);
  EXPECT_GE(without.most_trips, 1);
  EXPECT_EQ(without.mismatches, 0);
  EXPECT_EQ(without.weakened, 0);
}

// tests/data/wallfar_13.toml (the training arena wall-gap-13: a wall across the arena, its one
// doorway far off the nest-goal line), 60 robots, seed 21, task allocation: with every trip pressed
// by the full away field the path does not form within T_max; with away_decay it forms (the screen's
// case, docs/detours.md). The chain of runs differs from the scouts' first fruitless trips on.
TEST(AwayDecay, AWallWithAFarDoorwayFormsWhenSearchersLeanLessOnTheAwayField) {
  Params on;                    // the default
  test::hasty_along_walls(on);  // as measured
  on.resume_search = false;     // as measured: every trip explores from the nest (with it both form)
  Params off = on;
  off.away_decay = 1.0;
  const Scenario s = load_scenario(test::source_path("tests/data/wallfar_13.toml"));
  const Metrics without = evaluate(off, s, Mode::kTaskAllocation, 21);
  const Metrics with = evaluate(on, s, Mode::kTaskAllocation, 21);
  EXPECT_FALSE(without.success);
  EXPECT_TRUE(with.success);
}

}  // namespace
}  // namespace swarmpath::sim
