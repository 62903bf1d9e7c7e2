// SPDX-License-Identifier: MIT
// How the subgoal chain was laid (diagnostics beside SPEC §4's metrics) [R]. A chain whose links
// are laid goal-ward of their parents winds (a longer subgoal path, more robots, longer
// optimisations); counting how each link was laid tells why one run's chain is longer than
// another's without tracing it.
#pragma once

#include "scenario.hpp"
#include "world.hpp"

namespace swarmpath::sim {

struct ChainStats {
  int subgoals_laid = 0;           ///< transitions into SUBGOAL (RED): every link laid, kept or not
  int subgoals_laid_goalward = 0;  ///< of them, laid > 10 cm farther from the nest than the parent robot
  int forming_from_goal_side = 0;  ///< robots that began forming farther from the nest than their target
};

/// Watches the path-formation rows that fire (PfMemory::last_row, fired_tick) after every tick.
class ChainStatsObserver {
 public:
  /// Call after every tick of a path-formation or task-allocation world.
  void observe(const Scenario& s, const World& w);

  const ChainStats& stats() const { return stats_; }

 private:
  ChainStats stats_;
};

}  // namespace swarmpath::sim
