// SPDX-License-Identifier: MIT
// Seeds: common random numbers within a generation, new seeds each generation (unless fixed),
// fresh seeds for the re-evaluation, and the runner really uses them.
#include "evolve/seeds.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "evolve/objective.hpp"
#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::FixedOptimizer;

const std::vector<EvalSetting> kSettings = {
    {"a", 10, false}, {"a", 20, false}, {"b", 10, false}, {"h", 10, true}};

TEST(Seeds, CasesAreSettingMajorAndSkipHeldOut) {
  const auto cases = generation_cases(kSettings, 3, 1, 0, false);
  ASSERT_EQ(cases.size(), 9u);
  EXPECT_EQ(cases[0].setting, 0u);
  EXPECT_EQ(cases[3].setting, 1u);
  EXPECT_EQ(cases[8].setting, 2u);
  EXPECT_EQ(cases[5].replicate, 2);
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(cases[i].seed, generation_seed(1, 0, i));
  EXPECT_EQ(reevaluation_cases(kSettings, 2, 1).size(), 8u);  // held-out settings too
}

TEST(Seeds, ChangeBetweenGenerationsUnlessFixed) {
  const auto g0 = generation_cases(kSettings, 2, 5, 0, false);
  const auto g1 = generation_cases(kSettings, 2, 5, 1, false);
  std::set<std::uint64_t> seen;
  for (const auto& c : g0) seen.insert(c.seed);
  for (const auto& c : g1) EXPECT_EQ(seen.count(c.seed), 0u);
  EXPECT_EQ(seen.size(), g0.size());  // distinct within a generation too
  const auto f3 = generation_cases(kSettings, 2, 5, 3, true);
  for (std::size_t i = 0; i < g0.size(); ++i) EXPECT_EQ(f3[i].seed, g0[i].seed);
  for (const auto& c : reevaluation_cases(kSettings, 2, 5)) EXPECT_EQ(seen.count(c.seed), 0u);
  EXPECT_NE(generation_seed(5, 0, 0), generation_seed(6, 0, 0));  // the master seed matters
}

TEST(Seeds, EveryCandidateOfAGenerationMeetsTheSameSeeds) {
  const EvolveConfig c = testing::tiny("random", 3);
  const std::vector<EvalSetting> settings = {{"s", 8, false}};
  const FakeObjective f(settings, [](const sim::Params& p, const EvalCase&) { return p.w_away; });
  RunOptions o;
  o.threads = 2;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(
        std::vector<Vector>{{0.1, 0.1, 0.5}, {0.9, 0.9, 0.5}, {0.5, 0.5, 0.7}});
  };
  const RunResult r = run_evolution(c, f, o);
  // which seeds each candidate (told apart by w_away) saw, per generation
  std::map<double, std::vector<std::uint64_t>> by_candidate;
  for (const auto& call : f.calls()) by_candidate[call.params.w_away].push_back(call.c.seed);
  ASSERT_EQ(by_candidate.size(), 4u);   // three candidates (w_away 0.2, 1.8, 1.0) and the base (0.5)
  std::vector<std::uint64_t> expected;  // 3 generations x 2 cases, then 2 re-evaluation cases
  for (std::int64_t g = 0; g < 3; ++g) {
    for (std::uint64_t i = 0; i < 2; ++i) expected.push_back(generation_seed(c.seed, g, i));
  }
  std::sort(expected.begin(), expected.end());
  for (const double w : {0.2, 1.8, 1.0}) {
    ASSERT_EQ(by_candidate.count(w), 1u) << w;
    const std::vector<std::uint64_t>& seeds = by_candidate[w];
    std::vector<std::uint64_t> training;
    for (const std::uint64_t s : seeds) {
      if (s != reevaluation_seed(c.seed, 0) && s != reevaluation_seed(c.seed, 1)) training.push_back(s);
    }
    std::sort(training.begin(), training.end());
    EXPECT_EQ(training, expected) << "candidate w_away = " << w;
  }
  EXPECT_EQ(r.state.generation, 3);
}

}  // namespace
}  // namespace swarmpath::evolve
