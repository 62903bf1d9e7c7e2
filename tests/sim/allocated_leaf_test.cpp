// SPDX-License-Identifier: MIT
// T_leaf_allocated [R] (off by default; docs/detours.md, "Leaves of task allocation's fans"): with task
// allocation, an allocated subgoal that sees another branch of the chain and that no robot names for
// T_leaf_allocated ticks of that sight leaves the chain and goes home, as row #21's leaf does.
// tests/data/rooms_2.toml (the training arena rooms-2, 60 robots, seed 23): without the rule the
// robots led to the chain meet it in a fan and the run ends at T_max; with it the fan's leaves come
// back and the path forms.
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
  int left = 0;  ///< allocated robots that left the chain by row #21
};

Outcome run_rooms(const Params& p) {
  const Scenario s = load_scenario(test::source_path("tests/data/rooms_2.toml"));
  const std::uint8_t row21 = pf_row_number("#21");
  std::set<std::size_t> left;
  const Metrics m = run(p, s, Mode::kTaskAllocation, 23, [&](const World& at) {
    for (std::size_t i = 0; i < at.memory.size(); ++i) {
      const PfMemory& pf = at.memory[i].pf;
      if (pf.last_row == row21 && pf.role == PfRole::kAllocated) left.insert(i);
    }
    return false;
  });
  return {m.success, static_cast<int>(left.size())};
}

TEST(AllocatedLeaf, LeavesOfAFanOfAllocatedRobotsLeaveAndThePathForms) {
  Params off;
  ASSERT_EQ(off.t_leaf_allocated, 0.0);
  off.chain_bypass = false;  // measured before chain_bypass, which forms this run by itself
  Params on = off;
  on.t_leaf_allocated = 1500;
  const Outcome without = run_rooms(off);
  const Outcome with = run_rooms(on);
  EXPECT_FALSE(without.success);
  EXPECT_EQ(without.left, 0);
  EXPECT_TRUE(with.success);
  EXPECT_GT(with.left, 0);
}

}  // namespace
}  // namespace swarmpath::sim
