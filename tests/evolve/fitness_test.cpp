// SPDX-License-Identifier: MIT
// The fitness of a run: each term as documented, failures censored (never missing), and the
// candidate summary.
#include "evolve/fitness.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace swarmpath::evolve {
namespace {

sim::Metrics success(std::int64_t ticks, double path_tu, int path_robots, int allocated = -1) {
  sim::Metrics m;
  m.success = true;
  m.ticks = ticks;
  m.ticks_to_form = ticks;
  m.path_length_tu = path_tu;
  m.path_robots = path_robots;
  m.allocated = allocated;
  return m;
}

TEST(Fitness, SuccessfulRunAddsItsWeightedTerms) {
  const CaseInfo c{1000, 100.0, 10, sim::Mode::kPathFormation};
  const FitnessWeights w{1.0, 1.0, 1.0, 1.0, 3.0};
  const RunScore s = score_run(success(500, 120.0, 6), c, w);
  EXPECT_TRUE(s.success);
  EXPECT_DOUBLE_EQ(s.fitness, 0.5 + 1.2 + 0.6);
  EXPECT_DOUBLE_EQ(s.path_ratio, 1.2);
  EXPECT_EQ(s.ticks, 500.0);
  EXPECT_EQ(s.robots_used, 6.0);
  const FitnessWeights time_only{5.0, 2.0, 0.0, 0.0, 3.0};
  EXPECT_DOUBLE_EQ(score_run(success(500, 120.0, 6), c, time_only).fitness, 1.0);
}

TEST(Fitness, FailureIsACensoredTimeNotAMissingValue) {
  const CaseInfo c{1000, 100.0, 10, sim::Mode::kPathFormation};
  const FitnessWeights w{2.0, 1.0, 0.5, 0.25, 3.0};
  sim::Metrics m;  // never formed: ticks_to_form -1, path NaN, path_robots 0
  m.ticks = 1000;
  const RunScore s = score_run(m, c, w);
  EXPECT_FALSE(s.success);
  EXPECT_EQ(s.ticks, 1000.0);
  EXPECT_TRUE(std::isfinite(s.fitness));
  EXPECT_DOUBLE_EQ(s.fitness, 2.0 + 1.0 + 0.5 * 3.0 + 0.25 * 1.0);
  EXPECT_EQ(s.fitness, penalty_score(c, w).fitness);
  // worse than the slowest, longest success within the censoring ratio
  EXPECT_GT(s.fitness, score_run(success(1000, 300.0, 10), c, w).fitness);
}

TEST(Fitness, RobotsUsedFollowTheMode) {
  const FitnessWeights w{0.0, 0.0, 0.0, 1.0, 3.0};
  const sim::Metrics m = success(100, 100.0, 5, 20);
  EXPECT_DOUBLE_EQ(score_run(m, {1000, 100.0, 40, sim::Mode::kPathFormation}, w).fitness, 5.0 / 40.0);
  EXPECT_DOUBLE_EQ(score_run(m, {1000, 100.0, 40, sim::Mode::kTaskAllocation}, w).fitness, 20.0 / 40.0);
  // a failed task-allocation run used the robots it allocated (the fitness stays the penalty);
  // one that never allocated, and a failed path-formation run, used all N
  sim::Metrics failed;
  failed.ticks = 1000;
  failed.allocated = 12;
  const CaseInfo ta{1000, 100.0, 40, sim::Mode::kTaskAllocation};
  const RunScore f = score_run(failed, ta, w);
  EXPECT_EQ(f.robots_used, 12.0);
  EXPECT_DOUBLE_EQ(f.robots_fraction, 12.0 / 40.0);
  EXPECT_EQ(f.fitness, penalty_score(ta, w).fitness);
  EXPECT_EQ(score_run(failed, {1000, 100.0, 40, sim::Mode::kPathFormation}, w).robots_used, 40.0);
  failed.allocated = -1;
  EXPECT_EQ(score_run(failed, ta, w).robots_fraction, 1.0);
  // scouts that formed the chain before the founder allocated are used robots too
  EXPECT_DOUBLE_EQ(score_run(success(100, 100.0, 17, 3), ta, w).robots_used, 17.0);
}

TEST(Fitness, UnknownPathLengthCountsThePenaltyRatio) {
  const FitnessWeights w{0.0, 0.0, 1.0, 0.0, 3.0};
  const RunScore s =
      score_run(success(100, 120.0, 5), {1000, std::nan(""), 10, sim::Mode::kPathFormation}, w);
  EXPECT_TRUE(s.success);
  EXPECT_DOUBLE_EQ(s.fitness, 3.0);
}

TEST(Fitness, SummaryMeansPathsOverSuccessesOnly) {
  const CaseInfo c{1000, 100.0, 10, sim::Mode::kPathFormation};
  const FitnessWeights w{1.0, 1.0, 1.0, 0.0, 3.0};
  sim::Metrics fail;
  const std::vector<RunScore> runs = {score_run(success(200, 110.0, 4), c, w), score_run(fail, c, w),
                                      score_run(success(400, 130.0, 6), c, w)};
  const CandidateStats st = summarise(runs);
  EXPECT_EQ(st.runs, 3);
  EXPECT_DOUBLE_EQ(st.success_rate, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(st.mean_ticks, (200.0 + 1000.0 + 400.0) / 3.0);
  EXPECT_DOUBLE_EQ(st.mean_path_ratio, 1.2);
  EXPECT_DOUBLE_EQ(st.fitness, (runs[0].fitness + runs[1].fitness + runs[2].fitness) / 3.0);
  EXPECT_TRUE(std::isnan(summarise(std::vector<RunScore>{score_run(fail, c, w)}).mean_path_ratio));
}

}  // namespace
}  // namespace swarmpath::evolve
