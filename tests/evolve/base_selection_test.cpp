// SPDX-License-Identifier: MIT
// Keeping the base params ([reevaluate] keep_base): the paired test and its level split over the
// finalists; a finalist that looks better by its mean but not by the test leaves the base params as
// the pick, a clearly better one replaces them; the files say which, bit-identical at 1 and 2
// threads and after a resume; the keys are checked and the hash of configs without them unchanged.
#include "evolve/base_selection.hpp"

#include <algorithm>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/runner.hpp"
#include "evolve/simulation_budget.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::FixedOptimizer;
using testing::read_text;
using testing::scratch;

namespace fs = std::filesystem;

TEST(BaseSelection, PairedTestAtTheLevelSplitOverTheFinalists) {
  // base minus finalist 1, 2, 3, 4: mean 2.5, sd 1.2910, t = sqrt(15) on 3 degrees of freedom,
  // one-sided p = 1/2 - (sqrt(5)/6 + atan(sqrt(5))) / pi = 0.015234
  const std::vector<double> finalist{0.0, 0.0, 0.0, 0.0}, base{1.0, 2.0, 3.0, 4.0};
  const BaseSelection two = select_against_base(finalist, base, 2, 0.05);
  EXPECT_TRUE(two.on);
  EXPECT_EQ(two.pairs, 4);
  EXPECT_NEAR(two.mean_difference, 2.5, 1e-12);
  EXPECT_NEAR(two.sd_difference, 1.2909944487, 1e-9);
  EXPECT_NEAR(two.t, 3.8729833462, 1e-9);
  EXPECT_NEAR(two.p_value, 0.015234, 1e-6);
  EXPECT_EQ(two.threshold, 0.025);
  EXPECT_FALSE(two.base_kept);  // 0.0152 < 0.05 / 2 finalists
  const BaseSelection four = select_against_base(finalist, base, 4, 0.05);
  EXPECT_EQ(four.threshold, 0.0125);
  EXPECT_TRUE(four.base_kept);  // 0.0152 >= 0.05 / 4 finalists
  // a finalist worse than the base params never replaces them, nor one pair alone
  EXPECT_TRUE(select_against_base(base, finalist, 1, 0.5).base_kept);
  EXPECT_TRUE(select_against_base(std::vector<double>{0.0}, std::vector<double>{1.0}, 1, 0.5).base_kept);
  EXPECT_THROW(select_against_base(finalist, std::vector<double>{1.0}, 1, 0.5), std::invalid_argument);
}

// Finalist A (w_away 0.2) scores `a` plus `noise`, + and - in turn over the 12 fresh cases (`a` on
// the generation's cases, so it leads the best-so-far list); B (w_away 1.8) 2.0 everywhere; the base
// params (w_away 0.5, genomes/default.toml) 0.5 everywhere.
EvolveConfig two_finalists() {
  EvolveConfig c = testing::tiny("random", 1);
  c.reevaluate.seeds = 12;
  return c;
}

double score(const std::vector<EvalCase>& fresh, double a, double noise, const sim::Params& p,
             const EvalCase& k) {
  if (p.w_away > 1.0) return 2.0;
  if (p.w_away > 0.3) return 0.5;
  const auto at =
      std::find_if(fresh.begin(), fresh.end(), [&](const EvalCase& e) { return e.seed == k.seed; });
  if (at == fresh.end()) return a;
  return a + ((at - fresh.begin()) % 2 == 0 ? noise : -noise);
}

RunResult run_two(const EvolveConfig& c, double a, double noise, const fs::path& dir) {
  const std::vector<EvalSetting> settings{{"s", 8, false}};
  const std::vector<EvalCase> fresh = reevaluation_cases(settings, c.reevaluate.seeds, c.seed);
  const FakeObjective f(
      settings, [&](const sim::Params& p, const EvalCase& k) { return score(fresh, a, noise, p, k); });
  RunOptions o = testing::test_options(dir, 2);
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}});
  };
  return run_evolution(c, f, o);
}

TEST(BaseSelection, TheBaseParamsStayWhenNoFinalistBeatsThemByTheTest) {
  const EvolveConfig c = two_finalists();
  ASSERT_TRUE(c.reevaluate.keep_base);  // the default
  const fs::path dir = scratch("kept");
  // A: 0.49 +- 0.3, better than the base params' 0.5 by its mean, not by the paired test
  const RunResult r = run_two(c, 0.49, 0.3, dir);
  ASSERT_EQ(r.finalists.size(), 2u);
  EXPECT_EQ(r.finalists[r.best].params.w_away, 0.2);
  EXPECT_LT(r.finalists[r.best].reevaluated.fitness, r.base.reevaluated.fitness);
  EXPECT_EQ(r.selection.pairs, 12);
  EXPECT_EQ(r.selection.finalists, 2);
  EXPECT_NEAR(r.selection.mean_difference, 0.01, 1e-12);
  EXPECT_GT(r.selection.p_value, 0.4);
  EXPECT_TRUE(r.selection.base_kept);
  EXPECT_EQ(r.pick().w_away, 0.5);
  // best.toml holds the base params and says so; run.json records the test
  const std::string toml = read_text(dir / "best.toml");
  EXPECT_EQ(toml.rfind("# swarmpath evolve: the base params kept by run \"tiny\"", 0), 0u) << toml;
  EXPECT_NE(toml.find("No finalist beat the base params on fresh seeds"), std::string::npos) << toml;
  EXPECT_EQ(sim::get_value(sim::load_params((dir / "best.toml").string()), *sim::find_param("w_away")), 0.5);
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run.json"));
  EXPECT_TRUE(j.at("selection").at("base_kept").get<bool>());
  EXPECT_EQ(j.at("selection").at("pairs").get<int>(), 12);
  EXPECT_EQ(j.at("selection").at("threshold").get<double>(), 0.025);
  EXPECT_TRUE(j.at("best").at("base").get<bool>());
  EXPECT_EQ(j.at("best").at("tuned").at("w_away").get<double>(), 0.5);
  // without keep_base the same run reports A, as before
  EvolveConfig off = c;
  off.reevaluate.keep_base = false;
  const fs::path dir_off = scratch("off");
  const RunResult r_off = run_two(off, 0.49, 0.3, dir_off);
  EXPECT_FALSE(r_off.selection.on);
  EXPECT_EQ(r_off.pick().w_away, 0.2);
  EXPECT_EQ(read_text(dir_off / "best.toml").find("one-sided p"), std::string::npos);
  EXPECT_FALSE(
      nlohmann::json::parse(read_text(dir_off / "run.json")).at("selection").at("keep_base").get<bool>());
}

