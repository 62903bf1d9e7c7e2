// SPDX-License-Identifier: MIT
// The objectives of a multi-objective run and their 95 % intervals, against hand-computed values.
#include "evolve/pareto_objectives.hpp"

#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace swarmpath::evolve {
namespace {

RunScore run(bool success, double ticks, double path, double fraction) {
  RunScore r;
  r.success = success;
  r.ticks = ticks;
  r.path_ratio = success ? path : std::nan("");
  r.robots_fraction = fraction;
  return r;
}

const std::vector<ObjectiveKind> kAll = {ObjectiveKind::kPathRatio, ObjectiveKind::kTicks,
                                         ObjectiveKind::kRobotsFraction};

TEST(ParetoObjectives, NamesRoundTrip) {
  for (const ObjectiveKind k : kAll) EXPECT_EQ(parse_objective(objective_name(k)), k);
  EXPECT_FALSE(parse_objective("time").has_value());
}

TEST(ParetoObjectives, ValuesFollowTheRunsConventions) {
  // two successes (path 1.1 and 1.3, 1000 and 2000 ticks, 20 % and 40 % of the robots), one failure
  // (censored at 3000 ticks, every robot used)
  const std::vector<RunScore> runs = {run(true, 1000, 1.1, 0.2), run(true, 2000, 1.3, 0.4),
                                      run(false, 3000, 0, 1.0)};
  const CandidateStats s = summarise(runs);
  const Vector v = objective_values(s, kAll, 3.0);
  EXPECT_DOUBLE_EQ(v[0], 1.2);     // over the successful runs only
  EXPECT_DOUBLE_EQ(v[1], 2000.0);  // (1000 + 2000 + 3000) / 3
  EXPECT_DOUBLE_EQ(v[2], (0.2 + 0.4 + 1.0) / 3.0);
  // the means of the intervals are the objective values, bit for bit
  const std::vector<Interval> in = objective_intervals(runs, kAll, 3.0);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(in[k].mean, v[k]) << k;
  EXPECT_EQ(in[0].n, 2);
  EXPECT_EQ(in[1].n, 3);
  // no success: the path is the stated failure ratio, with an unbounded interval
  const std::vector<RunScore> failed = {run(false, 3000, 0, 1.0)};
  EXPECT_DOUBLE_EQ(objective_values(summarise(failed), kAll, 2.5)[0], 2.5);
  const Interval none = objective_intervals(failed, kAll, 2.5)[0];
  EXPECT_EQ(none.mean, 2.5);
  EXPECT_EQ(none.n, 0);
  EXPECT_TRUE(std::isinf(none.half_width));
  // the order of use is the order of the vector
  EXPECT_EQ(objective_values(s, {ObjectiveKind::kRobotsFraction, ObjectiveKind::kTicks}, 3.0),
            (Vector{v[2], v[1]}));
}

TEST(ParetoObjectives, IntervalIsStudentsTByHand) {
  // ticks 100, 200, 300: mean 200, s = 100, t(0.975, 2) = 4.302653 -> half width 248.4138
  const std::vector<RunScore> runs = {run(true, 100, 1, 0.5), run(true, 200, 1, 0.5), run(true, 300, 1, 0.5)};
  const Interval i = objective_intervals(runs, {ObjectiveKind::kTicks}, 3.0)[0];
  EXPECT_DOUBLE_EQ(i.mean, 200.0);
  EXPECT_NEAR(i.half_width, 4.302653 * 100.0 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(i.lower(), 200.0 - 248.4138, 1e-3);
  // equal values: zero width
  EXPECT_EQ(objective_intervals(runs, {ObjectiveKind::kRobotsFraction}, 3.0)[0].half_width, 0.0);
}

TEST(ParetoObjectives, PairedDifferencesByHand) {
  // a is 100 ticks faster on every seed although the seeds spread the ticks widely
  const std::vector<RunScore> a = {run(true, 900, 1.0, 0.5), run(true, 4900, 1.2, 0.5),
                                   run(false, 2900, 0, 1.0)};
  const std::vector<RunScore> b = {run(true, 1000, 1.1, 0.6), run(false, 5000, 0, 1.0),
                                   run(true, 3000, 1.0, 0.7)};
  const std::vector<Interval> d = paired_differences(a, b, kAll);
  // path: only seed 0 has both successes -> -0.1, one pair, unbounded
  EXPECT_NEAR(d[0].mean, -0.1, 1e-12);
  EXPECT_EQ(d[0].n, 1);
  EXPECT_TRUE(std::isinf(d[0].half_width));
  // ticks: -100 on every seed -> exactly -100 +- 0, while the unpaired interval is thousands wide
  EXPECT_EQ(d[1].mean, -100.0);
  EXPECT_EQ(d[1].half_width, 0.0);
  EXPECT_GT(objective_intervals(a, kAll, 3.0)[1].half_width, 1000.0);
  // robots: -0.1, -0.5, +0.3 -> mean -0.1, s = 0.4, half width t(2) 0.4 / sqrt 3
  EXPECT_NEAR(d[2].mean, -0.1, 1e-12);
  EXPECT_NEAR(d[2].half_width, 4.302653 * 0.4 / std::sqrt(3.0), 1e-9);
  EXPECT_THROW(paired_differences(a, std::span<const RunScore>(b).first(2), kAll), std::invalid_argument);
}

TEST(ParetoObjectives, TQuantileMatchesTablesAndTheNormalLimit) {
  EXPECT_NEAR(t_quantile_975(1), 12.7062, 1e-4);
  EXPECT_NEAR(t_quantile_975(9), 2.2622, 1e-4);
  EXPECT_NEAR(t_quantile_975(40), 2.0211, 1e-4);   // expansion (tables: 2.021075)
  EXPECT_NEAR(t_quantile_975(60), 2.0003, 1e-4);   // 2.000298
  EXPECT_NEAR(t_quantile_975(120), 1.9799, 1e-4);  // 1.979930
  EXPECT_NEAR(t_quantile_975(1000000), 1.959964, 1e-5);
  // the table and the expansion meet smoothly, and the quantile falls with df
  EXPECT_GT(t_quantile_975(30), t_quantile_975(31));
  EXPECT_LT(t_quantile_975(30) - t_quantile_975(31), 0.004);
  EXPECT_TRUE(std::isinf(t_quantile_975(0)));
}

TEST(ParetoObjectives, ViolationIsTheShortfallInSuccessRate) {
  CandidateStats s;
  s.success_rate = 0.5;
  EXPECT_DOUBLE_EQ(success_violation(s, 0.8, false), 0.3);
  EXPECT_EQ(success_violation(s, 0.5, false), 0.0);
  EXPECT_EQ(success_violation(s, 0.2, false), 0.0);
  // a candidate never simulated (success 0) is worse than any simulated one, the worst included
  const CandidateStats none;
  for (const double m : {0.0, 0.5, 1.0})
    EXPECT_GT(success_violation(none, m, true), success_violation(none, m, false));
  EXPECT_EQ(success_violation(none, 0.0, true), 1.0);
}

}  // namespace
}  // namespace swarmpath::evolve
