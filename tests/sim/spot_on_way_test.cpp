// SPDX-License-Identifier: MIT
// spot_on_way [R] (docs/detours.md, rows #5, #6b): a forming robot backing off to its spot takes the
// point where its own way from the nest first came within d_sub + 5 cm of its target, not a point
// nearer the nest in a straight line. In a small arena whose doorway lies far off the nest-goal line
// (tests/data/far_door.toml), the straight-line spot lies toward the wall; the way the robots came
// leads to the doorway.
#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Outcome {
  bool formed = false;
  int at_way_spot = 0;  ///< robots holding a chain link that backed off to a spot on their way
};

bool in_chain(PfState s) {
  return s == PfState::kSubgoal || s == PfState::kOpt1 || s == PfState::kSubNest || s == PfState::kOpt2 ||
         s == PfState::kPathDone;
}

Outcome run_in(const char* arena, const Params& p, Mode mode, std::uint64_t seed) {
  const Scenario s = load_scenario(test::source_path(arena));
  World w;
  const Metrics met = run(
      p, s, mode, seed, [](const World&) { return false; }, &w);
  Outcome o;
  o.formed = met.success;
  for (const RobotMemory& mem : w.memory) {
    if (in_chain(mem.pf.state) && mem.pf.has_way_spot && mem.pf.way_spot_for == mem.pf.parent.id)
      ++o.at_way_spot;
  }
  return o;
}

// far_door, 50 robots, seeds 1-8, runs that formed their path, default -> spot_on_way_pf: path formation
// 4 -> 7 (seeds 5-8 only with it; only forming robots that found the goal from its far side back off
// to a spot, backoff_far_spot: a few links at spots on the way). Task allocation 8 -> 7 since
// blocked_trip_ends, stop_at_view_edge and spot_patience were removed (6 -> 8 before: seeds 1, 7)
TEST(SpotOnWay, TheChainGrowsTheWayTheRobotsCameToAFarDoorway) {
  Params off;  // the default: spot_on_way_pf = false
  test::far_door_as_measured(off);
  off.way_after_edge = false;  // as measured: every way gives its spot
  Params on = off;
  on.spot_on_way_pf = true;

  const struct {
    Mode mode;
    std::uint64_t seed;
  } cases[] = {{Mode::kPathFormation, 5}, {Mode::kPathFormation, 7}};

  for (const auto& c : cases) {
    const Outcome without = run_in("tests/data/far_door.toml", off, c.mode, c.seed);
    const Outcome with = run_in("tests/data/far_door.toml", on, c.mode, c.seed);
    EXPECT_FALSE(without.formed) << c.seed;
    EXPECT_EQ(without.at_way_spot, 0) << c.seed;  // off: no robot chooses a spot on its way
    EXPECT_TRUE(with.formed) << c.seed;
    EXPECT_GT(with.at_way_spot, 0) << c.seed;  // links laid at spots on the way the robots came
  }
}

// way_after_edge [R]: the spot on the way only for a robot that followed an obstacle's edge on this
// trip. In an open arena (short_chain) spot_on_way alone lays links where the allocated robots'
// own wandering first came near their target (task allocation, seeds 1, 3 and 6: one each); with
// way_after_edge no robot that wandered there takes that spot. In far_door, where the robots come
// round the wall's end by its edge, links are still laid at spots on their way (seeds 1, 5, 6).
TEST(SpotOnWay, OnlyAWayThatWentRoundAnObstacleGivesTheSpot) {
  Params on;
  test::hasty_along_walls(on);  // as measured
  on.lead_way = false;          // as measured: the robots then come by the field, not along the founder's way
  on.chain_bypass = false;      // ... and every link they lay is kept
  on.spot_on_way = true;
  on.way_after_edge = false;
  Params edge = on;
  edge.way_after_edge = true;
  for (const std::uint64_t seed : {1, 3, 6}) {
    const Outcome wander = run_in("tests/data/short_chain.toml", on, Mode::kTaskAllocation, seed);
    const Outcome refined = run_in("tests/data/short_chain.toml", edge, Mode::kTaskAllocation, seed);
    EXPECT_GT(wander.at_way_spot, 0) << seed;
    EXPECT_EQ(refined.at_way_spot, 0) << seed;
    EXPECT_TRUE(refined.formed) << seed;
  }
  for (const std::uint64_t seed : {1, 5, 6}) {
    const Outcome round = run_in("tests/data/far_door.toml", edge, Mode::kTaskAllocation, seed);
    EXPECT_GT(round.at_way_spot, 0) << seed;
    EXPECT_TRUE(round.formed) << seed;
  }
}

}  // namespace
}  // namespace swarmpath::sim
