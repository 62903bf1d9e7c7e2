// SPDX-License-Identifier: MIT
// Evolve configs: the shipped ones load; every kind of bad config is a ConfigError that names
// file:line:key; the config hash ignores only the budget.
#include "evolve/evolve_config.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "evolve_test_support.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {
namespace {

using testing::source;
using testing::tiny_config;

using testing::expect_error;
using testing::replaced;

TEST(EvolveConfig, TheShippedConfigsLoad) {
  const EvolveConfig d = load_evolve_config(source("configs/evolve/default.toml"));
  EXPECT_EQ(d.name, "default");
  EXPECT_EQ(d.mode, sim::Mode::kPathFormation);
  EXPECT_EQ(d.genome.dim(), 6u);
  EXPECT_EQ(d.evaluation.scenarios.size(), 3u);
  EXPECT_EQ(d.optimizer.name, "cmaes");
  EXPECT_GT(d.budget.generations, 0);
  // genes come in SPEC §7 row order, whatever order the file lists them in
  for (std::size_t i = 1; i < d.genome.genes.size(); ++i)
    EXPECT_LT(d.genome.genes[i - 1].info->row, d.genome.genes[i].info->row);
  const EvolveConfig p = load_evolve_config(source("configs/evolve/paper-pf.toml"));
  EXPECT_EQ(p.evaluation.scenarios.size(), 8u);
  EXPECT_EQ(p.mode, sim::Mode::kPathFormation);
}

TEST(EvolveConfig, ReadsEverySetting) {
  const EvolveConfig c = testing::tiny("cmaes", 3);
  EXPECT_EQ(c.name, "tiny");
  EXPECT_EQ(c.seed, 7u);
  ASSERT_EQ(c.genome.dim(), 3u);
  EXPECT_EQ(c.genome.genes[0].info->name, "T_explore0");  // row 14, before w_away (18), p_turn (20)
  EXPECT_EQ(c.genome.genes[0].step, 50.0);
  EXPECT_TRUE(c.genome.genes[2].log);
  EXPECT_EQ(c.genome.genes[2].lo, 0.002);
  EXPECT_EQ(c.evaluation.robots, std::vector<int>{8});
  EXPECT_EQ(c.evaluation.max_ticks, 3000);
  EXPECT_EQ(c.optimizer.population, 4);
  EXPECT_EQ(c.budget.generations, 3);
  EXPECT_EQ(c.reevaluate.top_k, 2);
}

TEST(EvolveConfig, UnknownParameter) {
  const std::string t = replaced(tiny_config(), "w_away = {}", "w_awya = {}");
  expect_error(t, "w_awya", "tune.w_awya", "unknown parameter");
}

TEST(EvolveConfig, BoundOutsideTheParametersRange) {
  const std::string t = replaced(tiny_config(), "w_away = {}", "w_away = { lo = -1 }");
  expect_error(t, "lo = -1", "tune.w_away.lo", "outside");
}

TEST(EvolveConfig, LowNotBelowHigh) {
  const std::string t = replaced(tiny_config(), "w_away = {}", "w_away = { lo = 1.5, hi = 1.0 }");
  expect_error(t, "w_away", "tune.w_away.lo", "must be < hi");
}

TEST(EvolveConfig, LogScaleNeedsAPositiveLowBound) {
  const std::string t = replaced(tiny_config(), "w_away = {}", "w_away = { log = true }");
  expect_error(t, "w_away", "tune.w_away.log", "lo > 0");
}

TEST(EvolveConfig, EmptyEvaluationSet) {
  std::string t = tiny_config();
  const auto a = t.find("scenarios = [");
  t.replace(a, t.find('\n', a) - a, "scenarios = []");
  expect_error(t, "scenarios = []", "evaluation.scenarios", "empty");
  expect_error(replaced(tiny_config(), "robots = [8]", "robots = []"), "robots = []", "evaluation.robots",
               "empty");
}

TEST(EvolveConfig, UnknownOptimiser) {
  const std::string t = replaced(tiny_config(), "name = \"random\"", "name = \"adam\"");
  expect_error(t, "name = \"adam\"", "optimizer.name", "unknown optimiser");
}

TEST(EvolveConfig, UnknownKeys) {
  expect_error(replaced(tiny_config(), "generations = 2", "generatoins = 2"), "generatoins",
               "budget.generatoins", "unknown key");
  expect_error(replaced(tiny_config(), "seed = 7", "seed = 7\ncolour = \"red\""), "colour", "colour",
               "unknown key");
  expect_error(replaced(tiny_config(), "w_away = {}", "w_away = { lo = 0.5, stepp = 0.1 }"), "w_away",
               "tune.w_away.stepp", "unknown key");
}

TEST(EvolveConfig, WrongTypes) {
  expect_error(replaced(tiny_config(), "seeds = 2\nmax", "seeds = \"two\"\nmax"), "\"two\"",
               "evaluation.seeds", "expected an integer");
  expect_error(replaced(tiny_config(), "w_away = {}", "w_away = 1.0"), "w_away", "tune.w_away",
               "expected a table");
  expect_error(replaced(tiny_config(), "mode = \"pf\"", "mode = 1"), "mode = 1", "mode", "expected a string");
}

TEST(EvolveConfig, OtherImpossibleValues) {
  expect_error(replaced(tiny_config(), "mode = \"pf\"", "mode = \"diffusion\""), "mode =", "mode",
               "\"pf\" or \"ta\"");
  expect_error(replaced(tiny_config(), "generations = 2", "generations = 0"), "generations = 0",
               "budget.generations", "at least one");
  expect_error(replaced(tiny_config(), "robots = [8]", "robots = [100000]"), "robots = [",
               "evaluation.robots", "short_chain");
  expect_error(replaced(tiny_config(), "top_k = 2", "top_k = 0"), "top_k", "reevaluate.top_k", "must lie in");
  expect_error(replaced(tiny_config(), "w_away = {}", "early_stop_in_rec = { lo = 0 }"), "early_stop_in_rec",
               "tune.early_stop_in_rec.lo", "no settings");
  expect_error(replaced(tiny_config(), "w_away = {}", "T_lost = { step = 1.5 }"), "T_lost",
               "tune.T_lost.step", "whole step");
  const std::string missing = replaced(tiny_config(), "\n[budget]\ngenerations = 2\n", "\n");
  try {
    (void)parse_evolve_config(missing, "bad.toml", "");
    ADD_FAILURE() << "no error for a missing [budget]";
  } catch (const sim::ConfigError& e) {
    EXPECT_EQ(e.key(), "budget");
  }
  try {
    (void)parse_evolve_config(replaced(tiny_config(), "short_chain.toml", "no_such_arena.toml"), "bad.toml",
                              "");
    ADD_FAILURE() << "no error for a missing scenario";
  } catch (const sim::ConfigError& e) {
    EXPECT_EQ(e.key(), "evaluation.scenarios");
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
}

TEST(EvolveConfig, PathsResolveAgainstTheConfigFolder) {
  const EvolveConfig c = load_evolve_config(source("configs/evolve/default.toml"));
  EXPECT_EQ(c.evaluation.scenarios[0].written, "../scenarios/paper/env1.toml");
  EXPECT_EQ(sim::load_scenario(c.evaluation.scenarios[0].path).name, "env1");
  EXPECT_EQ(c.params_written, "../../genomes/default.toml");
}

TEST(EvolveConfig, HashIgnoresOnlyTheBudget) {
  const EvolveConfig a = testing::tiny("random", 2);
  const EvolveConfig b = testing::tiny("random", 5);
  EXPECT_EQ(config_hash(a), config_hash(b));
  EXPECT_EQ(config_hash(a).size(), 16u);
  const EvolveConfig c =
      parse_evolve_config(replaced(tiny_config(), "w_away = {}", "w_away = { hi = 1.5 }"), "tiny.toml", "");
  EXPECT_NE(config_hash(a), config_hash(c));
  const EvolveConfig d =
      parse_evolve_config(replaced(tiny_config(), "seed = 7", "seed = 8"), "tiny.toml", "");
  EXPECT_NE(config_hash(a), config_hash(d));
}

}  // namespace
}  // namespace swarmpath::evolve
