// SPDX-License-Identifier: MIT
// dead_end_traps 20 [R] (docs/detours.md, "Patience along walls"): an edge following turns back only
// when T_follow runs out, not after 5 T_trap without progress. tests/data/wallfar_11.toml (the
// training arena wall-gap-11: one long wall, its doorway 8 m off the nest-goal line, at the
// nest's latitude), 60 robots, path formation: explorers pushed away from the nest meet the wall
// where it lies farthest from the nest, and its doorway lies where following the wall loses ground.
#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

// Seeds 21, 23 and 24 form their path with dead_end_traps 20 (the default) and not with 5, the default
// until 2026-11-29, both with path formation's links as they were then (with anywhere_after_edge_pf
// and chain_bypass_pf, in the default since 2026-11-30, none of the three forms).
TEST(WallPatience, ARoomBehindAFarDoorwayIsReachedOnlyWithPatienceAlongItsWall) {
  Params patient;
  ASSERT_EQ(patient.dead_end_traps, 20);
  test::pf_links_by_trail_slack(patient);  // as measured
  Params hasty = patient;
  hasty.dead_end_traps = 5;
  const Scenario s = load_scenario(test::source_path("tests/data/wallfar_11.toml"));
  for (const std::uint64_t seed : {21, 23, 24}) {
    EXPECT_FALSE(evaluate(hasty, s, Mode::kPathFormation, seed).success) << seed;
    EXPECT_TRUE(evaluate(patient, s, Mode::kPathFormation, seed).success) << seed;
  }
}

}  // namespace
}  // namespace swarmpath::sim
