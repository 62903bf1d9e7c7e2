// SPDX-License-Identifier: MIT
// Path measurements of SPEC §2.5 and §4: the chain of subgoal robots from the nest to the goal,
// its length, and the ticks at which it formed (T_chain), finished optimisation 1 (T_opt1) and
// finished optimisation 2 (T_form, path complete).
#pragma once

#include <cstdint>
#include <vector>

#include "scenario.hpp"
#include "world.hpp"

namespace swarmpath::sim {

/// One picture of the chain: nest beacon, robot centres nest -> goal, goal beacon.
struct PathSnapshot {
  std::int64_t tick = -1;    ///< -1: never taken
  std::vector<int> robots;   ///< chain robots, nest side first
  std::vector<Vec2> points;  ///< nest, robots..., goal [m]
  double length_m = 0;       ///< polyline length of `points`
};

/// The robots from `first` (the nest-side subgoal) up its parent pointers to the goal, or an
/// empty list when the pointers end anywhere else, loop or pass a failed robot.
std::vector<int> chain_to_goal(const World& w, int first);

/// The robots from `last` (the goal-side subgoal) down its child pointers to the nest, returned
/// nest side first, or empty when they do not reach the nest (or pass a failed robot).
std::vector<int> chain_to_nest(const World& w, int last);

/// The snapshot of a chain (robot ids nest side first) in the world as it stands.
PathSnapshot snapshot(const Scenario& s, const World& w, const std::vector<int>& robots);

/// Watches the path-formation events after every tick.
class PathObserver {
 public:
  /// Call after every tick of a Mode::kPathFormation world.
  void observe(const Scenario& s, const World& w);

  bool complete() const { return final_.tick >= 0; }

  const PathSnapshot& subgoal_path() const { return subgoal_; }  ///< at T_chain

  const PathSnapshot& opt1_path() const { return opt1_; }  ///< at T_opt1

  const PathSnapshot& final_path() const { return final_; }  ///< at T_form

 private:
  struct Candidate {
    int first;  // the nest-side robot of the chain
    PathSnapshot snap;
  };

  std::vector<Candidate> chains_;  // T_chain snapshots, one per chain that reached the nest
  std::vector<Candidate> opt1s_;   // T_opt1 snapshots
  PathSnapshot subgoal_;
  PathSnapshot opt1_;
  PathSnapshot final_;
};

}  // namespace swarmpath::sim
