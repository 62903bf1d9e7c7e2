// SPDX-License-Identifier: MIT
// chain_bypass [R] (rows #15-#16; docs/detours.md, "A winding chain gives back its links"): a RED
// subgoal that sees its parent's parent within bypass_reach takes it as its parent, and the skipped
// robot leaves once every robot that named it names another. In task allocation (chain_bypass, on)
// tests/data/rooms_2.toml (training arena rooms-2, 60 robots, seed 23) forms only with it; in path
// formation without task allocation (chain_bypass_pf, on) tests/data/serpentine_2.toml (training
// arena serpentine-2, 60 robots, seed 27), whose path needs about 50 links, forms only with it.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/controllers/path_formation.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Outcome {
  bool success = false;
  int skipped = 0;  ///< robots that left the chain by row #16
};

Outcome run_arena(const std::string& file, const Params& p, Mode mode, std::uint64_t seed) {
  const Scenario s = load_scenario(test::source_path(file));
  const std::uint8_t row16 = pf_row_number("#16");
  std::set<std::size_t> skipped;
  const Metrics m = run(p, s, mode, seed, [&](const World& at) {
    for (std::size_t i = 0; i < at.memory.size(); ++i) {
      if (at.memory[i].pf.last_row == row16) skipped.insert(i);
    }
    return false;
  });
  return {m.success, static_cast<int>(skipped.size())};
}

// the arena's run forms with `on` and some robot is skipped (row #16); with `off` neither
void expect_forms_only_with(const std::string& file, const Params& on, const Params& off, Mode mode,
                            std::uint64_t seed) {
  const Outcome with = run_arena(file, on, mode, seed);
  const Outcome without = run_arena(file, off, mode, seed);
  EXPECT_TRUE(with.success) << file;
  EXPECT_GT(with.skipped, 0) << file;
  EXPECT_FALSE(without.success) << file;
  EXPECT_EQ(without.skipped, 0) << file;
}

TEST(ChainBypass, InTaskAllocationAWindingChainGivesBackLinksAndThePathForms) {
  const Params on;
  ASSERT_TRUE(on.chain_bypass);
  Params off = on;
  off.chain_bypass = false;
  expect_forms_only_with("tests/data/rooms_2.toml", on, off, Mode::kTaskAllocation, 23);
}

TEST(ChainBypass, InPathFormationTheSerpentinesChainFitsSixtyRobotsOnlyWithIt) {
  Params on;
  ASSERT_TRUE(on.chain_bypass_pf);
  on.anywhere_after_edge_pf = false;  // as measured: with it as well this run does not form
  Params off = on;
  off.chain_bypass_pf = false;
  expect_forms_only_with("tests/data/serpentine_2.toml", on, off, Mode::kPathFormation, 27);
}

}  // namespace
}  // namespace swarmpath::sim
