// SPDX-License-Identifier: MIT
// anywhere_after_edge [R] (on for task allocation; anywhere_after_edge_pf, on, for path formation;
// docs/detours.md, "The way back leads away from the nest"): a forming robot retracing a way that
// followed an obstacle's edge on this trip may stop as a subgoal anywhere on it, not only within
// trail_slack of its target's distance from the nest. tests/data/mixed_4.toml (the training arena
// mixed-4, 60 robots): the goal lies just across the corner of the nest's room, and the way between
// them runs through two doorways, the second one farther from the nest than the goal; without the
// switch the chain fans at the goal against the wall between it and the nest.
#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(AnywhereAfterEdge, AChainGrowsBackAlongAWayThatLeadsAwayFromTheNest) {
  const Params defaults;
  ASSERT_TRUE(defaults.anywhere_after_edge);
  ASSERT_TRUE(defaults.anywhere_after_edge_pf);
  const Scenario s = load_scenario(test::source_path("tests/data/mixed_4.toml"));
  // task allocation: the default forms, without the switch it does not
  Params ta_off = defaults;
  ta_off.anywhere_after_edge = false;
  EXPECT_TRUE(evaluate(defaults, s, Mode::kTaskAllocation, 21).success);
  EXPECT_FALSE(evaluate(ta_off, s, Mode::kTaskAllocation, 21).success);
  // path formation: its own switch, on in the default too
  Params pf_off = defaults;
  pf_off.anywhere_after_edge_pf = false;
  EXPECT_TRUE(evaluate(defaults, s, Mode::kPathFormation, 21).success);
  EXPECT_FALSE(evaluate(pf_off, s, Mode::kPathFormation, 21).success);
}

}  // namespace
}  // namespace swarmpath::sim
