// SPDX-License-Identifier: MIT
#include "path_metrics.hpp"

#include <algorithm>

namespace swarmpath::sim {

namespace {

bool is_robot(const World& w, int id) { return id >= 0 && id < w.robot_count(); }

}  // namespace

std::vector<int> chain_to_goal(const World& w, int first) {
  std::vector<int> chain;
  int id = first;
  while (is_robot(w, id)) {
    if (static_cast<int>(chain.size()) >= w.robot_count()) return {};  // a loop
    if (has_failed(w, id)) return {};  // its light is dark: no chain runs through it
    chain.push_back(id);
    id = w.memory[static_cast<std::size_t>(id)].pf.parent.id;
  }
  if (id != kGoalEmitter) return {};
  return chain;
}

std::vector<int> chain_to_nest(const World& w, int last) {
  std::vector<int> chain;
  int id = last;
  while (is_robot(w, id)) {
    if (static_cast<int>(chain.size()) >= w.robot_count()) return {};
    if (has_failed(w, id)) return {};  // its light is dark: no chain runs through it
    chain.push_back(id);
    id = w.memory[static_cast<std::size_t>(id)].pf.child.id;
  }
  if (id != kNestEmitter) return {};
  std::reverse(chain.begin(), chain.end());
  return chain;
}

PathSnapshot snapshot(const Scenario& s, const World& w, const std::vector<int>& robots) {
  PathSnapshot snap;
  snap.tick = w.tick;
  snap.robots = robots;
  snap.points.push_back(s.nest);
  for (const int id : robots) snap.points.push_back(w.positions[static_cast<std::size_t>(id)]);
  snap.points.push_back(s.goal);
  for (std::size_t i = 1; i < snap.points.size(); ++i)
    snap.length_m += dist(snap.points[i - 1], snap.points[i]);
  return snap;
}

void PathObserver::observe(const Scenario& s, const World& w) {
  if (complete()) return;
  static const std::uint8_t kChainRow = pf_row_number("#9a");  // a subgoal sees the nest
  static const std::uint8_t kOpt1Row = pf_row_number("#10");   // optimisation 1 done
  static const std::uint8_t kDoneRow = pf_row_number("#12");   // optimisation 2 done
  const std::int64_t fired = w.tick - 1;                       // rows fired during the tick just simulated
  for (int id = 0; id < w.robot_count(); ++id) {
    const PfMemory& m = w.memory[static_cast<std::size_t>(id)].pf;
    if (m.fired_tick != fired) continue;
    if (m.last_row == kChainRow) {
      // T_chain: a RED robot whose parent chain reaches the goal sees the nest
      const std::vector<int> chain = chain_to_goal(w, id);
      if (!chain.empty()) {
        chains_.push_back({id, snapshot(s, w, chain)});
        if (subgoal_.tick < 0) subgoal_ = chains_.back().snap;
      }
    } else if (m.last_row == kOpt1Row && m.parent.id == kGoalEmitter) {
      // T_opt1: the last subgoal turns BLUE
      const std::vector<int> chain = chain_to_nest(w, id);
      if (!chain.empty()) {
        opt1s_.push_back({chain.front(), snapshot(s, w, chain)});
        if (opt1_.tick < 0) opt1_ = opt1s_.back().snap;
      }
    } else if (m.last_row == kDoneRow && m.child.id == kNestEmitter) {
      // T_form: the nest-side robot finishes optimisation 2, the path is complete (a chain
      // broken on the way does not count: the run goes on)
      const std::vector<int> chain = chain_to_goal(w, id);
      if (chain.empty()) continue;
      final_ = snapshot(s, w, chain);
      // report the earlier snapshots of this very chain when there were several
      for (const Candidate& c : chains_) {
        if (c.first == id) subgoal_ = c.snap;
      }
      for (const Candidate& c : opt1s_) {
        if (c.first == id) opt1_ = c.snap;
      }
      return;
    }
  }
}

}  // namespace swarmpath::sim
