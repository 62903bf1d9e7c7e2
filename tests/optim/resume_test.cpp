// SPDX-License-Identifier: MIT
// Exact resume: state() -> JSON text -> parse -> restore() into a fresh optimiser (made with
// another seed) continues with the very candidates an uninterrupted run asks for.
#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

class Resume : public testing::TestWithParam<std::string> {};

OptimizerSettings settings_for(const std::string& name) {
  OptimizerSettings s = test::settings_named(name);
  s.ipop_restarts = 2;
  return s;
}

/// A fresh optimiser of the same kind, restored from the text of `from`'s state.
std::unique_ptr<Optimizer> resumed(const Optimizer& from, const OptimizerSettings& s) {
  const std::string text = from.state().dump();
  auto fresh = make_optimizer(s, test::test_box(), test::far_start(), 999);
  fresh->restore(nlohmann::json::parse(text));
  return fresh;
}

std::vector<Vector> concat(std::vector<Vector> a, const std::vector<Vector>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST_P(Resume, AfterTellContinuesBitIdentically) {
  const auto s = settings_for(GetParam());
  // NLopt replays its history on every tell, so it gets fewer evaluations (the cost grows as N^2)
  const int rounds = test::is_nlopt(GetParam()) ? 150 : 40;
  auto whole = make_optimizer(s, test::test_box(), test::far_start(), 3);
  const auto expected = test::candidates_of(*whole, test::rosenbrock, rounds);
  ASSERT_FALSE(expected.empty());
  for (const int split : {0, 1, rounds / 3}) {
    auto first = make_optimizer(s, test::test_box(), test::far_start(), 3);
    const auto head = test::candidates_of(*first, test::rosenbrock, split);
    auto second = resumed(*first, s);
    EXPECT_EQ(second->best_f(), first->best_f());
    EXPECT_EQ(second->best_x(), first->best_x());
    const auto tail = test::candidates_of(*second, test::rosenbrock, rounds - split);
    EXPECT_TRUE(test::bit_identical(concat(head, tail), expected)) << "split after " << split << " rounds";
    EXPECT_EQ(second->best_f(), whole->best_f());
  }
}

TEST_P(Resume, BetweenAskAndTellAsksTheSameBatchAgain) {
  const auto s = settings_for(GetParam());
  auto whole = make_optimizer(s, test::test_box(), test::far_start(), 4);
  const auto expected = test::candidates_of(*whole, test::sphere, 6);

  auto first = make_optimizer(s, test::test_box(), test::far_start(), 4);
  auto head = test::candidates_of(*first, test::sphere, 3);
  const auto pending = first->ask();
  auto second = resumed(*first, s);
  EXPECT_TRUE(test::bit_identical(second->ask(), pending));
  const auto tail = test::candidates_of(*second, test::sphere, 3);
  EXPECT_TRUE(test::bit_identical(concat(head, tail), expected));
}

TEST_P(Resume, RejectsAnotherOptimizersState) {
  auto a = make_optimizer(settings_for(GetParam()), test::test_box(), test::far_start(), 1);
  const std::string other = GetParam() == "random" ? "ga" : "random";
  auto b = make_optimizer(test::settings_named(other), test::test_box(), test::far_start(), 1);
  EXPECT_THROW(a->restore(b->state()), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Optim, Resume, testing::ValuesIn(optimizer_names()),
                         [](const testing::TestParamInfo<std::string>& param_info) {
                           return test::param_name(param_info.param);
                         });

}  // namespace
}  // namespace swarmpath::evolve
