// SPDX-License-Identifier: MIT
// Racing the finalists: the t tail against tabulated values, a clearly worse finalist dropped and
// the best kept (with the survivors' scores exactly those of a full re-evaluation), fewer
// simulations, bit-identical at 1 and 2 threads and after a resume, the keys checked.
#include "evolve/racing.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::FixedOptimizer;

TEST(Racing, StudentTailMatchesTables) {
  EXPECT_NEAR(student_t_upper(0.0, 5.0), 0.5, 1e-12);
  EXPECT_NEAR(student_t_upper(2.015048, 5.0), 0.05, 1e-6);   // t_{0.95, 5}
  EXPECT_NEAR(student_t_upper(1.812461, 10.0), 0.05, 1e-6);  // t_{0.95, 10}
  EXPECT_NEAR(student_t_upper(6.313752, 1.0), 0.05, 1e-6);   // t_{0.95, 1}
  EXPECT_NEAR(student_t_upper(-1.812461, 10.0), 0.95, 1e-6);
  EXPECT_NEAR(student_t_upper(2.527977, 20.0), 0.01, 1e-6);  // t_{0.99, 20}
}

TEST(Racing, PairedTestSidesAndDegenerateCases) {
  const std::vector<double> worse{1.0, 1.2, 0.9, 1.1}, better{-1.0, -1.2, -0.9, -1.1};
  EXPECT_LT(paired_t_p_value(worse), 0.01);
  EXPECT_GT(paired_t_p_value(better), 0.99);
  EXPECT_EQ(paired_t_p_value(std::vector<double>{0.3}), 1.0);            // one pair: no test
  EXPECT_EQ(paired_t_p_value(std::vector<double>{0.3, 0.3, 0.3}), 0.0);  // always worse
  EXPECT_EQ(paired_t_p_value(std::vector<double>{0.0, 0.0}), 1.0);       // tied
}

TEST(Racing, BlocksTakeOneCaseOfEverySetting) {
  const std::vector<EvalSetting> settings{{"a", 8, false}, {"b", 8, false}, {"c", 8, true}};
  const std::vector<EvalCase> cases = reevaluation_cases(settings, 3, 1);
  EXPECT_EQ(case_blocks(cases), (std::vector<int>{0, 1, 2, 0, 1, 2, 0, 1, 2}));
}

// A (w_away 0.2) scores 0.5, C (1.0) 0.55 and B (1.8) 1.5, each plus a seed-dependent noise in [0, 0.1)
double noisy(const sim::Params& p, const EvalCase& k) {
  const double noise = static_cast<double>(k.seed % 1000) / 10000.0;
  if (p.w_away < 0.5) return 0.5 + noise;
  if (p.w_away < 1.5) return 0.55 + noise;
  return 1.5 + noise;
}

RunResult race_run(bool race, int threads) {
  EvolveConfig c = testing::tiny("random", 1);
  c.reevaluate.top_k = 3;
  c.reevaluate.seeds = 8;
  c.reevaluate.race = race;
  const FakeObjective f({{"s", 8, false}}, noisy);
  RunOptions o;
  o.threads = threads;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(
        std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}, {0.5, 0.5, 0.5}});
  };
  return run_evolution(c, f, o);
}

TEST(Racing, DropsAClearlyWorseFinalistAndKeepsTheBest) {
  const RunResult full = race_run(false, 1), raced = race_run(true, 2);
  ASSERT_EQ(raced.finalists.size(), 3u);
  ASSERT_EQ(full.finalists.size(), 3u);
  // finalists in elite order: A, C, B
  EXPECT_EQ(raced.finalists[2].params.w_away, 1.8);
  EXPECT_GT(raced.finalists[2].dropped_after, 0);  // B is dropped ...
  EXPECT_LT(raced.finalists[2].dropped_after, 8);
  EXPECT_LT(raced.finalists[2].p_value, 0.05);
  EXPECT_EQ(raced.finalists[2].reevaluated.runs, raced.finalists[2].dropped_after);
  EXPECT_EQ(raced.finalists[0].dropped_after, 0);  // ... A never
  EXPECT_EQ(raced.best, full.best);                // and A is still reported
  EXPECT_EQ(raced.finalists[raced.best].params.w_away, 0.2);
  // a survivor's scores are those of the full re-evaluation, bit for bit
  EXPECT_EQ(raced.finalists[0].reevaluated.fitness, full.finalists[0].reevaluated.fitness);
  EXPECT_EQ(raced.finalists[0].reevaluated.runs, 8);
  EXPECT_EQ(raced.base.reevaluated.fitness, full.base.reevaluated.fitness);
  // fewer simulations: 4 x 8 without racing
  EXPECT_EQ(full.race.simulations, 32);
  EXPECT_EQ(raced.race.without_racing, 32);
  EXPECT_LE(raced.race.simulations, 32 - (8 - raced.finalists[2].dropped_after));
  EXPECT_EQ(raced.race.blocks, 8);
}

EvolveConfig raced_tiny(int generations) {
  return parse_evolve_config(
      testing::tiny_config("cmaes", generations) + "race = true\nrace_level = 0.2\nrace_first_test = 2\n",
      "tiny.toml", "");
}

TEST(Racing, BitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  const EvolveConfig c = raced_tiny(3);
  ASSERT_TRUE(c.reevaluate.race);
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  EXPECT_EQ(j.at("racing").at("simulations_without_racing").get<int>(),
            3 * 2);  // 2 finalists + base, 2 seeds
  EXPECT_TRUE(j.at("finalists")[0].contains("dropped_after_blocks"));
}

TEST(Racing, OffByDefaultAndTheHashUnchanged) {
  const EvolveConfig plain = testing::tiny("cmaes", 2);
  EXPECT_FALSE(plain.reevaluate.race);
  EvolveConfig explicit_off =
      parse_evolve_config(testing::tiny_config("cmaes", 2) + "race = false\n", "t", "");
  EXPECT_EQ(config_hash(plain), config_hash(explicit_off));
  EXPECT_NE(config_hash(plain), config_hash(raced_tiny(2)));
}

TEST(Racing, KeysAreChecked) {
  const std::string base = testing::tiny_config();
  testing::expect_error(base + "race = true\nrace_level = 0.7\n", "race_level", "reevaluate.race_level",
                        "must lie in");
  testing::expect_error(base + "race = true\nrace_first_test = 1\n", "race_first_test",
                        "reevaluate.race_first_test", "must lie in");
  testing::expect_error(base + "race = 3\n", "race = 3", "reevaluate.race", "");
  testing::expect_error(
      testing::replaced(testing::tiny_pareto_config(), "[reevaluate]\n", "[reevaluate]\nrace = true\n"),
      "race = true", "reevaluate.race", "single-objective");
}

}  // namespace
}  // namespace swarmpath::evolve
