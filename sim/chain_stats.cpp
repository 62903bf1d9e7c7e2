// SPDX-License-Identifier: MIT
#include "chain_stats.hpp"

#include <algorithm>

#include "controllers/path_formation.hpp"

namespace swarmpath::sim {

void ChainStatsObserver::begin(int robots) {
  previous_.assign(static_cast<std::size_t>(robots), static_cast<std::uint8_t>(PfState::kExploring));
  stats_ = ChainStats{};
}

void ChainStatsObserver::observe(const Scenario& s, const World& w) {
  constexpr double kGoalward = 0.10;  // [m] farther from the nest than the parent
  const std::size_t n = std::min(previous_.size(), w.memory.size());
  for (std::size_t i = 0; i < n; ++i) {
    const PfMemory& m = w.memory[i].pf;
    const auto was = static_cast<PfState>(previous_[i]);
    previous_[i] = static_cast<std::uint8_t>(m.state);
    if (m.state == was) continue;
    const double to_nest = dist(w.positions[i], s.nest);
    if (m.state == PfState::kSubgoalForming && m.target.valid() &&
        to_nest > dist(m.target.last_seen, s.nest)) {
      ++stats_.forming_from_goal_side;
    }
    if (m.state != PfState::kSubgoal || was != PfState::kSubgoalForming) continue;
    ++stats_.subgoals_laid;
    const int parent = m.parent.id;
    if (parent >= 0 && static_cast<std::size_t>(parent) < w.positions.size() &&
        to_nest > dist(w.positions[static_cast<std::size_t>(parent)], s.nest) + kGoalward) {
      ++stats_.subgoals_laid_goalward;
    }
  }
}

}  // namespace swarmpath::sim
