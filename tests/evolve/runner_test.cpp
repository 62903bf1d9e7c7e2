// SPDX-License-Identifier: MIT
// The evolution runner: bit-identical at 1 and 2 threads, exact resume (by --generations and
// after an interruption), re-evaluation picks by the fresh-seed mean, callbacks stop the run,
// penalised candidates are never simulated nor reported, resuming another config is refused.
#include "evolve/runner.hpp"

#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

#include "evolve/seeds.hpp"
#include "evolve_test_support.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {
namespace {

using testing::FakeObjective;
using testing::FixedOptimizer;
using testing::read_text;
using testing::run_json_text;
using testing::scratch;

namespace fs = std::filesystem;

RunResult run(const EvolveConfig& c, const CaseObjective& f, const fs::path& dir, int threads,
              std::optional<int> generations = {}, bool resume = false) {
  return run_evolution(c, f, testing::test_options(dir, threads, generations, resume));
}

void expect_same_files(const fs::path& a, const fs::path& b) {
  for (const char* name : {"log.csv", "best.toml", "checkpoint.json", "fitness.svg"}) {
    const std::string ta = read_text(a / name);
    EXPECT_FALSE(ta.empty()) << name;
    EXPECT_EQ(ta, read_text(b / name)) << name;
  }
  EXPECT_EQ(run_json_text(a), run_json_text(b));
}

TEST(Runner, BitIdenticalAtOneAndTwoThreads) {
  const EvolveConfig c = testing::tiny("cmaes", 2);
  const SwarmObjective f(c);
  const fs::path one = scratch("t1"), two = scratch("t2");
  const RunResult r1 = run(c, f, one, 1);
  const RunResult r2 = run(c, f, two, 2);
  expect_same_files(one, two);
  EXPECT_EQ(r1.state.generation, 2);
  EXPECT_EQ(r1.state.evaluations, 8);  // 2 generations x population 4
  EXPECT_EQ(r1.state.runs, 16);        // x 2 cases
  // the files hold what the run did
  const std::string log = read_text(one / "log.csv");
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 3);  // header + 2 generations
  EXPECT_EQ(log.rfind("generation,best,mean,std,", 0), 0u);
  const sim::Params best = sim::load_params((one / "best.toml").string());
  EXPECT_EQ(sim::get_value(best, *sim::find_param("w_away")), r1.pick().w_away);
  EXPECT_EQ(read_text(one / "fitness.svg").rfind("<svg", 0), 0u);
  const nlohmann::json j = nlohmann::json::parse(read_text(one / "run.json"));
  EXPECT_FALSE(j.at("versions").at("git_commit").get<std::string>().empty());
  EXPECT_EQ(j.at("seeds").at("generations").size(), 2u);
  EXPECT_EQ(j.at("seeds").at("generations")[1][0].get<std::uint64_t>(), generation_seed(7, 1, 0));
  EXPECT_FALSE(fs::exists(one / "checkpoint.json.tmp"));
}

TEST(Runner, ResumeContinuesExactly) {
  const EvolveConfig c = testing::tiny("cmaes", 4);
  const SwarmObjective f(c);
  const fs::path straight = scratch("straight"), split = scratch("split");
  run(c, f, straight, 2);  // 4 generations
  run(c, f, split, 2, 2);  // 2 generations ...
  EXPECT_EQ(read_checkpoint((split / "checkpoint.json").string()).generation, 2);
  run(c, f, split, 1, 4, /*resume=*/true);  // ... then resumed up to 4 (on another thread count)
  expect_same_files(straight, split);
}

TEST(Runner, AnInterruptedRunLosesAtMostTheGenerationInFlight) {
  const EvolveConfig c = testing::tiny("random", 3);
  const SwarmObjective f(c);
  const fs::path straight = scratch("straight"), killed = scratch("killed");
  run(c, f, straight, 2);
  RunOptions o;
  o.out_dir = killed.string();
  o.threads = 2;
  o.wall_time = false;
  o.callbacks.push_back([](const GenerationRecord& r, const RunState&) -> bool {
    if (r.generation == 1) throw std::runtime_error("killed");  // after generation 1's checkpoint
    return false;
  });
  EXPECT_THROW(run_evolution(c, f, o), std::runtime_error);
  EXPECT_EQ(read_checkpoint((killed / "checkpoint.json").string()).generation, 2);
  run(c, f, killed, 2, {}, /*resume=*/true);
  expect_same_files(straight, killed);
}

