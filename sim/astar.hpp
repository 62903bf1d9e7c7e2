// SPDX-License-Identifier: MIT
// The A* baseline of SPEC §4.5: occupancy grid at 1 cm, cells blocked within 8.5 cm of an
// obstacle or wall, 8-connected without corner cutting (or 4-connected), octile heuristic,
// start and goal in the cells holding the nest and goal centres, raw grid path length.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenario.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

enum class Connectivity : std::uint8_t { kFour, kEight };

struct AStarOptions {
  Connectivity connectivity = Connectivity::kEight;
  double resolution = 0.01;  ///< grid cell side [m] (SPEC §4.5: 1 cm)
  double inflation = 0.085;  ///< block cells whose centre is within this of an obstacle [m]
};

struct AStarResult {
  bool found = false;
  double length_m = 0.0;      ///< raw grid path length [m]
  std::vector<Vec2> path;     ///< cell centres at the path's corners, nest to goal [m]
  std::int64_t expanded = 0;  ///< nodes taken off the open list
};

/// Cells of the grid; refuses grids above this many cells (ConfigError) rather than exhaust memory.
inline constexpr std::int64_t kMaxAStarCells = 60'000'000;

AStarResult astar(const Scenario& s, const AStarOptions& options = {});

/// What an arena without an A* path is told (simulate's note, the error below).
inline constexpr const char* kNoAStarPath =
    "the A* baseline (SPEC 4.5: a 1 cm grid, cells within 8.5 cm of an obstacle blocked) finds no path "
    "from the nest to the goal: a passage is narrower than a robot";

/// The A*-8 baseline length in TU (SPEC §4.5), for path / A* (table, evaluate, the fitness's path
/// term); throws ConfigError naming `file` when there is no path: path / A* would be undefined.
double astar8_baseline_tu(const Scenario& s, const std::string& file);

/// Table units of the paper's length column: 1 TU = 10 cm (SPEC §3.2, dm-scale).
constexpr double to_tu(double metres) { return metres * 10.0; }

}  // namespace swarmpath::sim
