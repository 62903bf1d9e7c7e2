// SPDX-License-Identifier: MIT
// anywhere_after_edge [R] (off by default; docs/detours.md, "The way back leads away from the
// nest"): a forming robot retracing a way that followed an obstacle's edge on this trip may stop as
// a subgoal anywhere on it, not only within trail_slack of its target's distance from the nest.
// tests/data/mixed_4.toml (the training arena mixed-4, 60 robots): the goal lies just across the
// corner of the nest's room, and the way between them runs through two doorways, the second one
// farther from the nest than the goal; without the switch the chain fans at the goal against the
// wall between it and the nest.
#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(AnywhereAfterEdge, AChainGrowsBackAlongAWayThatLeadsAwayFromTheNest) {
  Params off;
  ASSERT_FALSE(off.anywhere_after_edge);
  off.chain_bypass = false;  // as measured (with it the rule's task-allocation run at seed 23 fails)
  Params on = off;
  on.anywhere_after_edge = true;
  const Scenario s = load_scenario(test::source_path("tests/data/mixed_4.toml"));
  for (const Mode mode : {Mode::kPathFormation, Mode::kTaskAllocation}) {
    EXPECT_FALSE(evaluate(off, s, mode, 21).success) << static_cast<int>(mode);
    EXPECT_TRUE(evaluate(on, s, mode, 21).success) << static_cast<int>(mode);
  }
  EXPECT_FALSE(evaluate(off, s, Mode::kTaskAllocation, 23).success);
  EXPECT_TRUE(evaluate(on, s, Mode::kTaskAllocation, 23).success);
}

}  // namespace
}  // namespace swarmpath::sim
