// SPDX-License-Identifier: MIT
// What the simulator tests share: paths into the source tree and small inline scenarios.
#pragma once

#include <string>

#include "sim/scenario.hpp"

namespace swarmpath::test {

inline std::string source_path(const std::string& relative) {
  return std::string(SWARMPATH_SOURCE_DIR) + "/" + relative;
}

inline std::string paper_env(int k) {
  return source_path("configs/scenarios/paper/env" + std::to_string(k) + ".toml");
}

/// A 6 m x 4 m open arena, nest at (-2, 0), goal at (2, 0); extra TOML appended.
inline std::string small_arena_toml(const std::string& extra = "", int robots = 10) {
  return "name = \"small\"\nclass = \"open\"\nnest = [-2.0, 0.0]\ngoal = [2.0, 0.0]\n\n"
         "[arena]\nsize = [6.0, 4.0]\n\n"
         "[deployment]\nsize = [1.0, 1.0]\nrobots = " +
         std::to_string(robots) + "\n" + extra;
}

inline sim::Scenario small_arena(const std::string& extra = "", int robots = 10) {
  return sim::parse_scenario(small_arena_toml(extra, robots), "small.toml");
}

}  // namespace swarmpath::test
