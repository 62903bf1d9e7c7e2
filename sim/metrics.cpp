// SPDX-License-Identifier: MIT
#include "metrics.hpp"

#include "astar.hpp"
#include "controllers/task_allocation.hpp"

namespace swarmpath::sim {

void MetricsAccumulator::begin(int robots) {
  robots_ = robots;
  ever_allocated_.assign(static_cast<std::size_t>(robots), 0);
  ever_allocated_count_ = 0;
  recruited_ = 0;
  recruit_row_ = ta_row_number("T10");
  distance_m_ = 0;
  goal_tick_ = -1;
  path_ = PathObserver{};
  chain_ = ChainStatsObserver{};
}

void MetricsAccumulator::observe(const Scenario& s, const World& w) {
  if (w.mode != Mode::kPathFormation && w.mode != Mode::kTaskAllocation) return;
  watch_path_ = true;
  if (goal_tick_ < 0) {              // how long finding the goal took (a diagnostic of exploration)
    constexpr double kInView = 1.0;  // [m], the paper's R_vis
    for (const Vec2& q : w.positions) {
      if (dist(q, s.goal) <= kInView) {
        goal_tick_ = w.tick;
        break;
      }
    }
  }
  path_.observe(s, w);
  chain_.observe(s, w);
  if (w.mode != Mode::kTaskAllocation) return;
  // the robots allocated: every robot that has entered INITIATE_TASK so far, whichever founder
  // (duplicate founders each allocate) and the founders themselves
  for (std::size_t i = 0; i < w.memory.size() && i < ever_allocated_.size(); ++i) {
    if (ever_allocated_[i] == 0 && w.memory[i].ta.state == TaState::kPathFormation) {
      ever_allocated_[i] = 1;
      ++ever_allocated_count_;
      if (w.memory[i].ta.last_row == recruit_row_) ++recruited_;
    }
  }
  if (alloc_tick_ >= 0) return;
  // T_alloc: the first founder to broadcast DONE
  for (const RobotMemory& mem : w.memory) {
    if (mem.ta.alloc_done_tick == w.tick - 1) {
      alloc_tick_ = w.tick;
      break;
    }
  }
}

Metrics MetricsAccumulator::finish(std::int64_t ticks, double dt, std::uint64_t hash) const {
  Metrics m;
  m.robots = robots_;
  m.ticks = ticks;
  m.state_hash = hash;
  m.distance_m = distance_m_;
  const double robot_seconds = static_cast<double>(robots_) * static_cast<double>(ticks) * dt;
  m.mean_speed_cm_s = robot_seconds > 0 ? 100.0 * distance_m_ / robot_seconds : 0.0;
  if (!watch_path_) return m;
  m.subgoal_path = path_.subgoal_path();
  m.opt1_path = path_.opt1_path();
  m.final_path = path_.final_path();
  m.success = path_.complete();
  m.chain = chain_.stats();
  m.ticks_to_chain = m.subgoal_path.tick;
  m.ticks_to_opt1 = m.opt1_path.tick;
  m.ticks_to_goal = goal_tick_;
  // a path can complete before any founder broadcasts DONE: the robots that initiated the task count
  m.allocated = alloc_tick_ >= 0 || ever_allocated_count_ > 0 ? ever_allocated_count_ : -1;
  m.ticks_to_allocate = alloc_tick_;
  m.recruited = recruited_;
  if (m.allocated >= 0) m.resource_reduction_pct = 100.0 * (robots_ - m.allocated) / robots_;
  if (m.subgoal_path.tick >= 0) m.subgoal_path_length_tu = to_tu(m.subgoal_path.length_m);
  if (m.opt1_path.tick >= 0) m.opt1_path_length_tu = to_tu(m.opt1_path.length_m);
  if (m.success) {
    m.ticks_to_form = m.final_path.tick;
    m.path_length_tu = to_tu(m.final_path.length_m);
    m.path_robots = static_cast<int>(m.final_path.robots.size());
  }
  return m;
}

}  // namespace swarmpath::sim
