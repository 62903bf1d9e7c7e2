// SPDX-License-Identifier: MIT
// GA specifics: x0 in the first generation, batch sizes, elitism.
#include <algorithm>

#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

TEST(Ga, FirstGenerationHoldsX0ThenChildrenReplaceAllButTheElites) {
  OptimizerSettings s = test::settings_named("ga");
  s.elites = 2;
  auto opt = make_optimizer(s, test::test_box(), test::classic_start(), 1);
  auto batch = opt->ask();
  ASSERT_EQ(batch.size(), 20u);
  EXPECT_EQ(batch[0], test::classic_start());
  opt->tell(batch, std::vector<double>(batch.size(), 1.0));
  EXPECT_EQ(opt->ask().size(), 18u);
}

TEST(Ga, ElitismNeverLosesThePopulationsBest) {
  OptimizerSettings s = test::settings_named("ga");
  s.mutation_sigma = 0.3;  // disruptive: without elites the population's best would drift up
  auto opt = make_optimizer(s, test::test_box(), test::far_start(), 2);
  double previous = INFINITY;
  for (int generation = 0; generation < 100; ++generation) {
    test::candidates_of(*opt, test::rosenbrock, 1);
    const auto fitness = opt->state().at("fitness").get<std::vector<double>>();
    const double best = *std::min_element(fitness.begin(), fitness.end());
    EXPECT_LE(best, previous) << "generation " << generation;
    EXPECT_EQ(best, opt->best_f());
    previous = best;
  }
}

TEST(Ga, WithoutElitesThePopulationsBestCanGetWorse) {
  // the counterpart of the test above, so that it can be seen to test something
  OptimizerSettings s = test::settings_named("ga");
  s.mutation_sigma = 0.3;
  s.elites = 0;
  auto opt = make_optimizer(s, test::test_box(), test::far_start(), 2);
  double previous = INFINITY;
  bool worsened = false;
  for (int generation = 0; generation < 100; ++generation) {
    test::candidates_of(*opt, test::rosenbrock, 1);
    const auto fitness = opt->state().at("fitness").get<std::vector<double>>();
    const double best = *std::min_element(fitness.begin(), fitness.end());
    worsened = worsened || best > previous;
    previous = best;
  }
  EXPECT_TRUE(worsened);
}

}  // namespace
}  // namespace swarmpath::evolve
