// SPDX-License-Identifier: MIT
// Every optimiser: the seed fixes the candidate sequence bit for bit, and candidates stay in the bounds.
#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

class EveryOptimizer : public testing::TestWithParam<std::string> {};

OptimizerSettings settings_for(const std::string& name) {
  OptimizerSettings s = test::settings_named(name);
  s.ipop_restarts = 2;
  return s;
}

TEST_P(EveryOptimizer, SameSeedSameCandidates) {
  const auto s = settings_for(GetParam());
  auto a = make_optimizer(s, test::test_box(), test::far_start(), 11);
  auto b = make_optimizer(s, test::test_box(), test::far_start(), 11);
  const int rounds = test::rounds_for(GetParam(), 300);
  const auto ca = test::candidates_of(*a, test::rosenbrock, rounds);
  const auto cb = test::candidates_of(*b, test::rosenbrock, rounds);
  ASSERT_GE(ca.size(), 100u);
  EXPECT_TRUE(test::bit_identical(ca, cb));
  EXPECT_EQ(a->best_f(), b->best_f());
}

TEST_P(EveryOptimizer, DifferentSeedsDifferUnlessDeterministic) {
  const auto s = settings_for(GetParam());
  auto a = make_optimizer(s, test::test_box(), test::far_start(), 11);
  auto b = make_optimizer(s, test::test_box(), test::far_start(), 12);
  const int rounds = test::rounds_for(GetParam(), 300);
  const auto ca = test::candidates_of(*a, test::rosenbrock, rounds);
  const auto cb = test::candidates_of(*b, test::rosenbrock, rounds);
  if (test::uses_randomness(GetParam())) {
    EXPECT_FALSE(test::bit_identical(ca, cb));
  } else {
    EXPECT_TRUE(test::bit_identical(ca, cb)) << "a deterministic algorithm depends on the seed";
  }
}

TEST_P(EveryOptimizer, CandidatesStayInsideTheBounds) {
  // the optimum (-20, 20, -20, ...) lies outside the box, so the search presses against its faces
  const auto corner_seeker = [](const Vector& x) {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double d = x[i] - (i % 2 == 0 ? -20.0 : 20.0);
      s += d * d;
    }
    return s;
  };
  const Bounds box = test::test_box();
  auto opt = make_optimizer(settings_for(GetParam()), box, test::far_start(), 5);
  const auto all = test::candidates_of(*opt, corner_seeker, test::rounds_for(GetParam(), 600));
  ASSERT_FALSE(all.empty());
  for (const auto& x : all) {
    ASSERT_EQ(x.size(), box.dim());
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_GE(x[i], box.lower[i]);
      ASSERT_LE(x[i], box.upper[i]);
    }
  }
  // and it got near the corner it seeks: (-3, 7, -3, ...) gives 5 * 17^2 + 5 * 13^2 = 2290
  EXPECT_LT(opt->best_f(), 2290.0 * 1.5) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Optim, EveryOptimizer, testing::ValuesIn(optimizer_names()),
                         [](const testing::TestParamInfo<std::string>& param_info) {
                           return test::param_name(param_info.param);
                         });

}  // namespace
}  // namespace swarmpath::evolve
