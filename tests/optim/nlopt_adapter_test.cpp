// SPDX-License-Identifier: MIT
// The NLopt adapter: one candidate per ask, NLopt's own stopping, the replay determinism check.
#include "evolve/optim/nlopt_adapter.hpp"

#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

TEST(NloptAdapter, AsksOneCandidateStartingAtX0ForLocalAlgorithms) {
  for (const std::string name : {"nlopt:bobyqa", "nlopt:sbplx", "nlopt:neldermead"}) {
    // 2 maps to 0.5 and back exactly; BOBYQA would move a start nearer than sigma0 to a bound
    const Vector x0(test::kDim, 2.0);
    auto opt = make_optimizer(test::settings_named(name), test::test_box(), x0, 1);
    const auto batch = opt->ask();
    ASSERT_EQ(batch.size(), 1u);
    EXPECT_EQ(batch[0], x0) << name;
  }
}

TEST(NloptAdapter, DoneWhenNloptConverges) {
  auto opt = make_optimizer(test::settings_named("nlopt:bobyqa"), test::test_box(), test::far_start(), 1);
  const auto r = test::run(*opt, test::sphere, 2000);
  EXPECT_TRUE(opt->done());
  EXPECT_LT(r.evaluations, 200);  // measured: 46
  EXPECT_LT(opt->best_f(), 1e-20);
  EXPECT_EQ(dynamic_cast<const NloptAdapter&>(*opt).result(), "xtol_reached");
  EXPECT_THROW(opt->ask(), std::logic_error);
}

TEST(NloptAdapter, DoneAfterMaxEvaluations) {
  OptimizerSettings s = test::settings_named("nlopt:sbplx");
  s.max_evaluations = 50;
  auto opt = make_optimizer(s, test::test_box(), test::far_start(), 1);
  const auto r = test::run(*opt, test::rosenbrock, 1000);
  EXPECT_TRUE(opt->done());
  EXPECT_EQ(r.evaluations, 50);
  EXPECT_EQ(dynamic_cast<const NloptAdapter&>(*opt).result(), "maxeval_reached");
}

TEST(NloptAdapter, ReplayThatDivergesFromTheHistoryThrows) {
  auto opt = make_optimizer(test::settings_named("nlopt:crs2"), test::test_box(), test::far_start(), 1);
  test::candidates_of(*opt, test::sphere, 30);
  auto state = opt->state();
  state["history"][10]["x"][4] = 0.123;  // not what NLopt asks for at evaluation 11
  auto fresh = make_optimizer(test::settings_named("nlopt:crs2"), test::test_box(), test::far_start(), 1);
  try {
    fresh->restore(state);
    FAIL() << "restore of a tampered history succeeded";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("diverged at evaluation 11"), std::string::npos) << e.what();
  }
}

TEST(NloptAdapter, PopulationReachesTheAlgorithm) {
  // CRS2 starts with a random population: its size changes when the next population begins
  auto sequence = [](int population) {
    OptimizerSettings s = test::settings_named("nlopt:crs2");
    s.population = population;
    auto opt = make_optimizer(s, test::test_box(), test::far_start(), 1);
    return test::candidates_of(*opt, test::sphere, 40);
  };
  const auto by_default = sequence(0);  // NLopt's 10 (n + 1) = 110
  const auto small = sequence(11);
  ASSERT_EQ(by_default.size(), small.size());
  // the first 11 points are drawn alike; after that the small population is full and CRS2 starts its steps
  EXPECT_TRUE(test::bit_identical({by_default.begin(), by_default.begin() + 11},
                                  {small.begin(), small.begin() + 11}));
  EXPECT_FALSE(test::bit_identical(by_default, small));
}

}  // namespace
}  // namespace swarmpath::evolve
