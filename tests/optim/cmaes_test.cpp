// SPDX-License-Identifier: MIT
// CMA-ES specifics: the default population, IPOP restarts, termination, resume across a restart.
#include "evolve/optim/cmaes.hpp"

#include <gtest/gtest.h>

#include "optim_test_support.hpp"

namespace swarmpath::evolve {
namespace {

Bounds unit_box(std::size_t n) { return {Vector(n, 0.0), Vector(n, 1.0)}; }

TEST(Cmaes, DefaultPopulationIsFourPlusThreeLogN) {
  for (const auto& [n, lambda] : {std::pair{1u, 4u}, {2u, 6u}, {10u, 10u}, {30u, 14u}, {100u, 17u}}) {
    auto opt = make_optimizer(test::settings_named("cmaes"), unit_box(n), Vector(n, 0.5), 1);
    EXPECT_EQ(opt->ask().size(), lambda) << "n = " << n;
  }
  OptimizerSettings s = test::settings_named("cmaes");
  s.population = 7;
  EXPECT_EQ(make_optimizer(s, unit_box(3), Vector(3, 0.5), 1)->ask().size(), 7u);
}

TEST(Cmaes, ConstantsFollowTheTutorial) {
  // n = 10, lambda = 10: mu = 5, mu_eff = 3.1672 (Hansen 2016, Table 1 and eqs. 49-58)
  const CmaesConstants k = CmaesConstants::make(10, 10);
  EXPECT_EQ(k.mu, 5u);
  EXPECT_NEAR(k.weights.sum(), 1.0, 1e-15);
  EXPECT_NEAR(k.mueff, 3.1672, 1e-4);
  EXPECT_NEAR(k.cs, (k.mueff + 2.0) / (10.0 + k.mueff + 5.0), 1e-15);
  EXPECT_NEAR(k.c1, 2.0 / (11.3 * 11.3 + k.mueff), 1e-15);
  EXPECT_NEAR(k.chi_n, std::sqrt(10.0) * (1.0 - 1.0 / 40.0 + 1.0 / 2100.0), 1e-15);
  EXPECT_GT(k.weights[0], k.weights[4]);
}

TEST(Cmaes, IpopRestartEscapesTheRosenbrockLocalMinimum) {
  // seed 5 from the far start converges to the local minimum f = 3.99 without restarts
  OptimizerSettings s = test::settings_named("cmaes");
  auto trapped = make_optimizer(s, test::test_box(), test::far_start(), 5);
  const auto r0 = test::run(*trapped, test::rosenbrock, 30000, 1e-6);
  EXPECT_TRUE(trapped->done());
  EXPECT_FALSE(r0.reached);
  EXPECT_NEAR(r0.best_f, 3.99, 0.05);

  s.ipop_restarts = 9;
  auto ipop = make_optimizer(s, test::test_box(), test::far_start(), 5);
  const auto r1 = test::run(*ipop, test::rosenbrock, 30000, 1e-6);
  EXPECT_TRUE(r1.reached) << "best " << r1.best_f << " after " << r1.evaluations;
  const auto state = ipop->state();
  EXPECT_GE(state.at("restarts").get<int>(), 1);
  EXPECT_EQ(state.at("lambda").get<std::size_t>(), 10u << state.at("restarts").get<int>());
}

TEST(Cmaes, FlatFitnessStopsByTolfunAndRestartsWithDoubledPopulation) {
  OptimizerSettings s = test::settings_named("cmaes");
  s.ipop_restarts = 2;
  auto opt = make_optimizer(s, test::test_box(), test::far_start(), 1);
  const auto r = test::run(
      *opt, [](const Vector&) { return 1.0; }, 100000);
  ASSERT_TRUE(opt->done());
  const auto& cmaes = dynamic_cast<const Cmaes&>(*opt);
  EXPECT_EQ(cmaes.stop_reason(), "tolfun");
  EXPECT_EQ(cmaes.restarts(), 2);
  EXPECT_EQ(cmaes.lambda(), 40u);
  // 10 + ceil(30 n / lambda) generations each: 40 x 10 + 25 x 20 + 18 x 40
  EXPECT_EQ(r.evaluations, 40 * 10 + 25 * 20 + 18 * 40);
  EXPECT_THROW(opt->ask(), std::logic_error);
}

TEST(Cmaes, SphereStopsOnceTheFitnessIsFlat) {
  // tolfun: the best values of the last 10 + ceil(30 n / lambda) generations and the last
  // generation's values span less than 1e-12, which on the sphere comes near f = 1e-13
  auto opt = make_optimizer(test::settings_named("cmaes"), test::test_box(), test::far_start(), 2);
  const auto r = test::run(*opt, test::sphere, 100000);
  ASSERT_TRUE(opt->done());
  EXPECT_EQ(dynamic_cast<const Cmaes&>(*opt).stop_reason(), "tolfun");
  EXPECT_LT(opt->best_f(), 1e-12);
  EXPECT_LT(r.evaluations, 5000);
  RecordProperty("evaluations", std::to_string(r.evaluations));
}

TEST(Cmaes, ResumesExactlyAcrossARestart) {
  OptimizerSettings s = test::settings_named("cmaes");
  s.ipop_restarts = 1;
  const auto flat = [](const Vector& x) { return x[0] < 0.0 ? 2.0 : 1.0; };
  auto whole = make_optimizer(s, test::test_box(), test::far_start(), 8);
  const auto expected = test::candidates_of(*whole, flat, 60);  // the restart comes after 40 generations

  auto first = make_optimizer(s, test::test_box(), test::far_start(), 8);
  auto head = test::candidates_of(*first, flat, 45);
  ASSERT_EQ(first->state().at("restarts").get<int>(), 1);
  auto second = make_optimizer(s, test::test_box(), test::far_start(), 1);
  second->restore(nlohmann::json::parse(first->state().dump()));
  const auto tail = test::candidates_of(*second, flat, 15);
  head.insert(head.end(), tail.begin(), tail.end());
  EXPECT_TRUE(test::bit_identical(head, expected));
}

TEST(Cmaes, NanFitnessCountsAsWorst) {
  // NaN wherever x[0] > 2: CMA-ES still converges on the sphere (the optimum has x[0] = 0)
  auto opt = make_optimizer(test::settings_named("cmaes"), test::test_box(), test::far_start(), 3);
  const auto f = [](const Vector& x) { return x[0] > 2.0 ? std::nan("") : test::sphere(x); };
  const auto r = test::run(*opt, f, 5000, 1e-8);
  EXPECT_TRUE(r.reached) << r.best_f;
  auto copy = make_optimizer(test::settings_named("cmaes"), test::test_box(), test::far_start(), 3);
  copy->restore(nlohmann::json::parse(opt->state().dump()));
  EXPECT_EQ(copy->best_f(), opt->best_f());
}

}  // namespace
}  // namespace swarmpath::evolve
