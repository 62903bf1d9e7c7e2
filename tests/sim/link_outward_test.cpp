// SPDX-License-Identifier: MIT
// link_outward_pf [R] (rows #5, #6b, path formation; off, under trial; docs/detours.md, "Path
// formation's chain along the way the robots came: link_outward_pf"): a forming robot retracing its
// own way from the nest may stop as a subgoal wherever its target is the nearest chain light in view,
// however far from the nest.
// tests/data/mixed_4.toml (the training arena mixed-4, 60 robots): the way between goal and nest runs
// through a doorway farther from the nest than the goal, and path formation's chain fans at the goal
// against the wall between them without the switch.
#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(LinkOutward, PathFormationsChainGrowsBackAlongTheWayTheRobotsCame) {
  Params off;
  ASSERT_FALSE(off.link_outward_pf);
  test::pf_links_by_trail_slack(off);  // as measured: anywhere_after_edge_pf forms this run too
  Params on = off;
  on.link_outward_pf = true;
  // seed 21 forms at tick 20 209 with the switch; without it not in 36 000 (the training screen)
  const Scenario s = with_max_ticks(load_scenario(test::source_path("tests/data/mixed_4.toml")), 21000);
  EXPECT_TRUE(evaluate(on, s, Mode::kPathFormation, 21).success);
  EXPECT_FALSE(evaluate(off, s, Mode::kPathFormation, 21).success);
}

}  // namespace
}  // namespace swarmpath::sim