TEST(Runner, ResumingWithAnotherConfigIsRefused) {
  const EvolveConfig c = testing::tiny("random", 1);
  const FakeObjective f({{"s", 8, false}}, [](const sim::Params& p, const EvalCase&) { return p.w_away; });
  const fs::path dir = scratch("run");
  run(c, f, dir, 1);
  EvolveConfig other = c;
  other.seed = 8;
  try {
    run(other, f, dir, 1, 2, true);
    ADD_FAILURE() << "resumed under another config";
  } catch (const sim::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("different config"), std::string::npos) << e.what();
  }
  // the budget may change
  EvolveConfig longer = c;
  longer.budget.generations = 2;
  EXPECT_EQ(run(longer, f, dir, 1, {}, true).state.generation, 2);
  // no checkpoint: a clear error
  EXPECT_THROW(run(c, f, scratch("empty"), 1, 2, true), sim::ConfigError);
}

TEST(Runner, ReportedBestIsTheBestOnFreshSeedsNotTheLuckiest) {
  // candidate A (w_away 0.2) scores 0.5 everywhere; candidate B (w_away 1.8) scores 0 on the
  // generation's seeds (lucky) and 1 on any other seed
  EvolveConfig c = testing::tiny("random", 1);
  const std::uint64_t g0 = generation_seed(c.seed, 0, 0), g1 = generation_seed(c.seed, 0, 1);
  const FakeObjective f({{"s", 8, false}}, [&](const sim::Params& p, const EvalCase& k) {
    if (p.w_away < 1.0) return 0.5;
    return k.seed == g0 || k.seed == g1 ? 0.0 : 1.0;
  });
  RunOptions o;
  o.threads = 2;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}});
  };
  const RunResult r = run_evolution(c, f, o);
  ASSERT_EQ(r.finalists.size(), 2u);
  EXPECT_EQ(r.state.history[0].best, 0.0);       // B won the generation ...
  EXPECT_EQ(r.finalists[0].params.w_away, 1.8);  // ... and leads the best-so-far list
  EXPECT_EQ(r.finalists[0].reevaluated.fitness, 1.0);
  EXPECT_EQ(r.finalists[1].reevaluated.fitness, 0.5);
  EXPECT_EQ(r.best, 1u);  // but A is reported
  EXPECT_EQ(r.finalists[r.best].params.w_away, 0.2);
  EXPECT_EQ(r.finalists[r.best].reevaluated.runs, 2);
}

TEST(Runner, HeldOutScenariosAreReportedNotChosenBy) {
  EvolveConfig c = testing::tiny("random", 1);
  c.reevaluate.held_out = c.evaluation.scenarios;  // the same arena, as a held-out setting
  const SwarmObjective real(c);
  ASSERT_EQ(real.settings().size(), 2u);
  EXPECT_TRUE(real.settings()[1].held_out);
  // A is better on the training settings, B on the held-out one: A is reported
  const FakeObjective f(real.settings(), [](const sim::Params& p, const EvalCase& k) {
    const bool a = p.w_away < 1.0;
    return k.setting == 0 ? (a ? 0.2 : 0.4) : (a ? 0.9 : 0.1);
  });
  RunOptions o;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5, 0.9, 0.5}});
  };
  const RunResult r = run_evolution(c, f, o);
  EXPECT_EQ(r.finalists[r.best].params.w_away, 0.2);
  EXPECT_EQ(r.finalists[r.best].held_out.fitness, 0.9);
  EXPECT_EQ(r.finalists[r.best].held_out.runs, 2);
  EXPECT_EQ(r.reevaluation_cases.size(), 4u);
}

