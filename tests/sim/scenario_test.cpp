// SPDX-License-Identifier: MIT
// Scenario files: the eight paper arenas load as SPEC §3.3 gives them, and every kind of bad
// input is rejected with file:line: key: message.
#include "sim/scenario.hpp"

#include <gtest/gtest.h>

#include "sim/config_error.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

using test::paper_env;

TEST(Scenario, PaperEnv4MatchesSpec) {  // SPEC §3.3 row 4
  const Scenario s = load_scenario(paper_env(4));
  EXPECT_EQ(s.name, "env4");
  EXPECT_EQ(s.env_class, EnvClass::kObstacle);
  EXPECT_EQ(s.arena_size, (Vec2{24.0, 14.0}));
  EXPECT_DOUBLE_EQ(s.wall_thickness, 0.1);
  EXPECT_EQ(s.nest, (Vec2{-6.5, 0.0}));
  EXPECT_EQ(s.goal, (Vec2{6.5, 0.0}));
  ASSERT_EQ(s.boxes.size(), 2u);
  EXPECT_EQ(s.boxes[0].size, (Vec2{1.0, 3.28}));
  EXPECT_NEAR(s.boxes[1].yaw, deg2rad(30.0), 1e-12);
  ASSERT_EQ(s.cylinders.size(), 1u);
  EXPECT_DOUBLE_EQ(s.cylinders[0].radius, 0.5);
  EXPECT_EQ(s.deployment.center, s.nest);  // defaults to the nest
  EXPECT_EQ(s.deployment.size, (Vec2{3.0, 3.0}));
  EXPECT_EQ(s.sim.ticks_per_second, 10);
  EXPECT_EQ(s.sim.max_ticks, 36000);
}

TEST(Scenario, AllPaperEnvironmentsLoadWithTheirClasses) {  // SPEC §5.1: 1-3 open, 4-6 obstacle, 7-8 complex
  const EnvClass expected[8] = {EnvClass::kOpen,     EnvClass::kOpen,     EnvClass::kOpen,
                                EnvClass::kObstacle, EnvClass::kObstacle, EnvClass::kObstacle,
                                EnvClass::kComplex,  EnvClass::kComplex};
  const std::size_t obstacles[8] = {0, 0, 0, 3, 4, 5, 21, 11};
  for (int k = 1; k <= 8; ++k) {
    const Scenario s = load_scenario(paper_env(k));
    EXPECT_EQ(s.env_class, expected[k - 1]) << "env" << k;
    EXPECT_EQ(s.boxes.size() + s.cylinders.size(), obstacles[k - 1]) << "env" << k;
    EXPECT_EQ(boundary_walls(s).size(), 4u);
    EXPECT_GE(deployment_capacity(s), 100) << "env" << k;
  }
}

TEST(Scenario, BoundaryWallsLieInsideTheArenaEdge) {  // SPEC §3.3: north centre (0, 6.95) size 24 x 0.1
  const Scenario s = load_scenario(paper_env(1));
  const auto walls = boundary_walls(s);
  EXPECT_EQ(walls[0].center, (Vec2{0.0, 6.95}));
  EXPECT_EQ(walls[0].size, (Vec2{24.0, 0.1}));
  EXPECT_EQ(walls[3].center, (Vec2{-11.95, 0.0}));
  EXPECT_EQ(walls[3].size, (Vec2{0.1, 14.0}));
}

