// SPDX-License-Identifier: MIT
// Racing the finalists against the base params ([reevaluate] race_base): the blocks are the fresh
// cases and then new seeds; a finalist worse than the base params is dropped and its runs buy more
// paired runs for a better one (the same budget, never more); with every finalist worse the
// re-evaluation stops early and the base params stay the pick; bit-identical at 1 and 2 threads and
// after a resume; the keys checked, the hash of configs without them unchanged.
#include "evolve/base_racing.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/runner.hpp"
#include "evolve/seeds.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::FixedOptimizer;
using testing::read_text;
using testing::scratch;

namespace fs = std::filesystem;

TEST(BaseRacing, BlocksAreTheFreshCasesThenNewSeeds) {
  const std::vector<EvalSetting> settings{{"a", 8, false}, {"b", 8, false}, {"c", 8, true}};
  const std::vector<EvalCase> cases = reevaluation_cases(settings, 2, 1);  // a0 a1 b0 b1 c0 c1
  const std::vector<EvalCase> b0 = base_race_block(settings, cases, 0, 1);
  const std::vector<EvalCase> b1 = base_race_block(settings, cases, 1, 1);
  ASSERT_EQ(b0.size(), 2u);  // the training settings only
  EXPECT_EQ(b0[0].seed, cases[0].seed);
  EXPECT_EQ(b0[1].seed, cases[2].seed);
  EXPECT_EQ(b1[0].seed, cases[1].seed);
  EXPECT_EQ(b1[1].seed, cases[3].seed);
  // past the fresh cases: new seeds numbered on after every re-evaluation case's (held-out ones too)
  const std::vector<EvalCase> b2 = base_race_block(settings, cases, 2, 1);
  const std::vector<EvalCase> b3 = base_race_block(settings, cases, 3, 1);
  ASSERT_EQ(b2.size(), 2u);
  EXPECT_EQ(b2[0].setting, 0u);
  EXPECT_EQ(b2[1].setting, 1u);
  EXPECT_EQ(b2[0].replicate, 2);
  EXPECT_EQ(b2[0].seed, reevaluation_seed(1, 6));
  EXPECT_EQ(b2[1].seed, reevaluation_seed(1, 7));
  EXPECT_EQ(b3[0].seed, reevaluation_seed(1, 8));
  std::set<std::uint64_t> seeds;
  for (const auto* block : {&cases, &b2, &b3})
    for (const EvalCase& k : *block) seeds.insert(k.seed);
  EXPECT_EQ(seeds.size(), cases.size() + 4);  // all distinct
}

// A (w_away 0.2) scores `a`, B (w_away 1.8) `b`, the base params (w_away 0.5) 0.5, each plus a
// seed-dependent noise in [0, 0.1); top_k 2, 4 fresh seeds of one setting: 12 simulations to spend
RunResult race_run(double a, double b, bool race_base, int threads, const fs::path& dir) {
  EvolveConfig c = testing::tiny("random", 1);
  c.reevaluate.seeds = 4;
  c.reevaluate.race_base = race_base;
  const FakeObjective f({{"s", 8, false}}, [=](const sim::Params& p, const EvalCase& k) {
    const double noise = static_cast<double>(k.seed % 1000) / 10000.0;
    if (p.w_away > 1.0) return b + noise;
    if (p.w_away > 0.3) return 0.5 + noise;
    return a + noise;
  });
  RunOptions o = testing::test_options(dir, threads);
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}});
  };
  return run_evolution(c, f, o);
}

const Finalist& with_w_away(const RunResult& r, double w) {
  const auto at = std::find_if(r.finalists.begin(), r.finalists.end(),
                               [&](const Finalist& f) { return f.params.w_away == w; });
  EXPECT_NE(at, r.finalists.end());
  return *at;
}

