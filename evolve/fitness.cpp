// SPDX-License-Identifier: MIT
#include "fitness.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::evolve {

int ta_robots_used(const sim::Metrics& m) { return std::max(m.allocated, m.path_robots); }

RunScore score_run(const sim::Metrics& m, const CaseInfo& c, const FitnessWeights& w) {
  if (!m.success) {
    RunScore s = penalty_score(c, w);
    // the robots a failed task-allocation run committed, when it got as far as allocating
    if (c.mode == sim::Mode::kTaskAllocation && m.allocated >= 0) {
      s.robots_used = static_cast<double>(ta_robots_used(m));
      s.robots_fraction = s.robots_used / static_cast<double>(c.robots);
    }
    return s;
  }
  RunScore s;
  s.success = true;
  const std::int64_t formed = m.ticks_to_form >= 0 ? m.ticks_to_form : m.ticks;
  s.ticks = static_cast<double>(formed);
  const bool known = std::isfinite(m.path_length_tu) && std::isfinite(c.astar_tu) && c.astar_tu > 0.0;
  s.path_ratio = known ? m.path_length_tu / c.astar_tu : std::numeric_limits<double>::quiet_NaN();
  const bool ta = c.mode == sim::Mode::kTaskAllocation;
  const int used = ta ? (m.allocated >= 0 ? ta_robots_used(m) : -1) : m.path_robots;
  s.robots_used = used >= 0 ? static_cast<double>(used) : static_cast<double>(c.robots);
  s.robots_fraction = s.robots_used / static_cast<double>(c.robots);
  const double max_ticks = static_cast<double>(c.max_ticks);
  s.fitness = w.w_time * s.ticks / max_ticks + w.w_path * (known ? s.path_ratio : w.fail_path_ratio) +
              w.w_robots * s.robots_used / static_cast<double>(c.robots);
  return s;
}

RunScore penalty_score(const CaseInfo& c, const FitnessWeights& w) {
  RunScore s;
  s.success = false;
  s.ticks = static_cast<double>(c.max_ticks);
  s.robots_used = static_cast<double>(c.robots);
  s.robots_fraction = 1.0;
  s.fitness = w.w_fail + w.w_time + w.w_path * w.fail_path_ratio + w.w_robots;
  return s;
}

CandidateStats summarise(std::span<const RunScore> runs) {
  CandidateStats st;
  if (runs.empty()) return st;
  double f = 0.0, ok = 0.0, ticks = 0.0, path = 0.0, robots = 0.0, fraction = 0.0;
  int paths = 0;
  for (const RunScore& r : runs) {
    f += r.fitness;
    ticks += r.ticks;
    robots += r.robots_used;
    fraction += r.robots_fraction;
    if (r.success) ok += 1.0;
    if (r.success && std::isfinite(r.path_ratio)) {
      path += r.path_ratio;
      ++paths;
    }
  }
  const double n = static_cast<double>(runs.size());
  st.fitness = f / n;
  st.success_rate = ok / n;
  st.mean_ticks = ticks / n;
  st.mean_path_ratio = paths > 0 ? path / paths : std::numeric_limits<double>::quiet_NaN();
  st.mean_robots = robots / n;
  st.mean_robots_fraction = fraction / n;
  st.runs = static_cast<int>(runs.size());
  return st;
}

}  // namespace swarmpath::evolve
