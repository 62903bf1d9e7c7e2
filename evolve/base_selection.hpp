// SPDX-License-Identifier: MIT
// Keeping the base params ([reevaluate] keep_base, the default of single-objective runs): the base
// params run the finalists' fresh cases (common random numbers), and the pick is the base params
// unless the best finalist (lowest mean there) beats them by a one-sided paired t-test on those
// runs. The best of k finalists is chosen on the same runs it is tested on, so the test runs at
// keep_base_level / k (Bonferroni): when no finalist is better than the base params, the chance
// that one replaces them is at most keep_base_level. A tuner whose best candidates are chosen
// partly by luck then returns its start rather than something worse than it. With
// keep_base_test = "signed-rank" the test is an exact one-sided Wilcoxon signed-rank test on the
// same pairs: it weighs their ranks, not their sizes, so that one failed run among them (a pair
// that differs by ten times the rest) is one pair lost, not the whole test.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace swarmpath::evolve {

/// keep_base's test of the best finalist against the base params.
enum class KeepBaseTest {
  kPairedT,     ///< one-sided paired Student t-test ("t", the default)
  kSignedRank,  ///< exact one-sided Wilcoxon signed-rank test ("signed-rank")
};

/// The test's name in evolve configs and in JSON ("t", "signed-rank").
std::string_view keep_base_test_name(KeepBaseTest t);

/// The test a name stands for; nullopt when none does.
std::optional<KeepBaseTest> parse_keep_base_test(std::string_view name);

/// The test of the best finalist against the base params, and its outcome.
struct BaseSelection {
  bool on = false;               ///< keep_base was in force
  bool base_kept = false;        ///< the pick is the base params
  std::size_t finalist = 0;      ///< the finalist tested: the best by its fresh-case mean
  int finalists = 0;             ///< the finalists it was chosen from (k)
  double level = 0.0;            ///< keep_base_level
  double threshold = 0.0;        ///< level / k: a p-value below it replaces the base params
  int pairs = 0;                 ///< paired runs (the training cases both ran)
  double mean_difference = 0.0;  ///< base minus finalist, mean over the pairs (> 0: the finalist is better)
  double sd_difference = 0.0;    ///< its standard deviation (n - 1)
  double t = 0.0;                ///< mean / (sd / sqrt(n)); 0 when sd is 0
  double p_value = 1.0;          ///< one-sided: the finalist is better (1 with fewer than 2 pairs)
  KeepBaseTest test = KeepBaseTest::kPairedT;  ///< the test whose p-value this is
  double w_plus =
      0.0;  ///< signed-rank: the sum of the ranks of the pairs the finalist won (ties: mean ranks)
};

/// Pairs up to which signed_rank_p_value counts exactly (n^3 steps); beyond, a normal approximation.
inline constexpr std::size_t kExactSignedRankPairs = 400;

/// One-sided p-value of a Wilcoxon signed-rank test that the differences `d` lie above 0: zero
/// differences are dropped, tied sizes share their mean rank, and p = P(W+ >= the observed W+) over
/// the 2^n equally likely signs (exact up to kExactSignedRankPairs non-zero differences, by counting
/// sums of doubled ranks; 1 when none is left). `w_plus`, when given, receives the observed W+.
double signed_rank_p_value(std::span<const double> d, double* w_plus = nullptr);

/// Tests `finalist`'s fresh-case fitness against `base`'s, case by case (equal lengths, the same
/// cases in the same order); `finalists` = k, `level` = keep_base_level.
BaseSelection select_against_base(std::span<const double> finalist, std::span<const double> base,
                                  int finalists, double level, KeepBaseTest test = KeepBaseTest::kPairedT);

}  // namespace swarmpath::evolve