TEST(BaseRacing, AWorseFinalistsRunsGoToTheBetterOne) {
  const RunResult plain = race_run(0.3, 2.0, false, 1, scratch("plain"));
  const fs::path dir = scratch("raced");
  const RunResult raced = race_run(0.3, 2.0, true, 2, dir);
  ASSERT_EQ(raced.finalists.size(), 2u);
  const Finalist &a = with_w_away(raced, 0.2), &b = with_w_away(raced, 1.8);
  // B is dropped at the first test (after 2 blocks), A never
  EXPECT_EQ(b.dropped_after, 2);
  EXPECT_LT(b.p_value, 0.2);
  EXPECT_EQ(b.reevaluated.runs, 2);
  EXPECT_EQ(a.dropped_after, 0);
  // B's 2 blocks left buy A and the base params one more block each: 5 paired runs, not 4
  EXPECT_EQ(a.reevaluated.runs, 5);
  EXPECT_EQ(raced.base.reevaluated.runs, 5);
  EXPECT_EQ(raced.race.blocks, 5);
  EXPECT_EQ(raced.race.simulations, 12);  // 3 x 2 + 2 x 3: the plain re-evaluation's 3 x 4
  EXPECT_EQ(plain.race.simulations, 12);
  EXPECT_EQ(raced.selection.pairs, 5);
  EXPECT_FALSE(raced.selection.base_kept);
  EXPECT_EQ(raced.pick().w_away, 0.2);
  // the first 4 blocks are the plain re-evaluation's cases: the same runs, so the same scores there
  EXPECT_EQ(with_w_away(plain, 0.2).reevaluated.runs, 4);
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run.json"));
  EXPECT_EQ(j.at("racing").at("against").get<std::string>(), "base params");
  EXPECT_EQ(j.at("racing").at("simulations").get<int>(), 12);
  EXPECT_EQ(j.at("selection").at("pairs").get<int>(), 5);
}

TEST(BaseRacing, EveryFinalistWorseStopsEarlyAndKeepsTheBaseParams) {
  const fs::path dir = scratch("worse");
  const RunResult r = race_run(1.5, 2.0, true, 2, dir);
  ASSERT_EQ(r.finalists.size(), 2u);
  EXPECT_EQ(r.finalists[0].dropped_after, 2);
  EXPECT_EQ(r.finalists[1].dropped_after, 2);
  EXPECT_EQ(r.race.blocks, 2);
  EXPECT_EQ(r.race.simulations, 6);  // 2 blocks of 3, half of the plain 12
  EXPECT_TRUE(r.selection.on);
  EXPECT_TRUE(r.selection.base_kept);
  EXPECT_EQ(r.pick().w_away, 0.5);
  EXPECT_EQ(r.finalists[r.best].params.w_away, 0.2);  // the better of the two by its mean, reported
  EXPECT_EQ(r.selection.pairs, 2);
  const std::string toml = read_text(dir / "best.toml");
  EXPECT_EQ(toml.rfind("# swarmpath evolve: the base params kept by run \"tiny\"", 0), 0u) << toml;
}

TEST(BaseRacing, BitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  const EvolveConfig c =
      parse_evolve_config(testing::replaced(testing::tiny_config("cmaes", 3), "top_k = 2\nseeds = 2\n",
                                            "top_k = 2\nseeds = 4\n") +
                              "race_base = true\nrace_base_level = 0.3\n",
                          "tiny.toml", "");
  ASSERT_TRUE(c.reevaluate.race_base);
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  EXPECT_LE(j.at("racing").at("simulations").get<int>(), 3 * 4);  // 2 finalists + base, 4 seeds
  EXPECT_TRUE(j.at("finalists")[0].contains("dropped_after_blocks"));
}

TEST(BaseRacing, KeysAreCheckedAndOffKeepsTheHash) {
  const std::string base = testing::tiny_config();
  testing::expect_error(base + "race_base = true\nrace_base_level = 0.7\n", "race_base_level",
                        "reevaluate.race_base_level", "must lie in");
  testing::expect_error(base + "race_base_level = 0.1\n", "race_base_level", "reevaluate.race_base_level",
                        "only with race_base = true");
  testing::expect_error(base + "race = true\nrace_base = true\n", "race_base", "reevaluate.race_base",
                        "not both");
  testing::expect_error(base + "race_base = true\nkeep_base = false\n", "race_base = true",
                        "reevaluate.race_base", "keep_base = true");
  testing::expect_error(
      testing::replaced(testing::tiny_pareto_config(), "[reevaluate]\n", "[reevaluate]\nrace_base = true\n"),
      "race_base = true", "reevaluate.race_base", "single-objective");
  const EvolveConfig plain = testing::tiny("cmaes", 2);
  EXPECT_FALSE(plain.reevaluate.race_base);
  const auto with = [&](const std::string& lines) {
    return parse_evolve_config(testing::tiny_config("cmaes", 2) + lines, "t", "");
  };
  EXPECT_EQ(config_hash(plain), config_hash(with("race_base = false\n")));
  EXPECT_NE(config_hash(plain), config_hash(with("race_base = true\n")));
  EXPECT_NE(config_hash(with("race_base = true\n")),
            config_hash(with("race_base = true\nrace_base_level = 0.1\n")));
}

}  // namespace
}  // namespace swarmpath::evolve
