// SPDX-License-Identifier: MIT
#include "chain_stats.hpp"

#include "controllers/path_formation.hpp"

namespace swarmpath::sim {

void ChainStatsObserver::observe(const Scenario& s, const World& w) {
  constexpr double kGoalward = 0.10;  // [m] farther from the nest than the parent
  const auto rows = pf_transitions();
  const std::int64_t fired = w.tick - 1;  // rows fired during the tick just simulated
  for (std::size_t i = 0; i < w.memory.size(); ++i) {
    const PfMemory& m = w.memory[i].pf;
    if (m.fired_tick != fired || m.last_row == 0) continue;
    const PfTransition& row = rows[m.last_row - 1U];
    if (row.from == row.to) continue;  // re-targeting while forming
    const double to_nest = dist(w.positions[i], s.nest);
    if (row.to == PfState::kSubgoalForming && m.target.valid() &&
        to_nest > dist(m.target.last_seen, s.nest)) {
      ++stats_.forming_from_goal_side;
    }
    if (row.from != PfState::kSubgoalForming || row.to != PfState::kSubgoal) continue;
    ++stats_.subgoals_laid;
    const int parent = m.parent.id;
    if (parent >= 0 && static_cast<std::size_t>(parent) < w.positions.size() &&
        to_nest > dist(w.positions[static_cast<std::size_t>(parent)], s.nest) + kGoalward) {
      ++stats_.subgoals_laid_goalward;
    }
  }
}

}  // namespace swarmpath::sim
