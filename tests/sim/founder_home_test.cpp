// SPDX-License-Identifier: MIT
// founder_retrace and founder_in_crowd [R] (docs/detours.md, What is left item 8): a goal founder that
// never reaches the nest allocates nobody. tests/data/corridor_9.toml (the training arena corridor-9:
// the nest inside a corridor closed to the east, its way out a channel at its west end), task
// allocation, seed 22, the first 8 000 ticks: without the rules the founder never starts its
// protocol and no link is laid.
#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Scenario corridor(std::int64_t robots) {
  return with_robots(with_max_ticks(load_scenario(test::source_path("tests/data/corridor_9.toml")), 8000),
                     robots);
}

// The default (the switch off) lays no link and forms no path; with the switch on the path forms.
// dm_rescout off, as measured: with it (the default) the decision makers that no founder reached
// scout again, a second founder allocates, and at 100 robots its chain reaches the nest by tick
// 7 925 without either switch.
void expect_only_the_switch_forms(bool Params::*key, std::int64_t robots) {
  Params off;
  off.dm_rescout = false;
  ASSERT_FALSE(off.*key);  // under trial, off in the default
  Params on = off;
  on.*key = true;
  const Metrics without = evaluate(off, corridor(robots), Mode::kTaskAllocation, 22);
  const Metrics with = evaluate(on, corridor(robots), Mode::kTaskAllocation, 22);
  EXPECT_EQ(without.chain.subgoals_laid, 0);
  EXPECT_FALSE(without.success);
  EXPECT_TRUE(with.success);
}

// 60 robots: the founder, home bound by the field, meets the corridor's outer wall 1.1 m from the
// nest; its trail home would begin at the nest behind that wall. With founder_retrace it goes back
// to where it left its way and in through the channel; the path forms (at tick 4 907)
TEST(FounderHome, AFounderBesideTheNestsWallGoesBackAlongItsWay) {
  expect_only_the_switch_forms(&Params::founder_retrace, 60);
}

// 100 robots: the founder comes in through the channel, but the decision makers waiting at the nest
// fill the corridor and hold it 1.3 m off, beyond R_nest_reach. With founder_in_crowd it asks from
// where it stands; the path forms (at tick 5 930)
TEST(FounderHome, AFounderHeldOffByTheCrowdAsksFromWhereItStands) {
  expect_only_the_switch_forms(&Params::founder_in_crowd, 100);
}

}  // namespace
}  // namespace swarmpath::sim
