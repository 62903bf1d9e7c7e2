// SPDX-License-Identifier: MIT
// CMA-ES's distribution mean as a finalist ([reevaluate] mean_finalist): CMA-ES recommends its mean
// m in the caller's units, the other optimisers nothing; with the key on the mean takes the last
// finalist's place on the same fresh cases and can be the pick, a mean equal to a kept finalist
// leaves the finalists as they were; the run is bit-identical at 1 and 2 threads and after a resume
// (the mean comes from the restored optimiser); the key is checked and off keeps the hash.
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "evolve/optim/cmaes.hpp"
#include "evolve/runner.hpp"
#include "evolve/simulation_budget.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::read_text;
using testing::scratch;

namespace fs = std::filesystem;

TEST(MeanFinalist, CmaesRecommendsItsDistributionMeanInTheCallersUnits) {
  const Bounds b{{0.0, 10.0}, {2.0, 30.0}};
  OptimizerSettings s;
  Cmaes cma(s, b, {0.5, 25.0}, 3);
  // before any generation the mean is the start
  const Vector start = cma.recommended_x();
  ASSERT_EQ(start.size(), 2u);
  EXPECT_NEAR(start[0], 0.5, 1e-12);
  EXPECT_NEAR(start[1], 25.0, 1e-12);
  // after one: the state's mean (unit cube), mapped to the bounds, and no longer the start
  const std::vector<Vector> xs = cma.ask();
  std::vector<double> f;
  for (const Vector& x : xs) f.push_back((x[0] - 1.7) * (x[0] - 1.7) + (x[1] - 12.0) * (x[1] - 12.0));
  cma.tell(xs, f);
  const std::vector<double> unit = cma.state().at("mean").get<std::vector<double>>();
  const Vector m = cma.recommended_x();
  EXPECT_NEAR(m[0], std::clamp(unit[0], 0.0, 1.0) * 2.0, 1e-12);
  EXPECT_NEAR(m[1], 10.0 + std::clamp(unit[1], 0.0, 1.0) * 20.0, 1e-12);
  EXPECT_NE(m, start);
  // optimisers without a distribution recommend nothing
  const std::unique_ptr<Optimizer> ga = make_optimizer(OptimizerSettings{"ga"}, b, {0.5, 25.0}, 3);
  EXPECT_TRUE(ga->recommended_x().empty());
}

// Asks the same two candidates every generation (A: w_away 0.2, B: w_away 1.8) and recommends `mean`.
class TwoAndAMean final : public Optimizer {
 public:
  explicit TwoAndAMean(Vector mean) : mean_(std::move(mean)) {}

  std::string name() const override { return "cmaes"; }

  std::vector<Vector> ask() override { return {{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}}; }

  void tell(const std::vector<Vector>&, const std::vector<double>&) override { ++told_; }

  Vector best_x() const override { return {0.5, 0.1, 0.5}; }

  double best_f() const override { return 0.0; }

  Vector recommended_x() const override { return mean_; }

  nlohmann::json state() const override { return {{"told", told_}}; }

  void restore(const nlohmann::json& s) override { told_ = s.at("told").get<int>(); }

 private:
  Vector mean_;
  int told_ = 0;
};

// A (w_away 0.2) 0.45, B (w_away 1.8) 2.0, the base params (w_away 0.5) 0.5, and the point w_away
// 0.4, which the generations never ask, 0.1; A and that point 0-0.04 more by the run's seed
RunResult run_with_mean(bool mean_finalist, const Vector& mean, const fs::path& dir) {
  EvolveConfig c = testing::tiny("cmaes", 2);
  c.reevaluate.seeds = 6;
  c.reevaluate.mean_finalist = mean_finalist;
  const std::vector<EvalSetting> settings{{"s", 8, false}};
  const FakeObjective f(settings, [](const sim::Params& p, const EvalCase& k) {
    const double noise = 0.01 * static_cast<double>((k.seed >> 7) % 5);  // the base params' runs: none
    if (std::abs(p.w_away - 0.4) < 1e-9) return 0.1 + noise;
    if (p.w_away > 1.0) return 2.0;
    return p.w_away > 0.3 ? 0.5 : 0.45 + noise;
  });
  RunOptions o = testing::test_options(dir, 2);
  o.make_optimizer = [mean](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<TwoAndAMean>(mean);
  };
  return run_evolution(c, f, o);
}