TEST(Runner, CallbacksStopTheRun) {
  const EvolveConfig c = testing::tiny("random", 5);
  const FakeObjective f({{"s", 8, false}}, [](const sim::Params& p, const EvalCase&) { return p.w_away; });
  RunOptions o;
  int seen = 0;
  o.callbacks.push_back([&](const GenerationRecord& r, const RunState& st) {
    ++seen;
    EXPECT_EQ(st.generation, r.generation + 1);
    return r.generation == 1;
  });
  const RunResult r = run_evolution(c, f, o);
  EXPECT_EQ(seen, 2);
  EXPECT_EQ(r.state.generation, 2);
  EXPECT_EQ(r.stop_reason, "callback");
}

TEST(Runner, PenalisedCandidatesAreNeitherSimulatedNorReported) {
  // base theta_hard 75, theta_soft 70; tuned hard in [60, 75], soft in [70, 90]: hard 60 with
  // soft 90 can be repaired neither way (soft cannot go below 70, hard not above 75)
  const fs::path dir = scratch("cfg");
  std::string base = read_text(testing::source("genomes/default.toml"));
  base.replace(base.find("theta_hard = 90"), 15, "theta_hard = 75");
  testing::write_text(dir / "base.toml", base);
  std::string text =
      testing::tiny_config("random", 1, "theta_hard = { hi = 75 }\ntheta_soft = { lo = 70 }\n");
  const std::string paper = testing::source("genomes/default.toml");
  text.replace(text.find(paper), paper.size(), (dir / "base.toml").string());
  const EvolveConfig c = parse_evolve_config(text, "pen.toml", "");
  ASSERT_EQ(c.genome.dim(), 5u);  // row order: theta_hard, theta_soft, T_explore0, w_away, p_turn
  const FakeObjective f({{"s", 8, false}}, [](const sim::Params& p, const EvalCase&) { return p.w_away; });
  RunOptions o;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<FixedOptimizer>(
        std::vector<Vector>{{0.0, 1.0, 0.5, 0.1, 0.5},    // hard 60, soft 90: unrepairable
                            {1.0, 0.0, 0.5, 0.3, 0.5}});  // hard 75, soft 70: valid
  };
  const RunResult r = run_evolution(c, f, o);
  EXPECT_EQ(f.penalties(), 2);  // candidate 0 on both cases, instead of simulating it
  for (const auto& call : f.calls()) EXPECT_NE(call.params.w_away, 0.2);
  ASSERT_EQ(r.finalists.size(), 1u);
  EXPECT_EQ(r.finalists[0].params.w_away, 0.6);
  EXPECT_EQ(r.state.history[0].best, 0.6);
  EXPECT_EQ(r.state.history[0].mean, (0.6 + 100.0) / 2.0);  // the fake's penalty is 100
  EXPECT_EQ(r.state.runs, 2);                               // only the valid candidate ran
}

TEST(Runner, FinalistsAreDistinct) {
  const EvolveConfig c = testing::tiny("random", 2);
  const FakeObjective f({{"s", 8, false}}, [](const sim::Params& p, const EvalCase&) { return p.w_away; });
  RunOptions o;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    // the first two decode to the same parameters (T_explore0 rounds to the same step)
    return std::make_unique<FixedOptimizer>(
        std::vector<Vector>{{0.5, 0.1, 0.5}, {0.5001, 0.1, 0.5}, {0.5, 0.5, 0.5}});
  };
  const RunResult r = run_evolution(c, f, o);
  ASSERT_EQ(r.finalists.size(), 2u);  // top_k = 2 of two distinct parameter sets
  EXPECT_EQ(r.finalists[0].params.w_away, 0.2);
  EXPECT_EQ(r.finalists[1].params.w_away, 1.0);
  EXPECT_EQ(r.finalists[0].elite.generation, 0);  // the first time it was seen wins ties
  EXPECT_EQ(r.finalists[0].elite.candidate, 0);
}

}  // namespace
}  // namespace swarmpath::evolve
