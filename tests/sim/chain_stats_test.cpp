// SPDX-License-Identifier: MIT
// The chain diagnostics: which links were laid goal-ward of their parent, and which robots began
// forming from the goal side of their target.
#include "sim/chain_stats.hpp"

#include <string_view>

#include <gtest/gtest.h>

#include "sim/controllers/path_formation.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Tracked ref(int id, Vec2 where) {
  Tracked t;
  t.id = id;
  t.last_seen = where;
  return t;
}

// small arena: nest (-2, 0), goal (2, 0); robot 0 is a RED subgoal at (1, 0)
struct ChainFixture : ::testing::Test {
  Scenario s = test::small_arena("", 3);
  World w = make_world(s, Params{}, Mode::kPathFormation, 1,
                       std::vector<Pose>{{{1.0, 0.0}, 1, 0}, {{0.0, 1.0}, 1, 0}, {{0.0, -1.0}, 1, 0}});
  ChainStatsObserver obs;

  void SetUp() override {
    w.memory[0].pf.state = PfState::kSubgoal;
    w.memory[0].pf.parent = ref(kGoalEmitter, s.goal);
    tick();  // robot 0 did not turn RED under observation: not counted
  }

  // one tick: the rows set by the caller fired in it
  void tick() {
    ++w.tick;
    obs.observe(s, w);
  }

  void fire(int i, std::string_view row, PfState to) {
    PfMemory& m = w.memory[static_cast<std::size_t>(i)].pf;
    m.state = to;
    m.last_row = pf_row_number(row);
    m.fired_tick = w.tick;
  }

  // robot i takes robot 0 as its target at `at` (row 1), then turns RED at `laid` (row 5)
  void form(int i, Vec2 at, Vec2 laid) {
    PfMemory& m = w.memory[static_cast<std::size_t>(i)].pf;
    w.positions[static_cast<std::size_t>(i)] = at;
    m.target = ref(0, w.positions[0]);
    fire(i, "#1", PfState::kSubgoalForming);
    tick();
    w.positions[static_cast<std::size_t>(i)] = laid;
    m.parent = m.target;
    fire(i, "#5", PfState::kSubgoal);
    tick();
  }
};

TEST_F(ChainFixture, ALinkLaidNestwardFromTheNestSideCountsOnlyAsLaid) {
  form(1, {0.8, 0.1}, {0.3, 0.0});  // nest side of robot 0, laid 70 cm nearer the nest
  EXPECT_EQ(obs.stats().subgoals_laid, 1);
  EXPECT_EQ(obs.stats().subgoals_laid_goalward, 0);
  EXPECT_EQ(obs.stats().forming_from_goal_side, 0);
}

TEST_F(ChainFixture, ALinkLaidBeyondItsParentCountsAsGoalwardAndFromTheGoalSide) {
  form(1, {1.25, 0.1}, {1.6, 0.5});   // goal side of robot 0, and laid farther from the nest
  form(2, {1.2, -0.1}, {0.3, -0.1});  // goal side, but laid nestward
  EXPECT_EQ(obs.stats().subgoals_laid, 2);
  EXPECT_EQ(obs.stats().subgoals_laid_goalward, 1);
  EXPECT_EQ(obs.stats().forming_from_goal_side, 2);
}

TEST(ChainStats, AWholeRunLaysAtLeastThePathsRobots) {
  const Scenario s = load_scenario(test::source_path("tests/data/short_chain.toml"));
  const Metrics m = evaluate(Params{}, s, Mode::kPathFormation, 1);
  ASSERT_TRUE(m.success);
  EXPECT_GE(m.chain.subgoals_laid, m.path_robots);  // every path robot was laid once at least
  EXPECT_LE(m.chain.subgoals_laid_goalward, m.chain.subgoals_laid);
}

}  // namespace
}  // namespace swarmpath::sim
