// SPDX-License-Identifier: MIT
// Tuning on arena families: [[evaluation.family]] is read strictly, every generation draws fresh
// arenas that every candidate meets, the validation arenas come from seeds training never uses
// (nor the benchmarks), the run is bit-identical at 1 and 2 threads and after a resume (NSGA-II
// too), and the files record the arenas of training and validation.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "evolve/objective.hpp"
#include "evolve/pareto_runner.hpp"
#include "evolve/runner.hpp"
#include "evolve/seeds.hpp"
#include "evolve_test_support.hpp"
#include "sim/arenas/registry.hpp"

namespace swarmpath::evolve {
namespace {

using testing::expect_error;
using testing::read_text;
using testing::replaced;
using testing::scratch;

namespace fs = std::filesystem;

// small arenas (10 m x 8 m, A* on 0.8 M cells) and short runs keep these tests quick
const std::string kFamilies =
    "max_ticks = 2000\n"
    "seeds = 1\n"
    "\n[[evaluation.family]]\n"
    "family = \"open\"\n"
    "params = { width = 10, height = 8, distance_min = 3, distance_max = 4 }\n"
    "arenas = 2\n"
    "robots = [8, 10]\n"
    "\n[[evaluation.family]]\n"
    "family = \"wall-gap\"\n"
    "params = { width = 10, height = 8, door_min = 1.5, door_max = 2 }\n"
    "robots = [8]\n";

// the tiny config with families instead of its scenario
std::string family_config(const std::string& optimizer = "random", int generations = 2) {
  std::string t = testing::tiny_config(optimizer, generations);
  const auto a = t.find("scenarios = ");
  const auto b = t.find("\n[optimizer]");
  t.replace(a, b - a, kFamilies);
  return t + "arenas = 2\n";  // into [reevaluate]: two validation arenas per family entry
}

EvolveConfig parsed(const std::string& text) { return parse_evolve_config(text, "fam.toml", ""); }

TEST(FamilyTuning, TheConfigNamesFamiliesWithCountsRobotsAndParameters) {
  const EvolveConfig c = parsed(family_config());
  EXPECT_TRUE(c.evaluation.scenarios.empty());
  ASSERT_EQ(c.evaluation.families.size(), 2u);
  const FamilyEntry& open = c.evaluation.families[0];
  EXPECT_EQ(open.spec.family->name, "open");
  EXPECT_EQ(open.arenas, 2);
  EXPECT_EQ(open.robots, (std::vector<int>{8, 10}));
  EXPECT_EQ(open.seeds, 1);
  EXPECT_EQ(open.spec.param_values()("distance_max"), 4.0);
  EXPECT_EQ(open.spec.param_values()("robots"), 10.0);  // drawn for the largest count
  EXPECT_EQ(c.evaluation.families[1].arenas, 1);
  EXPECT_EQ(c.reevaluate.arenas, 2);
  EXPECT_TRUE(c.reevaluate.every_generation);  // the default with families
  EXPECT_FALSE(testing::tiny().reevaluate.every_generation);
  // the families are part of the config's hash (a resume under other arenas is refused)
  const EvolveConfig other = parsed(replaced(family_config(), "distance_max = 4", "distance_max = 5"));
  EXPECT_NE(config_hash(c), config_hash(other));
  EXPECT_EQ(config_json(c)["evaluation"]["families"][0]["params"]["distance_min"], 3.0);
}

TEST(FamilyTuning, BadFamilyEntriesAreRefusedWithFileLineAndKey) {
  const std::string t = family_config();
  expect_error(replaced(t, "family = \"open\"", "family = \"lake\""), "family = \"lake\"",
               "evaluation.family[0].family", "unknown arena family");
  expect_error(replaced(t, "distance_min = 3,", "distance_min = 1,"), "distance_min = 1",
               "evaluation.family[0].params.distance_min", "must lie in");
  expect_error(replaced(t, "door_min = 1.5", "door_min = 3"), "door_min = 3",
               "evaluation.family[1].params.door_min", "must be <= door_max");
  expect_error(replaced(t, "arenas = 2\nrobots", "arenas = 0\nrobots"), "arenas = 0",
               "evaluation.family[0].arenas", "must lie in");
  expect_error(replaced(t, "robots = [8, 10]", "robots = [8, 150]"), "robots = [8, 150]",
               "evaluation.family[0].robots", "at most 120");
  expect_error(replaced(t, "distance_max = 4 }", "distance_max = 4, robots = 9 }"), "robots = 9",
               "evaluation.family[0].params.robots", "robot counts");
  expect_error(replaced(t, "robots = [8]\n", "robots = [8]\nrepeats = 2\n"), "repeats = 2",
               "evaluation.family[1].repeats", "unknown key");
  // nothing to evaluate
  std::string empty = testing::tiny_config();
  const auto a = empty.find("scenarios = ");
  empty.erase(a, empty.find("robots = [8]") - a);
  expect_error(empty, "[evaluation]", "evaluation.scenarios", "evaluation set is empty");
}

TEST(FamilyTuning, AScenarioFileDrawnFromABenchmarkSeedIsRefused) {
  const fs::path dir = scratch("files");
  const sim::arenas::ArenaSpec spec = sim::arenas::spec_from_settings(
      "open", {"width=10", "height=8", "distance_min=3", "distance_max=4"}, "t");
  testing::write_text(dir / "bench.toml",
                      sim::arenas::generate_arena(spec, sim::arenas::kBenchmarkSeedLo + 3).toml);
  testing::write_text(dir / "free.toml", sim::arenas::generate_arena(spec, 3).toml);
  const std::string chain = testing::source("tests/data/short_chain.toml");
  const std::string bench = replaced(testing::tiny_config(), chain, (dir / "bench.toml").string());
  expect_error(bench, "scenarios = ", "evaluation.scenarios", "a benchmark's seed");
  EXPECT_NO_THROW(parsed(replaced(testing::tiny_config(), chain, (dir / "free.toml").string())));
  const std::string held =
      testing::tiny_config() + "held_out = [\"" + (dir / "bench.toml").string() + "\"]\n";
  expect_error(held, "held_out = ", "reevaluate.held_out", "never for tuning");
}

TEST(FamilyTuning, ArenaSeedRangesAreDisjointAndNeverABenchmarks) {
  std::set<std::uint64_t> training, validation;
  for (std::uint64_t master : {1ULL, 7ULL}) {
    for (std::int64_t g = 0; g < 50; ++g) {
      for (std::uint64_t f = 0; f < 3; ++f) {
        for (std::uint64_t k = 0; k < 4; ++k) training.insert(training_arena_seed(master, g, f, k));
      }
    }
    for (std::uint64_t f = 0; f < 3; ++f) {
      for (std::uint64_t k = 0; k < 20; ++k) validation.insert(validation_arena_seed(master, f, k));
    }
  }
  EXPECT_EQ(training.size(), 2u * 50 * 3 * 4);
  EXPECT_EQ(validation.size(), 2u * 3 * 20);
  for (const std::uint64_t s : training) {
    EXPECT_EQ(arena_use(s), ArenaUse::kTraining);
    EXPECT_FALSE(sim::arenas::is_benchmark_seed(s));
    EXPECT_EQ(validation.count(s), 0u);
  }
  for (const std::uint64_t s : validation) {
    EXPECT_EQ(arena_use(s), ArenaUse::kValidation);
    EXPECT_LE(s, sim::arenas::kMaxArenaSeed);
  }
  EXPECT_EQ(arena_use(verify_arena_seed(1, 0, 0)), ArenaUse::kVerify);
  EXPECT_EQ(arena_use(sim::arenas::kBenchmarkSeedLo), ArenaUse::kOther);
}

TEST(FamilyTuning, CasesDrawFreshArenasEveryGenerationSharedAcrossRobotCounts) {
  const EvolveConfig c = parsed(family_config());
  const SwarmObjective f(c);
  const std::vector<EvalSetting>& settings = f.settings();
  ASSERT_EQ(settings.size(), 3u);  // open x {8, 10}, wall-gap x {8}
  const std::vector<EvalCase> g0 = generation_cases(settings, c.evaluation.seeds, c.seed, 0, false);
  const std::vector<EvalCase> g1 = generation_cases(settings, c.evaluation.seeds, c.seed, 1, false);
  ASSERT_EQ(g0.size(), 5u);                       // open: 2 arenas x 2 robot counts, wall-gap: 1 arena
  EXPECT_EQ(g0[0].arena_seed, g0[2].arena_seed);  // arena 0 of "open" at 8 and at 10 robots
  EXPECT_EQ(g0[1].arena_seed, g0[3].arena_seed);
  EXPECT_NE(g0[0].arena_seed, g0[1].arena_seed);
  EXPECT_EQ(g0[4].arena_seed, training_arena_seed(c.seed, 0, 1, 0));
  for (std::size_t i = 0; i < g0.size(); ++i) {
    EXPECT_NE(g0[i].arena_seed, g1[i].arena_seed) << i;
    EXPECT_EQ(generation_cases(settings, 1, c.seed, 5, true)[i].arena_seed, g0[i].arena_seed)
        << "fixed seeds";
  }
  const std::vector<EvalCase> v = reevaluation_cases(settings, c.reevaluate.seeds, c.seed);
  ASSERT_EQ(v.size(), 6u);  // 2 validation arenas per robot count and entry
  for (const EvalCase& k : v) EXPECT_EQ(arena_use(k.arena_seed), ArenaUse::kValidation);
  // the objective scores a case the same whether its arena was prepared or drawn on demand
  const SwarmObjective fresh(c);
  const RunScore unprepared = fresh.evaluate(c.genome.base, g0[4]);
  f.prepare(g0);
  const RunScore prepared = f.evaluate(c.genome.base, g0[4]);
  EXPECT_EQ(prepared.fitness, unprepared.fitness);
  EXPECT_EQ(f.simulation(g0[2]).scenario->robots, 10);
  EXPECT_EQ(f.simulation(g0[2]).scenario, f.simulation(g0[2]).scenario);  // one shared scenario per arena
  EXPECT_EQ(f.simulation(g0[2]).scenario->origin->seed, g0[2].arena_seed);
  EXPECT_GT(f.astar_tu(g0[2]), 0.0);
}

TEST(FamilyTuning, EveryCandidateOfAGenerationMeetsTheSameArenasAndValidationArenasAreApart) {
  const EvolveConfig c = parsed(family_config("random", 3));
  const SwarmObjective real(c);
  const testing::FakeObjective f(real.settings(), [](const sim::Params& p, const EvalCase& k) {
    return p.w_away + static_cast<double>(k.arena_seed % 7) * 0.01;
  });
  RunOptions o;
  o.threads = 2;
  o.make_optimizer = [](const OptimizerSettings&, const Bounds&, const Vector&, std::uint64_t) {
    return std::make_unique<testing::FixedOptimizer>(
        std::vector<Vector>{{0.1, 0.1, 0.5}, {0.9, 0.9, 0.5}, {0.5, 0.5, 0.7}});
  };
  const RunResult r = run_evolution(c, f, o);
  // training arena -> the candidates (by w_away) that met it
  std::map<std::uint64_t, std::set<double>> met;
  std::set<std::uint64_t> validation;
  for (const auto& call : f.calls()) {
    if (arena_use(call.c.arena_seed) == ArenaUse::kTraining)
      met[call.c.arena_seed].insert(call.params.w_away);
    if (arena_use(call.c.arena_seed) == ArenaUse::kValidation) validation.insert(call.c.arena_seed);
  }
  EXPECT_EQ(met.size(), 3u * 3u);  // 3 generations x 3 arenas (2 open, 1 wall-gap), all different
  for (const auto& [seed, candidates] : met) EXPECT_EQ(candidates.size(), 3u) << seed;
  EXPECT_EQ(validation.size(), 2u * 2u);  // 2 validation arenas for each of the 2 entries
  for (const std::uint64_t s : validation) EXPECT_EQ(met.count(s), 0u);
  // every generation's best was scored on the validation set
  for (const GenerationRecord& g : r.state.history) EXPECT_EQ(g.validation_runs, 6);
  EXPECT_EQ(r.finalists[r.best].arenas.runs, 6);
}

void expect_same_files(const fs::path& a, const fs::path& b, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const std::string ta = read_text(a / name);
    EXPECT_FALSE(ta.empty()) << name;
    EXPECT_EQ(ta, read_text(b / name)) << name;
  }
  EXPECT_EQ(testing::run_json_text(a), testing::run_json_text(b));
}

TEST(FamilyTuning, BitIdenticalAtOneAndTwoThreadsAndAfterAResume) {
  const EvolveConfig c = parsed(family_config("cmaes", 2));
  const SwarmObjective f(c);
  const fs::path one = scratch("t1"), two = scratch("t2"), split = scratch("split");
  run_evolution(c, f, testing::test_options(one, 1));
  run_evolution(c, SwarmObjective(c), testing::test_options(two, 2));
  run_evolution(c, SwarmObjective(c), testing::test_options(split, 2, 1));
  run_evolution(c, SwarmObjective(c), testing::test_options(split, 1, 2, /*resume=*/true));
  const std::vector<std::string> files = {"log.csv", "best.toml", "checkpoint.json", "fitness.svg"};
  expect_same_files(one, two, files);
  expect_same_files(one, split, files);
  // log.csv and run.json record training and validation
  const std::string log = read_text(one / "log.csv");
  EXPECT_NE(log.find(",validation_fitness,validation_success_rate\n"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(read_text(one / "run.json"));
  ASSERT_EQ(j["seeds"]["arena_generations"].size(), 2u);
  EXPECT_EQ(j["seeds"]["arena_generations"][1][4].get<std::uint64_t>(), training_arena_seed(c.seed, 1, 1, 0));
  const nlohmann::json& reev = j["seeds"]["reevaluation"];
  ASSERT_EQ(reev.size(), 6u);
  EXPECT_EQ(arena_use(reev[0]["arena_seed"].get<std::uint64_t>()), ArenaUse::kValidation);
  EXPECT_NE(reev[0]["arena"].get<std::string>().find("swarmpath arena generate --family open --seed "),
            std::string::npos);
  EXPECT_EQ(j["best"]["validation_arenas"]["runs"], 6);
  EXPECT_EQ(j["config"]["evaluation"]["families"].size(), 2u);
}

TEST(FamilyTuning, NsgaTwoOnFamiliesIsBitIdenticalAtOneAndTwoThreads) {
  std::string t = replaced(family_config("nsga2", 2), "population = 4\n", "population = 4\n");
  t.erase(t.find("top_k = 2\n"), std::string("top_k = 2\n").size());
  t += "\n[objectives]\nuse = [\"path\", \"ticks\"]\nmin_success = 0.0\nreference = [3.0, 2000]\n";
  const EvolveConfig c = parsed(t);
  const fs::path one = scratch("p1"), two = scratch("p2");
  const ParetoResult r = run_pareto(c, SwarmObjective(c), testing::test_options(one, 1));
  run_pareto(c, SwarmObjective(c), testing::test_options(two, 2));
  expect_same_files(one, two, {"log.csv", "checkpoint.json", "pareto.csv"});
  EXPECT_EQ(r.reevaluation_cases.size(), 6u);  // the front is re-evaluated on the validation arenas
}

}  // namespace
}  // namespace swarmpath::evolve
