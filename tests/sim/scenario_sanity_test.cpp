// SPDX-License-Identifier: MIT
// Scenario files that would load but run into nonsense (robots leaving a wall-less arena, a goal
// nobody can reach, a neighbour grid that exhausts memory, control characters that break the
// pictures) are rejected at load with file:line: key, and errors point at the right key.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "sim/config_error.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

ConfigError rejection(const std::string& text) {
  try {
    parse_scenario(text, "bad.toml");
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return ConfigError("", 0, "", "");
}

int line_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << needle;
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
}

void expect_rejected(const std::string& text, const std::string& marker, const std::string& key,
                     const std::vector<std::string>& words) {
  const ConfigError e = rejection(text);
  EXPECT_EQ(e.line(), line_of(text, marker)) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  for (const std::string& w : words)
    EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << w << ": " << e.what();
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

// a 2000 m arena: the largest side allowed
std::string huge_arena(const std::string& simulation) {
  return "name = \"huge\"\nclass = \"open\"\nnest = [-2.0, 0.0]\ngoal = [2.0, 0.0]\n\n[arena]\n"
         "size = [2000.0, 2000.0]\n\n[deployment]\nsize = [1.0, 1.0]\nrobots = 5\n\n[simulation]\n" +
         simulation;
}

TEST(ScenarioSanity, TheNeighbourGridIsBoundedByItsCellCountNamingBothKeys) {
  const std::string text = huge_arena("grid_cell = 0.1\n");
  expect_rejected(
      text, "grid_cell", "simulation.grid_cell",
      {"arena.size", "2000 x 2000 m", "400000000 neighbour-grid cells", "limit 4000000", "grid_cell >= 1 m"});
  EXPECT_NO_THROW(parse_scenario(huge_arena("grid_cell = 1.0\n"), "huge.toml"));  // 4 000 000 cells
  EXPECT_NO_THROW(test::small_arena("[simulation]\ngrid_cell = 0.1\n"));          // 60 x 40 cells
}

TEST(ScenarioSanity, BoundaryWallsCannotBeRemoved) {
  for (const std::string t : {"0", "0.0", "0.005"}) {
    const std::string bad = with(test::small_arena_toml(), "size = [6.0, 4.0]\n",
                                 "size = [6.0, 4.0]\nwall_thickness = " + t + "\n");
    expect_rejected(bad, "wall_thickness", "arena.wall_thickness", {"at least 0.01 m", "leave the arena"});
  }
  EXPECT_NO_THROW(parse_scenario(
      with(test::small_arena_toml(), "size = [6.0, 4.0]\n", "size = [6.0, 4.0]\nwall_thickness = 0.01\n"),
      "thin.toml"));
}

TEST(ScenarioSanity, AGoalNoRobotCanReachIsRejected) {
  // the goal (2, 0) boxed in by four walls
  const std::string boxed = test::small_arena_toml(
      "[[box]]\ncenter = [2.0, 0.6]\nsize = [1.2, 0.1]\n[[box]]\ncenter = [2.0, -0.6]\nsize = [1.2, 0.1]\n"
      "[[box]]\ncenter = [1.4, 0.0]\nsize = [0.1, 1.3]\n[[box]]\ncenter = [2.6, 0.0]\nsize = [0.1, 1.3]\n");
  expect_rejected(boxed, "goal = ", "goal", {"no robot can drive from the nest (-2, 0) to the goal (2, 0)"});
  // a wall across the arena with a gap narrower than a robot (12 cm; a robot is 17 cm wide)
  const std::string slit = test::small_arena_toml(
      "[[box]]\ncenter = [0.0, 1.03]\nsize = [0.2, 1.94]\n[[box]]\ncenter = [0.0, -1.03]\nsize = [0.2, "
      "1.94]\n");
  expect_rejected(slit, "goal = ", "goal", {"no robot can drive"});
  // the same wall with a 40 cm door: fine
  EXPECT_NO_THROW(parse_scenario(test::small_arena_toml("[[box]]\ncenter = [0.0, 1.2]\nsize = [0.2, 1.6]\n"
                                                        "[[box]]\ncenter = [0.0, -1.0]\nsize = [0.2, 2.0]\n"),
                                 "door.toml"));
  // a goal closer to a wall than a robot's radius
  const std::string corner = with(test::small_arena_toml(), "goal = [2.0, 0.0]", "goal = [2.86, 0.0]");
  expect_rejected(corner, "goal = ", "goal", {"within 8.5 cm of the east wall"});
  const std::string nest = with(test::small_arena_toml("[[cylinder]]\ncenter = [-2.0, 0.3]\nradius = 0.25\n"),
                                "nest = [-2.0, 0.0]", "nest = [-2.0, 0.0]");
  expect_rejected(nest, "nest = ", "nest", {"within 8.5 cm of cylinder[0]"});
}

TEST(ScenarioSanity, ControlCharactersInStringsAreRejected) {
  for (const std::string c : {"\\u0000", "\\u0007", "\\n", "\\u001b[31m", "\\u007f"}) {
    const std::string text = with(test::small_arena_toml(), "name = \"small\"", "name = \"env" + c + "4\"");
    expect_rejected(text, "name = ", "name", {"control character"});
  }
  EXPECT_EQ(parse_scenario(with(test::small_arena_toml(), "name = \"small\"", "name = \"arène 4 (édité)\""),
                           "ok.toml")
                .name,
            "arène 4 (édité)");
}

TEST(ScenarioSanity, TooManyObstaclesPointsAtTheTableThatOverflows) {
  std::string text =
      "name = \"many\"\nclass = \"open\"\nnest = [-900.0, 0.0]\ngoal = [-890.0, 0.0]\n[arena]\n"
      "size = [2000.0, 2000.0]\n[deployment]\nsize = [1.0, 1.0]\nrobots = 2\n"
      "[[box]]\ncenter = [0.0, 500.0]\nsize = [0.1, 0.1]\n";
  text.reserve(text.size() + 46 * kMaxObstacles);
  for (std::size_t i = 0; i < kMaxObstacles; ++i) {
    text += "[[cylinder]]\ncenter = [" + std::to_string(static_cast<int>(i % 1000) - 500) + ".0, " +
            std::to_string(static_cast<int>(i / 1000) * 2 + 100) + ".0]\nradius = 0.01\n";
  }
  expect_rejected(text, "[[cylinder]]", "cylinder", {"too many obstacles", "1 box and 200000 cylinders"});
}

TEST(ScenarioSanity, AFolderIsNotAScenarioFile) {
  try {
    load_scenario(test::source_path("configs/scenarios/paper"));
    ADD_FAILURE() << "loaded a folder";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("configs/scenarios/paper: is a folder, not a file"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace swarmpath::sim
