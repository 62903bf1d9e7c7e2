// SPDX-License-Identifier: MIT
// make_optimizer: every listed name builds; bad names, settings and problems are refused with
// std::invalid_argument naming the problem; tell() refuses answers to another batch.
#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

/// The message of the std::invalid_argument that make_optimizer throws ("" if none).
std::string refusal(const OptimizerSettings& s, const Bounds& b = test::test_box(),
                    const Vector& x0 = test::far_start()) {
  try {
    make_optimizer(s, b, x0, 1);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

OptimizerSettings with(const std::string& name, void (*edit)(OptimizerSettings&)) {
  OptimizerSettings s = test::settings_named(name);
  edit(s);
  return s;
}

TEST(Factory, EveryListedNameBuilds) {
  for (const auto& name : optimizer_names()) {
    auto opt = make_optimizer(test::settings_named(name), test::test_box(), test::far_start(), 1);
    ASSERT_NE(opt, nullptr);
    EXPECT_EQ(opt->name(), name);
    EXPECT_FALSE(opt->ask().empty()) << name;
  }
  EXPECT_GE(optimizer_names().size(), 10u);
}

TEST(Factory, RejectsUnknownNames) {
  EXPECT_NE(refusal(test::settings_named("simplex")).find("unknown optimizer 'simplex'"), std::string::npos);
  EXPECT_NE(refusal(test::settings_named("nlopt:lbfgs")).find("'lbfgs'"), std::string::npos);
  EXPECT_NE(refusal(test::settings_named("")).find("unknown optimizer"), std::string::npos);
}

TEST(Factory, RejectsBadPopulations) {
  for (const std::string name : {"cmaes", "ga", "random", "nlopt:esch", "nlopt:crs2", "nlopt:isres"}) {
    for (const int population : {1, -3}) {
      OptimizerSettings s = test::settings_named(name);
      s.population = population;
      EXPECT_NE(refusal(s).find("population"), std::string::npos) << name << " population " << population;
    }
  }
  // CRS2 needs at least n + 1 points
  OptimizerSettings crs = test::settings_named("nlopt:crs2");
  crs.population = 5;
  EXPECT_NE(refusal(crs).find("n + 1"), std::string::npos);
  crs.population = 11;
  EXPECT_EQ(refusal(crs), "");
}

TEST(Factory, RejectsBadOptimizerSettings) {
  EXPECT_NE(refusal(with("cmaes", [](auto& s) { s.sigma0 = 0.0; })).find("sigma0"), std::string::npos);
  EXPECT_NE(refusal(with("cmaes", [](auto& s) { s.sigma0 = 2.0; })).find("sigma0"), std::string::npos);
  EXPECT_NE(refusal(with("cmaes", [](auto& s) { s.ipop_restarts = -1; })).find("ipop_restarts"),
            std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.elites = 20; })).find("elites"), std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.elites = -1; })).find("elites"), std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.tournament = 0; })).find("tournament"), std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.crossover_rate = 1.5; })).find("crossover_rate"),
            std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.mutation_rate = -0.1; })).find("mutation_rate"),
            std::string::npos);
  EXPECT_NE(refusal(with("ga", [](auto& s) { s.mutation_sigma = 0.0; })).find("mutation_sigma"),
            std::string::npos);
  EXPECT_NE(refusal(with("nlopt:bobyqa", [](auto& s) { s.max_evaluations = -5; })).find("max_evaluations"),
            std::string::npos);
  EXPECT_NE(refusal(with("nlopt:sbplx", [](auto& s) { s.xtol_rel = -1.0; })).find("xtol_rel"),
            std::string::npos);
}

TEST(Factory, RejectsBadProblems) {
  const auto s = test::settings_named("cmaes");
  Vector outside = test::far_start();
  outside[3] = 7.5;
  EXPECT_NE(refusal(s, test::test_box(), outside).find("x0 outside the bounds at coordinate 3"),
            std::string::npos);
  EXPECT_NE(refusal(s, test::test_box(), Vector(3, 0.0)).find("x0 has dimension 3"), std::string::npos);

  Bounds flat = test::test_box();
  flat.upper[2] = flat.lower[2];
  EXPECT_NE(refusal(s, flat).find("lower < upper, coordinate 2"), std::string::npos);
  Bounds inverted = test::test_box();
  std::swap(inverted.lower[0], inverted.upper[0]);
  EXPECT_NE(refusal(s, inverted, Vector(10, 0.0)).find("lower < upper, coordinate 0"), std::string::npos);
  Bounds ragged = test::test_box();
  ragged.upper.pop_back();
  EXPECT_NE(refusal(s, ragged).find("bounds"), std::string::npos);
  EXPECT_NE(refusal(s, Bounds{}, Vector{}).find("dimension is 0"), std::string::npos);
}

TEST(Factory, TellRefusesAnswersToAnotherBatch) {
  for (const auto& name : optimizer_names()) {
    auto opt = make_optimizer(test::settings_named(name), test::test_box(), test::far_start(), 1);
    EXPECT_THROW(opt->tell({test::far_start()}, {1.0}), std::logic_error) << name << ": tell before ask";
    auto batch = opt->ask();
    EXPECT_THROW(opt->tell(batch, std::vector<double>(batch.size() + 1, 1.0)), std::invalid_argument) << name;
    auto moved = batch;
    moved[0][0] += 0.25;
    EXPECT_THROW(opt->tell(moved, std::vector<double>(batch.size(), 1.0)), std::invalid_argument) << name;
    EXPECT_NO_THROW(opt->tell(batch, std::vector<double>(batch.size(), 1.0))) << name;
  }
}

}  // namespace
}  // namespace swarmpath::evolve