// Parses `text`, expects a ConfigError and returns it.
ConfigError rejection(const std::string& text) {
  try {
    parse_scenario(text, "bad.toml");
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return ConfigError("", 0, "", "");
}

void expect_rejected(const std::string& text, int line, const std::string& key, const std::string& fragment) {
  const ConfigError e = rejection(text);
  EXPECT_EQ(e.file(), "bad.toml");
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
}

TEST(ScenarioRejects, SyntaxErrorWithLine) {
  expect_rejected(test::small_arena_toml("[simulation\nmax_ticks = 5\n"), 12, "", "TOML syntax error");
}

TEST(ScenarioRejects, UnknownKeyWithSuggestion) {
  expect_rejected(test::small_arena_toml("[[cylinder]]\ncenter = [0.0, 1.0]\nradus = 0.2\n"), 14,
                  "cylinder[0].radus", "did you mean 'radius'");
  expect_rejected("colour = \"red\"\n" + test::small_arena_toml(), 1, "colour", "unknown key");
}

TEST(ScenarioRejects, MissingKeys) {
  expect_rejected("class = \"open\"\nnest = [0.0, 0.0]\ngoal = [1.0, 0.0]\n[deployment]\nsize = [1.0, 1.0]\n",
                  1, "arena", "missing required key");
  expect_rejected(test::small_arena_toml("[[cylinder]]\ncenter = [0.0, 1.0]\n"), 12, "cylinder[0].radius",
                  "missing required key");
}

TEST(ScenarioRejects, WrongTypes) {
  expect_rejected(test::small_arena_toml("[[cylinder]]\ncenter = [0.0, 1.0]\nradius = \"big\"\n"), 14,
                  "cylinder[0].radius", "expected a number, got a string");
  expect_rejected(test::small_arena_toml("[[box]]\ncenter = 3.0\nsize = [1.0, 1.0]\n"), 13, "box[0].center",
                  "expected a pair of numbers");
  expect_rejected(test::small_arena_toml("[simulation]\nmax_ticks = 1.5\n"), 13, "simulation.max_ticks",
                  "expected an integer");
  expect_rejected(test::small_arena_toml("[simulation]\nocclude_by_robots = 1\n"), 13,
                  "simulation.occlude_by_robots", "expected a boolean");
}

TEST(ScenarioRejects, NegativeAndZeroSizes) {
  expect_rejected(test::small_arena_toml("[[cylinder]]\ncenter = [0.0, 1.0]\nradius = -0.5\n"), 14,
                  "cylinder[0].radius", "obstacle radius must be > 0");
  expect_rejected(test::small_arena_toml("[[box]]\ncenter = [0.0, 1.0]\nsize = [0.5, 0.0]\n"), 14,
                  "box[0].size", "obstacle size must be > 0");
  expect_rejected("class = \"open\"\nnest = [0.0, 0.0]\ngoal = [1.0, 0.0]\n[arena]\nsize = [-3.0, 4.0]\n", 5,
                  "arena.size", "arena size must be > 0");
}

TEST(ScenarioRejects, NestOrGoalInsideAnObstacle) {
  expect_rejected(test::small_arena_toml("[[cylinder]]\ncenter = [2.0, 0.1]\nradius = 0.3\n"), 4, "goal",
                  "goal (2, 0) lies inside cylinder[0]");
  expect_rejected(test::small_arena_toml("[[box]]\ncenter = [-2.0, 0.0]\nsize = [0.2, 0.2]\nyaw_deg = 45\n"),
                  3, "nest", "lies inside box[0]");
}

TEST(ScenarioRejects, NestOrGoalOutsideTheArena) {
  std::string text = test::small_arena_toml();
  text.replace(text.find("goal = [2.0, 0.0]"), 17, "goal = [3.5, 0.0]");
  expect_rejected(text, 4, "goal", "outside the arena");
  // inside the edge but within the boundary wall
  text = test::small_arena_toml();
  text.replace(text.find("goal = [2.0, 0.0]"), 17, "goal = [2.95, 0.0]");
  expect_rejected(text, 4, "goal", "outside the arena interior");
}

TEST(ScenarioRejects, DeploymentRegionThatCannotHoldTheRobots) {
  expect_rejected(test::small_arena_toml("", 80), 11, "deployment.robots", "cannot hold 80 robots");
  EXPECT_NO_THROW(test::small_arena("", 10));
}

TEST(ScenarioRejects, AbsurdSizes) {
  expect_rejected(test::small_arena_toml("", 1000000000), 11, "deployment.robots", "exceed the limit");
  expect_rejected(test::small_arena_toml("[simulation]\nmax_ticks = 1000000000\n"), 13,
                  "simulation.max_ticks", "must lie in [1, 10000000]");
  expect_rejected("class = \"open\"\nnest = [0.0, 0.0]\ngoal = [1.0, 0.0]\n[arena]\nsize = [1e9, 4.0]\n", 5,
                  "arena.size", "at most 2000 m");
  expect_rejected(test::small_arena_toml("", 0), 11, "deployment.robots", "at least 1");
}

TEST(ScenarioRejects, BadClassAndSpacing) {
  std::string text = test::small_arena_toml();
  text.replace(text.find("\"open\""), 6, "\"maze\"");
  expect_rejected(text, 2, "class", "must be \"open\", \"obstacle\" or \"complex\"");
  expect_rejected(test::small_arena_toml() + "min_spacing = 0.1\n", 12, "deployment.min_spacing",
                  "so that robots do not overlap");
}

TEST(Scenario, PhysicsRegionsAreReadAndDefaultToOneWorld) {
  EXPECT_EQ(test::small_arena().sim.physics_regions_x, 1);
  EXPECT_EQ(test::small_arena().sim.physics_regions_y, 1);
  const Scenario s = test::small_arena("[simulation]\nphysics_regions = [3, 2]\n");
  EXPECT_EQ(s.sim.physics_regions_x, 3);
  EXPECT_EQ(s.sim.physics_regions_y, 2);
}

TEST(ScenarioRejects, PhysicsRegionsOutsideOneToSixteenOrFractional) {
  for (const std::string bad : {"[0, 1]", "[2, 17]", "[1.5, 1]"}) {
    expect_rejected(test::small_arena_toml("[simulation]\nphysics_regions = " + bad + "\n"), 13,
                    "simulation.physics_regions", "two whole numbers in [1, 16]");
  }
}

TEST(ScenarioRejects, MissingFile) {
  try {
    load_scenario("/nonexistent/env.toml");
    FAIL() << "accepted a missing file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/env.toml: cannot open file"), std::string::npos)
        << e.what();
  }
}

TEST(ScenarioOverrides, RobotsAndTicksAreChecked) {
  const Scenario s = load_scenario(paper_env(1));
  EXPECT_EQ(with_robots(s, 60).robots, 60);
  EXPECT_EQ(with_max_ticks(s, 500).sim.max_ticks, 500);
  EXPECT_THROW(with_robots(s, 1000000000), ConfigError);
  EXPECT_THROW(with_robots(s, 5000), ConfigError);  // 3 x 3 m cannot hold them
  EXPECT_THROW(with_robots(s, -3), ConfigError);
  EXPECT_THROW(with_max_ticks(s, 1000000000), ConfigError);
  EXPECT_THROW(with_max_ticks(s, 0), ConfigError);
}

}  // namespace
}  // namespace swarmpath::sim