TEST(BaseSelection, AClearlyBetterFinalistReplacesTheBaseParams) {
  const EvolveConfig c = two_finalists();
  const fs::path dir = scratch("beaten");
  const RunResult r = run_two(c, 0.3, 0.05, dir);  // A: 0.3 +- 0.05 against 0.5 on every pair
  EXPECT_FALSE(r.selection.base_kept);
  EXPECT_LT(r.selection.p_value, 1e-6);
  EXPECT_NEAR(r.selection.mean_difference, 0.2, 1e-12);
  EXPECT_EQ(r.pick().w_away, 0.2);
  const std::string toml = read_text(dir / "best.toml");
  EXPECT_EQ(toml.rfind("# swarmpath evolve: the best candidate of run \"tiny\"", 0), 0u) << toml;
  EXPECT_NE(toml.find("one-sided p = "), std::string::npos) << toml;
  EXPECT_EQ(sim::get_value(sim::load_params((dir / "best.toml").string()), *sim::find_param("w_away")), 0.2);
  const nlohmann::json j = nlohmann::json::parse(read_text(dir / "run.json"));
  EXPECT_FALSE(j.at("selection").at("base_kept").get<bool>());
  EXPECT_FALSE(j.at("best").at("base").get<bool>());
  EXPECT_EQ(j.at("best").at("tuned").at("w_away").get<double>(), 0.2);
}

TEST(BaseSelection, BitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  const EvolveConfig c = testing::tiny("cmaes", 3);
  ASSERT_TRUE(c.reevaluate.keep_base);
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  const nlohmann::json& s = j.at("selection");
  EXPECT_TRUE(s.at("keep_base").get<bool>());
  EXPECT_EQ(s.at("pairs").get<int>(), 2);  // 2 fresh seeds of one setting
  EXPECT_EQ(s.at("base_kept").get<bool>(), s.at("p_value").get<double>() >= s.at("threshold").get<double>());
  EXPECT_EQ(j.at("best").at("base").get<bool>(), s.at("base_kept").get<bool>());
}

TEST(BaseSelection, KeysAreCheckedAndTheDefaultKeepsTheHash) {
  const std::string base = testing::tiny_config();
  testing::expect_error(base + "keep_base_level = 0.7\n", "keep_base_level", "reevaluate.keep_base_level",
                        "must lie in");
  testing::expect_error(base + "keep_base_level = 0.0\n", "keep_base_level", "reevaluate.keep_base_level",
                        "must lie in");
  testing::expect_error(base + "keep_base = \"yes\"\n", "keep_base =", "reevaluate.keep_base", "");
  testing::expect_error(base + "keep_base = false\nkeep_base_level = 0.1\n", "keep_base_level",
                        "reevaluate.keep_base_level", "only with keep_base = true");
  testing::expect_error(
      testing::replaced(testing::tiny_pareto_config(), "[reevaluate]\n", "[reevaluate]\nkeep_base = true\n"),
      "keep_base = true", "reevaluate.keep_base", "multi-objective");
  EXPECT_FALSE(parse_evolve_config(testing::tiny_pareto_config(), "t", "").reevaluate.keep_base);
  // on by default for single-objective runs: the hash names it only when it is not the default
  const EvolveConfig plain = testing::tiny("cmaes", 2);
  EXPECT_TRUE(plain.reevaluate.keep_base);
  EXPECT_EQ(plain.reevaluate.keep_base_level, 0.05);
  const auto with = [&](const std::string& lines) {
    return parse_evolve_config(testing::tiny_config("cmaes", 2) + lines, "t", "");
  };
  EXPECT_EQ(config_hash(plain), config_hash(with("keep_base = true\nkeep_base_level = 0.05\n")));
  EXPECT_NE(config_hash(plain), config_hash(with("keep_base = false\n")));
  EXPECT_NE(config_hash(plain), config_hash(with("keep_base_level = 0.01\n")));
  EXPECT_EQ(with("keep_base_level = 0.01\n").reevaluate.keep_base_level, 0.01);
  // the base params' fresh runs count in the budget only when they may be the pick
  EXPECT_EQ(simulation_budget(plain)->reevaluation, (2 + 1) * 2);
  EXPECT_EQ(simulation_budget(with("keep_base = false\n"))->reevaluation, 2 * 2);
}

}  // namespace
}  // namespace swarmpath::evolve
