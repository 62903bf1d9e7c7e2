// SPDX-License-Identifier: MIT
// T_leaf [R] (docs/detours.md, row #21): without task allocation, a RED subgoal that no robot names as
// its parent or target for T_leaf ticks (a leaf no explorer extends) leaves the chain and goes home. In
// a wall-gap arena the robots that find the chain from the goal's room grow it into a fan of side
// branches; the leaves that nobody extends come back to the chain's tip from the nest's side.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/controllers/path_formation.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Outcome {
  bool success = false;
  int left = 0;         ///< robots that left the chain by row #21
  int branch_tops = 0;  ///< at the end, subgoals (or the goal) with more than one RED child
};

Outcome run_fan(const Params& p) {
  const Scenario s = load_scenario(test::source_path("tests/data/wall_gap_fan.toml"));
  const std::uint8_t row21 = pf_row_number("#21");
  std::set<std::size_t> left;
  World w;
  const Metrics m = run(
      p, s, Mode::kPathFormation, 11,
      [&](const World& at) {
        for (std::size_t i = 0; i < at.memory.size(); ++i) {
          const PfMemory& pf = at.memory[i].pf;
          if (pf.last_row == row21) left.insert(i);
        }
        return false;
      },
      &w);
  Outcome o;
  o.success = m.success;
  o.left = static_cast<int>(left.size());
  std::map<int, int> children;
  for (const RobotMemory& mem : w.memory) {
    if (mem.pf.state == PfState::kSubgoal) ++children[mem.pf.parent.id];
  }
  for (const auto& [parent, n] : children) o.branch_tops += n > 1 ? 1 : 0;
  return o;
}

// wall-gap-1 (the arena generator's wall-gap family, seed 1), 60 robots, seed 11, path formation: without
// the rule the run ends at T_max with its RED robots in a fan of branches (docs/detours-wall-gap-1-*.svg);
// with T_leaf the leaves nobody extends leave, come back, and the path forms
TEST(Leaf, LeavesNobodyExtendsLeaveTheFanAndThePathForms) {
  Params on;  // the default: T_leaf = 1500
  on.retarget_tip =
      false;  // as measured: with it the fan's robots keep to its tips and the path forms without T_leaf
  Params off = on;
  off.t_leaf = 0;
  const Outcome without = run_fan(off);
  const Outcome with = run_fan(on);
  EXPECT_FALSE(without.success);
  EXPECT_EQ(without.left, 0);
  EXPECT_GE(without.branch_tops, 2);  // several branches
  EXPECT_TRUE(with.success);
  EXPECT_GT(with.left, 0);
}

}  // namespace
}  // namespace swarmpath::sim
