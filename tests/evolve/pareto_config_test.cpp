// SPDX-License-Identifier: MIT
// Multi-objective evolve configs: [objectives] is read strictly, belongs to nsga2 only, and the
// settings that mean nothing there ([fitness] weights, top_k) are refused at their line.
#include <gtest/gtest.h>

#include "evolve/evolve_config.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::expect_error;
using testing::replaced;
using testing::tiny_config;
using testing::tiny_pareto_config;

TEST(ParetoConfig, ReadsTheObjectives) {
  const EvolveConfig c = parse_evolve_config(tiny_pareto_config(), "tiny.toml", "");
  ASSERT_TRUE(c.multi_objective());
  EXPECT_EQ(c.multi.objectives, (std::vector<ObjectiveKind>{ObjectiveKind::kPathRatio, ObjectiveKind::kTicks,
                                                            ObjectiveKind::kRobotsFraction}));
  EXPECT_EQ(c.multi.min_success, 0.5);
  EXPECT_EQ(c.multi.reference, (Vector{2.0, 3000.0, 1.0}));
  EXPECT_EQ(config_json(c).at("objectives").at("min_success"), 0.5);
  // the objectives are part of the hash (a resume under others is refused)
  const EvolveConfig other = parse_evolve_config(
      replaced(tiny_pareto_config(), "min_success = 0.5", "min_success = 0.6"), "tiny.toml", "");
  EXPECT_NE(config_hash(c), config_hash(other));
  // single-objective configs have none
  EXPECT_FALSE(parse_evolve_config(tiny_config(), "tiny.toml", "").multi_objective());
}

TEST(ParetoConfig, TheShippedParetoConfigLoads) {
  const EvolveConfig c = load_evolve_config(testing::source("configs/evolve/paper-ta-pareto.toml"));
  EXPECT_EQ(c.mode, sim::Mode::kTaskAllocation);
  EXPECT_EQ(c.optimizer.name, "nsga2");
  EXPECT_EQ(c.multi.objectives.size(), 3u);
  const EvolveConfig two = load_evolve_config(testing::source("configs/evolve/paper-ta-pareto-2d.toml"));
  EXPECT_EQ(two.multi.objectives,
            (std::vector<ObjectiveKind>{ObjectiveKind::kTicks, ObjectiveKind::kRobotsFraction}));
  EXPECT_EQ(two.multi.reference, (Vector{36000.0, 1.0}));
}

TEST(ParetoConfig, Nsga2NeedsObjectives) {
  std::string t = tiny_config("nsga2");
  t.erase(t.find("top_k = 2\n"), 10);
  expect_error(t, "[optimizer]", "optimizer", "needs an [objectives] table");
}

TEST(ParetoConfig, ObjectivesBelongToMultiObjectiveOptimisers) {
  const std::string t =
      tiny_config("cmaes") + "\n[objectives]\nuse = [\"path\", \"ticks\"]\nreference = [2, 3000]\n";
  expect_error(t, "use = [\"path\", \"ticks\"]", "objectives.use", "multi-objective optimiser");
}

TEST(ParetoConfig, BadObjectiveLists) {
  const std::string t = tiny_pareto_config();
  const std::string use = "use = [\"path\", \"ticks\", \"robots\"]";
  expect_error(replaced(t, use, "use = [\"path\", \"time\", \"robots\"]"), "use =", "objectives.use",
               "unknown objective \"time\"");
  expect_error(replaced(t, use, "use = [\"path\", \"path\", \"robots\"]"), "use =", "objectives.use",
               "named twice");
  expect_error(
      replaced(replaced(t, use, "use = [\"ticks\"]"), "reference = [2.0, 3000, 1.0]", "reference = [3000]"),
      "use =", "objectives.use", "2 or 3");
  expect_error(replaced(t, "reference = [2.0, 3000, 1.0]", "reference = [2.0, 3000]"), "reference",
               "objectives.reference", "one value per objective");
  expect_error(replaced(t, "reference = [2.0, 3000, 1.0]", "reference = [2.0, -1, 1.0]"), "reference",
               "objectives.reference", "> 0");
  expect_error(replaced(t, "min_success = 0.5", "min_success = 1.5"), "min_success", "objectives.min_success",
               "must lie in [0, 1]");
  expect_error(replaced(t, "min_success = 0.5", "min_sucess = 0.5"), "min_sucess", "objectives.min_sucess",
               "unknown");
}

TEST(ParetoConfig, WeightsAndTopKAreRefused) {
  const std::string t = tiny_pareto_config();
  expect_error(t + "\n[fitness]\nw_time = 2.0\n", "w_time", "fitness.w_time", "not a weighted sum");
  // fail_path_ratio still applies (the path of a candidate that never succeeded)
  const EvolveConfig c = parse_evolve_config(t + "\n[fitness]\nfail_path_ratio = 4.0\n", "tiny.toml", "");
  EXPECT_EQ(c.fitness.fail_path_ratio, 4.0);
  expect_error(replaced(t, "seeds = 2\n\n[objectives]", "top_k = 3\nseeds = 2\n\n[objectives]"), "top_k",
               "reevaluate.top_k", "every point of its final front");
}

}  // namespace
}  // namespace swarmpath::evolve
