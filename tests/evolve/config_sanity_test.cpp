// SPDX-License-Identifier: MIT
// Evolve configs that would run but silently mean something else are refused at load, with
// file:line: key: a run name that leaves results/evolve/, a scenario or robot count counted
// twice, a held-out scenario that is also trained on, and optimiser settings blamed on the
// right key.
#include <gtest/gtest.h>

#include "evolve/objective.hpp"
#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

using testing::expect_error;
using testing::replaced;
using testing::tiny_config;

TEST(EvolveConfigSanity, ARunNameThatWouldLeaveTheResultsFolderIsRefused) {
  for (const std::string name : {"..", "."}) {
    expect_error(replaced(tiny_config(), "name = \"tiny\"", "name = \"" + name + "\""), "name = ", "name",
                 "names the output folder");
  }
}

TEST(EvolveConfigSanity, AScenarioOrRobotCountCountedTwiceIsRefused) {
  const std::string chain = testing::source("tests/data/short_chain.toml");
  const std::string twice = "scenarios = [\"" + chain + "\", \"" + chain + "\"]";
  expect_error(replaced(tiny_config(), "scenarios = [\"" + chain + "\"]", twice),
               "scenarios = ", "evaluation.scenarios", "listed twice");
  expect_error(replaced(tiny_config(), "robots = [8]", "robots = [8, 6, 8]"),
               "robots = ", "evaluation.robots", "8 robots listed twice");
  // a held-out scenario that is also trained on is not held out
  expect_error(tiny_config() + "held_out = [\"" + chain + "\"]\n", "held_out", "reevaluate.held_out",
               "also in evaluation.scenarios");
}

TEST(EvolveConfigSanity, OptimiserSettingsAreBlamedOnTheirOwnKey) {
  expect_error(replaced(tiny_config("ga"), "population = 4", "population = 4\nelites = 4"), "elites = 4",
               "optimizer.elites", "elites must be in [0, population - 1]");
  expect_error(replaced(tiny_config("ga"), "population = 4", "population = 4\ntournament = 0"), "tournament",
               "optimizer.tournament", "must lie in");
  expect_error(replaced(tiny_config("cmaes"), "population = 4", "population = 1"), "population = 1",
               "optimizer.population", "population must be >= 2");
}

TEST(EvolveConfigSanity, AnArenaWhoseAStarBaselineFindsNoPathIsRefused) {
  // a 16.5 cm slit passes the load check's conservative grid but no robot (17 cm) passes it
  const auto dir = testing::scratch("slit");
  testing::write_text(dir / "slit.toml", testing::read_text(testing::source("tests/data/short_chain.toml")) +
                                             "\n[[box]]\ncenter = [0.0, 1.0825]\nsize = [0.2, 1.835]\n"
                                             "[[box]]\ncenter = [0.0, -0.925]\nsize = [0.2, 1.85]\n");
  const EvolveConfig c = parse_evolve_config(
      replaced(tiny_config(), testing::source("tests/data/short_chain.toml"), (dir / "slit.toml").string()),
      "slit-run.toml", "");
  try {
    const SwarmObjective f(c);
    ADD_FAILURE() << "an objective on an arena without an A* path";
  } catch (const sim::ConfigError& e) {
    EXPECT_EQ(e.file(), (dir / "slit.toml").string()) << e.what();
    EXPECT_NE(std::string(e.what()).find("A* baseline"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarmpath::evolve
