// SPDX-License-Identifier: MIT
#include "table_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmpath::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double mean_of(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double s = 0;
  for (const double x : v) s += x;  // index order: deterministic
  return s / static_cast<double>(v.size());
}

void push_if(std::vector<double>& v, double x) {
  if (!std::isnan(x)) v.push_back(x);
}

CaseSummary summarise_case(const std::vector<GridRun>& runs, std::size_t& i, const sim::Scenario& s,
                           double astar8_tu) {
  const GridCase& c0 = runs[i].c;
  CaseSummary cs;
  cs.scenario = s.name;
  cs.robots = c0.robots;
  cs.astar8_tu = astar8_tu;
  std::vector<double> ticks, path, subgoal, opt1, robots, allocated, rr, alloc_ticks, after;
  for (; i < runs.size() && runs[i].c.scenario == c0.scenario && runs[i].c.robots == c0.robots; ++i) {
    const sim::Metrics& m = runs[i].m;
    ++cs.runs;
    push_if(subgoal, m.subgoal_path_length_tu);
    push_if(opt1, m.opt1_path_length_tu);
    if (m.allocated >= 0) {
      allocated.push_back(m.allocated);
      push_if(rr, m.resource_reduction_pct);
      alloc_ticks.push_back(static_cast<double>(m.ticks_to_allocate));
    }
    if (!m.success) continue;
    ++cs.successes;
    ticks.push_back(static_cast<double>(m.ticks_to_form));
    path.push_back(m.path_length_tu);
    robots.push_back(m.path_robots);
    if (m.ticks_to_allocate >= 0) after.push_back(static_cast<double>(m.ticks_to_form - m.ticks_to_allocate));
  }
  cs.success_rate = static_cast<double>(cs.successes) / cs.runs;
  cs.ticks_to_form = mean_of(ticks);
  cs.path_length_tu = mean_of(path);
  cs.subgoal_length_tu = mean_of(subgoal);
  cs.opt1_length_tu = mean_of(opt1);
  cs.path_robots = mean_of(robots);
  cs.ratio_to_astar = cs.path_length_tu / cs.astar8_tu;
  cs.allocated = mean_of(allocated);
  cs.resource_reduction_pct = mean_of(rr);
  cs.ticks_to_allocate = mean_of(alloc_ticks);
  cs.ticks_after_allocate = mean_of(after);
  return cs;
}

EnvSummary summarise_env(const TableReport& r, const sim::Scenario& s, double astar8_tu) {
  EnvSummary e;
  e.scenario = s.name;
  e.env_class = std::string(sim::to_string(s.env_class));
  e.astar8_tu = astar8_tu;
  e.paper = paper_row(s);
  std::vector<double> rate, ticks, path, allocated, rr, after;
  for (const CaseSummary& cs : r.cases) {
    if (cs.scenario != e.scenario) continue;
    rate.push_back(cs.success_rate);
    push_if(ticks, cs.ticks_to_form);
    push_if(path, cs.path_length_tu);
    push_if(allocated, cs.allocated);
    push_if(rr, cs.resource_reduction_pct);
    push_if(after, cs.ticks_after_allocate);
  }
  e.success_rate = mean_of(rate);
  e.ticks_to_form = mean_of(ticks);
  e.path_length_tu = mean_of(path);
  e.ratio_to_astar = e.path_length_tu / e.astar8_tu;
  e.allocated = mean_of(allocated);
  e.resource_reduction_pct = mean_of(rr);
  e.ticks_after_allocate = mean_of(after);
  return e;
}

// below, with NaN (no success) counting as never below, but anything is below NaN
bool below(double ours, double theirs) {
  if (std::isnan(ours)) return false;
  return std::isnan(theirs) || ours < theirs;
}

}  // namespace

TableReport summarise(const std::vector<sim::Scenario>& scenarios, const std::vector<double>& astar8_tu,
                      const std::vector<GridRun>& runs, sim::Mode mode) {
  TableReport r;
  r.mode = mode;
  r.runs = static_cast<int>(runs.size());
  int successes = 0;
  std::vector<double> rr;
  for (const GridRun& run : runs) {
    successes += run.m.success ? 1 : 0;
    if (run.m.allocated >= 0) push_if(rr, run.m.resource_reduction_pct);
  }
  for (std::size_t i = 0; i < runs.size();) {
    const std::size_t s = runs[i].c.scenario;
    r.cases.push_back(summarise_case(runs, i, scenarios[s], astar8_tu[s]));
  }
  r.success_rate = r.runs > 0 ? 100.0 * successes / r.runs : 0.0;
  r.mean_resource_reduction_pct = mean_of(rr);
  // headline figures over the cases (SPEC §4.6): a case without a success is not shorter
  int shorter = 0;
  std::vector<double> ratios;
  for (const CaseSummary& cs : r.cases) {
    push_if(ratios, cs.ratio_to_astar);
    if (cs.path_length_tu < cs.astar8_tu) ++shorter;
  }
  r.pct_shorter_than_astar = r.cases.empty() ? 0.0 : 100.0 * shorter / static_cast<double>(r.cases.size());
  r.mean_ratio_to_astar = mean_of(ratios);
  r.min_ratio_to_astar = ratios.empty() ? kNaN : *std::min_element(ratios.begin(), ratios.end());
  r.max_ratio_to_astar = ratios.empty() ? kNaN : *std::max_element(ratios.begin(), ratios.end());
  // environments: the paper's table averages each column over the robot counts
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    const bool any = std::any_of(r.cases.begin(), r.cases.end(),
                                 [&](const CaseSummary& cs) { return cs.scenario == scenarios[s].name; });
    if (any) r.envs.push_back(summarise_env(r, scenarios[s], astar8_tu[s]));
  }
  return r;
}

Comparison compare(const TableReport& pf, const TableReport& ta) {
  Comparison c{pf, ta, 0.0, 0.0};
  int faster = 0, shorter = 0, cases = 0;
  for (const CaseSummary& a : ta.cases) {
    for (const CaseSummary& b : pf.cases) {
      if (a.scenario != b.scenario || a.robots != b.robots) continue;
      ++cases;
      faster += below(a.ticks_to_form, b.ticks_to_form) ? 1 : 0;
      shorter += below(a.path_length_tu, b.path_length_tu) ? 1 : 0;
    }
  }
  if (cases > 0) {
    c.pct_ta_faster = 100.0 * faster / cases;
    c.pct_ta_shorter_than_pf = 100.0 * shorter / cases;
  }
  return c;
}

}  // namespace swarmpath::app
