// SPDX-License-Identifier: MIT
// keep_base_test = "signed-rank": the exact one-sided Wilcoxon signed-rank test (zeros dropped, ties
// at their mean rank), the decision it makes where one failed run hides a finalist's lead from the
// paired t-test, the key's errors and hash, and the files that name it.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/base_selection.hpp"
#include "evolve/racing.hpp"
#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

TEST(SignedRank, ExactPValuesCountTheSignsOfTheRanks) {
  double w = 0.0;
  // all five pairs won: W+ = 15, the largest of 2^5 equally likely sums
  EXPECT_DOUBLE_EQ(signed_rank_p_value(std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0}, &w), 1.0 / 32.0);
  EXPECT_EQ(w, 15.0);
  // the smallest lost: W+ = 14, reached by two sign patterns of 32
  EXPECT_DOUBLE_EQ(signed_rank_p_value(std::vector<double>{-1.0, 2.0, 3.0, 4.0, 5.0}, &w), 2.0 / 32.0);
  EXPECT_EQ(w, 14.0);
  // zero differences are dropped
  EXPECT_DOUBLE_EQ(signed_rank_p_value(std::vector<double>{0.0, 1.0, 0.0, 2.0, 3.0, 4.0, 5.0}), 1.0 / 32.0);
  // three tied sizes share rank 2: W+ = 4 with two of three won, P(two or three won) = 4 / 8
  EXPECT_DOUBLE_EQ(signed_rank_p_value(std::vector<double>{0.5, 0.5, -0.5}, &w), 0.5);
  EXPECT_EQ(w, 4.0);
  // nothing left to test
  EXPECT_EQ(signed_rank_p_value(std::vector<double>{}), 1.0);
  EXPECT_EQ(signed_rank_p_value(std::vector<double>{0.0, 0.0}), 1.0);
  // every pair lost: W+ = 0, always reached
  EXPECT_DOUBLE_EQ(signed_rank_p_value(std::vector<double>{-1.0, -2.0}), 1.0);
}

// 17 pairs won by about 0.1 and one failed run lost by 3: the t-test sees a negative mean, the
// ranks a finalist that won all but one pair (P(W- <= 18) over 2^18 sign patterns = 253 / 262 144)
std::vector<double> one_failed_run() {
  std::vector<double> d;
  for (int k = 0; k < 17; ++k) d.push_back(0.1 + 0.001 * k);
  d.push_back(-3.0);
  return d;
}

TEST(SignedRank, OneFailedRunLosesOnePairNotTheTest) {
  const std::vector<double> d = one_failed_run();
  EXPECT_GT(paired_t_p_value(d), 0.5);
  EXPECT_NEAR(signed_rank_p_value(d), 253.0 / 262144.0, 1e-15);
  const std::vector<double> base(d.size(), 1.0);
  std::vector<double> finalist;
  for (const double v : d) finalist.push_back(1.0 - v);
  const BaseSelection t = select_against_base(finalist, base, 2, 0.05);
  EXPECT_EQ(t.test, KeepBaseTest::kPairedT);
  EXPECT_TRUE(t.base_kept);
  const BaseSelection rank = select_against_base(finalist, base, 2, 0.05, KeepBaseTest::kSignedRank);
  EXPECT_EQ(rank.test, KeepBaseTest::kSignedRank);
  EXPECT_FALSE(rank.base_kept);  // 0.00097 < 0.05 / 2
  EXPECT_EQ(rank.w_plus, 153.0);
  EXPECT_EQ(rank.pairs, 18);
  EXPECT_NEAR(rank.mean_difference, t.mean_difference, 1e-15);  // the same pairs, reported alike
  // a finalist worse on most pairs never replaces the base params by its ranks either
  EXPECT_TRUE(select_against_base(base, finalist, 1, 0.5, KeepBaseTest::kSignedRank).base_kept);
}

TEST(SignedRank, TheNormalApproximationBeyondTheExactCountAgreesWithIt) {
  // sizes 1..n, the pairs of size divisible by 3 lost: exact at n = kExactSignedRankPairs, the normal
  // approximation one pair later; a third lost is far from both tails, so the two p-values are close
  const auto p_at = [](std::size_t n) {
    std::vector<double> d;
    for (std::size_t k = 1; k <= n; ++k) d.push_back(static_cast<double>(k) * (k % 3 == 0 ? -1.0 : 1.0));
    return signed_rank_p_value(d);
  };
  const double exact = p_at(kExactSignedRankPairs), approx = p_at(kExactSignedRankPairs + 1);
  EXPECT_GT(exact, 0.0);
  EXPECT_LT(exact, 1.0);
  EXPECT_NEAR(approx, exact, 0.02);
}

TEST(SignedRank, EachTestsNameParsesBackToItAndNoOtherNameDoes) {
  EXPECT_EQ(keep_base_test_name(KeepBaseTest::kPairedT), "t");
  EXPECT_EQ(keep_base_test_name(KeepBaseTest::kSignedRank), "signed-rank");
  for (const KeepBaseTest t : {KeepBaseTest::kPairedT, KeepBaseTest::kSignedRank})
    EXPECT_EQ(parse_keep_base_test(keep_base_test_name(t)), t);
  EXPECT_FALSE(parse_keep_base_test("wilcoxon").has_value());
  EXPECT_FALSE(parse_keep_base_test("").has_value());
}

TEST(SignedRank, TheKeyIsCheckedAndTheTTestKeepsTheHash) {
  const std::string base = testing::tiny_config();
  testing::expect_error(base + "keep_base_test = \"wilcoxon\"\n", "keep_base_test",
                        "reevaluate.keep_base_test", "choices: t, signed-rank");
  testing::expect_error(base + "keep_base = false\nkeep_base_test = \"signed-rank\"\n", "keep_base_test",
                        "reevaluate.keep_base_test", "only with keep_base = true");
  const auto with = [&](const std::string& lines) {
    return parse_evolve_config(testing::tiny_config("cmaes", 2) + lines, "t", "");
  };
  const EvolveConfig plain = testing::tiny("cmaes", 2);
  EXPECT_EQ(plain.reevaluate.keep_base_test, KeepBaseTest::kPairedT);
  EXPECT_EQ(config_hash(plain), config_hash(with("keep_base_test = \"t\"\n")));
  const EvolveConfig rank = with("keep_base_test = \"signed-rank\"\n");
  EXPECT_EQ(rank.reevaluate.keep_base_test, KeepBaseTest::kSignedRank);
  EXPECT_NE(config_hash(plain), config_hash(rank));
}

TEST(SignedRank, TheFilesNameTheTestAndTheRunIsBitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  EvolveConfig c = testing::tiny("cmaes", 3);
  c.reevaluate.seeds = 6;  // 6 pairs: the smallest p is 1/64
  c.reevaluate.keep_base_test = KeepBaseTest::kSignedRank;
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  const nlohmann::json& s = j.at("selection");
  EXPECT_EQ(s.at("test").get<std::string>(), "signed-rank");
  EXPECT_EQ(s.at("pairs").get<int>(), 6);
  EXPECT_GE(s.at("w_plus").get<double>(), 0.0);
  EXPECT_LE(s.at("w_plus").get<double>(), 21.0);  // 1 + ... + 6
  EXPECT_GE(s.at("p_value").get<double>(), 1.0 / 64.0);
  EXPECT_EQ(s.at("base_kept").get<bool>(), s.at("p_value").get<double>() >= s.at("threshold").get<double>());
}

}  // namespace
}  // namespace swarmpath::evolve
