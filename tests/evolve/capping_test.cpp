// SPDX-License-Identifier: MIT
// Adaptive capping: the settling rule, a small case where capping stops runs yet every
// generation's best, the finalists and the reported best are those of the uncapped run, bit-identical
// files at 1 and 2 threads and after a resume, the keys checked.
#include "evolve/capping.hpp"

#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::scratch;

TEST(Capping, SettledOnlyWhenKCandidatesAreCertainlyBetter) {
  // bounds [1, 1.5], [2, 2.5], [5, 6], [2.5, 9]; keep 2: the 2nd lowest upper bound is 2.5
  const std::vector<double> lower{1.0, 2.0, 5.0, 2.5}, upper{1.5, 2.5, 6.0, 9.0};
  EXPECT_EQ(settled_out(lower, upper, 2), (std::vector<bool>{false, false, true, false}));  // 2.5: a tie
  EXPECT_EQ(settled_out(lower, upper, 3), (std::vector<bool>(4, false)));
  EXPECT_EQ(settled_out(lower, upper, 4), (std::vector<bool>(4, false)));
  EXPECT_EQ(capping_keep(9, 3), 5u);  // CMA-ES's mu = 4 of 9, top_k 3
  EXPECT_EQ(capping_keep(8, 6), 6u);
}

// the tiny config at T_max 10 000, population 8, CMA-ES, capping at half T_max
std::string capped_text(bool on, int generations) {
  std::string t = testing::replaced(
      testing::tiny_config("cmaes", generations), "max_ticks = 3000\n",
      std::string("max_ticks = 10000\n") + (on ? "capping = true\ncapping_fraction = 0.5\n" : ""));
  return testing::replaced(t, "population = 4\n", "population = 8\n");
}

EvolveConfig capped(bool on, int generations = 3) {
  return parse_evolve_config(capped_text(on, generations), "tiny.toml", "");
}

TEST(Capping, StopsRunsWithoutChangingWhatRanksFirst) {
  const EvolveConfig on = capped(true), off = capped(false);
  const SwarmObjective f_on(on), f_off(off);
  const RunResult a = run_evolution(on, f_on, testing::test_options(scratch("on"), 2));
  const RunResult b = run_evolution(off, f_off, testing::test_options(scratch("off"), 2));
  std::int64_t capped_runs = 0;
  ASSERT_EQ(a.state.history.size(), b.state.history.size());
  for (std::size_t g = 0; g < a.state.history.size(); ++g) {
    const GenerationRecord &x = a.state.history[g], &y = b.state.history[g];
    capped_runs += x.capped_runs;
    EXPECT_EQ(x.best, y.best) << g;  // each generation's best, exactly
    EXPECT_EQ(x.best_so_far, y.best_so_far) << g;
    EXPECT_EQ(x.tuned_best, y.tuned_best) << g;
    EXPECT_LE(x.mean, y.mean) << g;  // censored candidates count their lower bound
  }
  EXPECT_GT(capped_runs, 0);  // it did stop runs here
  ASSERT_EQ(a.finalists.size(), b.finalists.size());
  for (std::size_t i = 0; i < a.finalists.size(); ++i) {
    EXPECT_EQ(a.finalists[i].elite.x, b.finalists[i].elite.x);
    EXPECT_EQ(a.finalists[i].elite.stats.fitness, b.finalists[i].elite.stats.fitness);
    EXPECT_EQ(a.finalists[i].reevaluated.fitness, b.finalists[i].reevaluated.fitness);
  }
  EXPECT_EQ(a.best, b.best);
}

TEST(Capping, BitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  const EvolveConfig c = capped(true);
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  EXPECT_GT(j.at("capping").at("capped_runs").get<int>(), 0);
}

TEST(Capping, OffByDefaultKeysCheckedHashUnchanged) {
  EXPECT_FALSE(testing::tiny().evaluation.capping);
  EXPECT_EQ(config_hash(capped(false)),
            config_hash(parse_evolve_config(testing::replaced(capped_text(false, 3), "max_ticks = 10000\n",
                                                              "max_ticks = 10000\ncapping = false\n"),
                                            "t", "")));
  const std::string on = capped_text(true, 2);
  testing::expect_error(testing::replaced(on, "capping_fraction = 0.5", "capping_fraction = 1.5"),
                        "capping_fraction", "evaluation.capping_fraction", "must lie in");
  testing::expect_error(testing::replaced(on, "name = \"cmaes\"", "name = \"ga\""), "capping = true",
                        "evaluation.capping", "needs optimizer cmaes or random");
}

}  // namespace
}  // namespace swarmpath::evolve
