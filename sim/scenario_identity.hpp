// SPDX-License-Identifier: MIT
// What makes two scenarios the same, independent of their names and files: the arena (size,
// walls, obstacles, nest, goal, class and deployment region) and, for a whole experiment, the
// robot count and the simulation settings too. The paper's table is matched by the arena, and a
// list that holds one experiment twice is refused.
#pragma once

#include <cstdint>

#include "scenario.hpp"

namespace swarmpath::sim {

/// FNV-1a over the arena's exact values: class, size, wall thickness, every box and cylinder in
/// file order, nest, goal, deployment region and spacing. Not the name, the file, the robot count or
/// the simulation settings.
std::uint64_t arena_fingerprint(const Scenario& s);

/// arena_fingerprint plus the robot count and every simulation setting: two scenarios with equal
/// values run the same experiment.
std::uint64_t experiment_fingerprint(const Scenario& s);

}  // namespace swarmpath::sim