TEST(MeanFinalist, TheMeanTakesTheLastFinalistsPlaceAndCanBeThePick) {
  const Vector mean{0.5, 0.2, 0.5};  // w_away 0.4
  const fs::path off_dir = scratch("off"), on_dir = scratch("on");
  const RunResult off = run_with_mean(false, mean, off_dir);
  ASSERT_EQ(off.finalists.size(), 2u);
  EXPECT_EQ(off.finalists[1].params.w_away, 1.8);  // B: the second best by generation mean
  EXPECT_EQ(off.pick().w_away, 0.2);

  const RunResult on = run_with_mean(true, mean, on_dir);
  ASSERT_EQ(on.finalists.size(), 2u);
  EXPECT_EQ(on.finalists[0].params.w_away, 0.2);  // A stays first
  EXPECT_EQ(on.finalists[1].elite.candidate, kDistributionMean);
  EXPECT_EQ(on.finalists[1].elite.generation, 1);  // after the second (last) generation
  EXPECT_EQ(on.finalists[1].elite.stats.runs, 0);  // never simulated during the run
  EXPECT_NEAR(on.finalists[1].params.w_away, 0.4, 1e-12);
  EXPECT_EQ(on.finalists[1].reevaluated.runs, off.finalists[1].reevaluated.runs);  // the same fresh cases
  EXPECT_EQ(on.state.runs, off.state.runs);
  EXPECT_EQ(on.best, 1u);
  EXPECT_EQ(on.selection.finalist, 1u);
  EXPECT_FALSE(on.selection.base_kept);
  EXPECT_NEAR(on.pick().w_away, 0.4, 1e-12);
  const std::string toml = read_text(on_dir / "best.toml");
  EXPECT_NE(toml.find("# CMA-ES's distribution mean after generation 1 (mean_finalist; never simulated"),
            std::string::npos)
      << toml;
  const nlohmann::json j = nlohmann::json::parse(read_text(on_dir / "run.json"));
  const nlohmann::json& fin = j.at("finalists");
  ASSERT_EQ(fin.size(), 2u);
  EXPECT_FALSE(fin[0].at("distribution_mean").get<bool>());
  EXPECT_TRUE(fin[1].at("distribution_mean").get<bool>());
  EXPECT_FALSE(nlohmann::json::parse(read_text(off_dir / "run.json"))
                   .at("finalists")[1]
                   .contains("distribution_mean"));
}

TEST(MeanFinalist, AMeanEqualToAKeptFinalistLeavesTheFinalistsAsTheyWere) {
  const RunResult r = run_with_mean(true, {0.5, 0.1, 0.5}, scratch("same"));  // A's own point
  ASSERT_EQ(r.finalists.size(), 2u);
  EXPECT_EQ(r.finalists[0].params.w_away, 0.2);
  EXPECT_EQ(r.finalists[1].params.w_away, 1.8);
  EXPECT_NE(r.finalists[1].elite.candidate, kDistributionMean);
}

TEST(MeanFinalist, BitIdenticalAtOneAndTwoThreadsAndAfterResume) {
  EvolveConfig c = testing::tiny("cmaes", 3);
  c.reevaluate.mean_finalist = true;
  const SwarmObjective f(c);
  const nlohmann::json j = testing::expect_same_at_threads_and_resume(c, f, 3);
  const nlohmann::json& fin = j.at("finalists");
  ASSERT_EQ(fin.size(), 2u);
  EXPECT_TRUE(fin[1].at("distribution_mean").get<bool>());
  EXPECT_EQ(fin[1].at("candidate").get<int>(), kDistributionMean);
}

TEST(MeanFinalist, TheKeyIsCmaesOnlyAndOffKeepsTheHash) {
  testing::expect_error(testing::tiny_config("ga") + "mean_finalist = true\n", "mean_finalist",
                        "reevaluate.mean_finalist", "CMA-ES's");
  testing::expect_error(testing::tiny_config("cmaes") + "mean_finalist = 1\n", "mean_finalist",
                        "reevaluate.mean_finalist", "");
  const EvolveConfig plain = testing::tiny("cmaes", 2);
  EXPECT_FALSE(plain.reevaluate.mean_finalist);
  const auto with = [&](const std::string& lines) {
    return parse_evolve_config(testing::tiny_config("cmaes", 2) + lines, "t", "");
  };
  EXPECT_EQ(config_hash(plain), config_hash(with("mean_finalist = false\n")));
  EXPECT_NE(config_hash(plain), config_hash(with("mean_finalist = true\n")));
  EXPECT_TRUE(with("mean_finalist = true\n").reevaluate.mean_finalist);
  // the same simulations: the mean takes a finalist's place
  EXPECT_EQ(simulation_budget(plain)->reevaluation,
            simulation_budget(with("mean_finalist = true\n"))->reevaluation);
}

}  // namespace
}  // namespace swarmpath::evolve
