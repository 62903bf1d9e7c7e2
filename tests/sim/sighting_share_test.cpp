// SPDX-License-Identifier: MIT
// share_sighting [R] (docs/detours.md): in path formation without task allocation, robots at the nest
// tell each other where they saw the goal or the chain, and a resting robot without a sighting of
// its own starts its next trip toward the one it heard. In a serpentine the field away from the nest
// leads explorers into the walls; told robots find the chain and lay its links sooner.
#include "sim/controllers/sighting_share.hpp"

#include <array>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(SightingShare, ATellingCarriesTheSightingToARestingRobotWithoutOne) {
  Params p;
  p.share_sighting = 300;
  p.share_after = 0;  // from the start of the run
  const Vec2 nest{-7.0, 0.5};
  PfMemory teller;
  teller.state = PfState::kResting;
  teller.sighting = {6.93, -2.41};  // east and south of the nest: both coordinates' signs travel
  teller.has_sighting = true;
  EXPECT_TRUE(tells_sighting(p, teller, 250.0, 0));
  EXPECT_FALSE(tells_sighting(p, teller, 350.0, 0));  // farther from the nest than share_sighting
  p.share_after = 6000;                               // telling begins at tick 6 000 of the run
  EXPECT_FALSE(tells_sighting(p, teller, 250.0, 5999));
  EXPECT_TRUE(tells_sighting(p, teller, 250.0, 6000));
  p.share_after = 0;
  Command cmd;
  tell_sighting(7, nest, teller, cmd);
  ASSERT_TRUE(cmd.rab_send);

  PfMemory listener;
  listener.state = PfState::kResting;
  EXPECT_TRUE(listens_for_sighting(p, listener));
  std::array<RabMessage, 1> inbox{};
  inbox[0].sender = 7;
  inbox[0].range_cm = 120;
  inbox[0].data = cmd.rab;
  ASSERT_TRUE(hear_sighting(inbox, nest, listener));
  EXPECT_TRUE(listener.has_sighting);
  EXPECT_FALSE(listener.sighted_this_trip);  // a trip that finds nothing there forgets it
  EXPECT_NEAR(listener.sighting.x, 6.93, 0.006);
  EXPECT_NEAR(listener.sighting.y, -2.41, 0.006);
  EXPECT_FALSE(listens_for_sighting(p, listener));  // it has one of its own now

  // off, and robots of task allocation, neither tell nor listen
  PfMemory allocated = teller;
  allocated.role = PfRole::kAllocated;
  EXPECT_FALSE(tells_sighting(p, allocated, 100.0, 0));
  p.share_sighting = 0;
  EXPECT_FALSE(tells_sighting(p, teller, 100.0, 0));
  PfMemory resting;
  resting.state = PfState::kResting;
  EXPECT_FALSE(listens_for_sighting(p, resting));
}

int links_laid_by(const Params& p, const Scenario& s, std::uint64_t seed) {
  return run(p, s, Mode::kPathFormation, seed, [](const World&) { return false; }).chain.subgoals_laid;
}

// small_serpentine, 40 robots, seeds 1-8, links laid by tick 8 000 without sharing and with `with`: with
// sharing at least as many again in 6 of 8 seeds, and half as many again in all
void expect_told_robots_lay_more_links(const Params& off, const Params& with) {
  const Scenario s =
      with_max_ticks(load_scenario(test::source_path("tests/data/small_serpentine.toml")), 8000);
  int sum_off = 0, sum_on = 0, more = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const int a = links_laid_by(off, s, seed);
    const int b = links_laid_by(with, s, seed);
    sum_off += a;
    sum_on += b;
    if (b > a) ++more;
  }
  EXPECT_GE(more, 6) << sum_off << " -> " << sum_on;
  EXPECT_GE(2 * sum_on, 3 * sum_off) << sum_off << " -> " << sum_on;  // at least half as many again
}

// small_serpentine, 40 robots, the default genome with T_leaf = 0, links laid (transitions into RED) by tick
// 8 000, seeds 1-8, off -> on: 6 -> 26, 9 -> 15, 9 -> 34, 5 -> 7, 15 -> 14, 15 -> 28, 6 -> 10, 11 -> 25 (76
// -> 159)
TEST(SightingShare, ToldRobotsLayTheChainThroughASerpentineSooner) {
  Params off;
  off.share_sighting = 0;
  off.t_leaf = 0;  // as measured (beside T_leaf = 1500 the same seeds give 112 -> 146)
  Params on = off;
  on.share_sighting = 300;
  on.share_after = 0;  // from the start of the run
  expect_told_robots_lay_more_links(off, on);
}

// share_after [R]: telling begins at a tick of the run, so that a search that finds its way before then
// runs as without sharing (short_chain, 20 robots, seed 1: the path forms at tick 1 445 without sharing,
// at 1 440 with it from the start), and one still under way then gets it (small_serpentine, 40 robots,
// seeds 1-8, links laid by tick 8 000, the default genome with T_leaf = 0: 76 without sharing, 145 with
// it from tick 3 000, more in 7 of 8 seeds).
TEST(SightingShare, TellingFromShareAfterLeavesAQuickSearchAsItWasAndHelpsASlowOne) {
  const Scenario quick = load_scenario(test::source_path("tests/data/short_chain.toml"));
  Params off;
  off.share_sighting = 0;
  Params from_start = off;
  from_start.share_sighting = 300;
  from_start.share_after = 0;
  Params late = from_start;
  late.share_after = 2000;
  const Metrics a = run(off, quick, Mode::kPathFormation, 1, [](const World&) { return false; });
  const Metrics b = run(from_start, quick, Mode::kPathFormation, 1, [](const World&) { return false; });
  const Metrics c = run(late, quick, Mode::kPathFormation, 1, [](const World&) { return false; });
  ASSERT_TRUE(a.success);
  EXPECT_LT(a.ticks_to_form, 2000);
  EXPECT_NE(a.state_hash, b.state_hash);  // sharing from the start changes this run
  EXPECT_EQ(a.state_hash, c.state_hash);  // sharing from tick 2 000 does not
  EXPECT_EQ(a.ticks_to_form, c.ticks_to_form);

  off.t_leaf = 0;
  late.t_leaf = 0;
  late.share_after = 3000;
  expect_told_robots_lay_more_links(off, late);
}

}  // namespace
}  // namespace swarmpath::sim
