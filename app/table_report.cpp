// SPDX-License-Identifier: MIT
#include "table_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>

#include "common.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double mean_of(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double s = 0;
  for (const double x : v) s += x;  // index order: deterministic
  return s / static_cast<double>(v.size());
}

nlohmann::json number_or_null(double v) {
  return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

std::string cell(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

}  // namespace

TableReport summarise(const std::vector<sim::Scenario>& scenarios, const std::vector<double>& astar8_tu,
                      const std::vector<GridRun>& runs, const std::string& mode) {
  TableReport r;
  r.mode = mode;
  r.runs = static_cast<int>(runs.size());
  // cases, in grid order
  std::size_t i = 0;
  int successes = 0;
  while (i < runs.size()) {
    const GridCase& c0 = runs[i].c;
    CaseSummary cs;
    cs.scenario = scenarios[c0.scenario].name;
    cs.robots = c0.robots;
    cs.astar8_tu = astar8_tu[c0.scenario];
    std::vector<double> ticks, path, subgoal, opt1, robots;
    for (; i < runs.size() && runs[i].c.scenario == c0.scenario && runs[i].c.robots == c0.robots; ++i) {
      const sim::Metrics& m = runs[i].m;
      ++cs.runs;
      if (!std::isnan(m.subgoal_path_length_tu)) subgoal.push_back(m.subgoal_path_length_tu);
      if (!std::isnan(m.opt1_path_length_tu)) opt1.push_back(m.opt1_path_length_tu);
      if (!m.success) continue;
      ++cs.successes;
      ticks.push_back(static_cast<double>(m.ticks_to_form));
      path.push_back(m.path_length_tu);
      robots.push_back(m.path_robots);
    }
    successes += cs.successes;
    cs.success_rate = static_cast<double>(cs.successes) / cs.runs;
    cs.ticks_to_form = mean_of(ticks);
    cs.path_length_tu = mean_of(path);
    cs.subgoal_length_tu = mean_of(subgoal);
    cs.opt1_length_tu = mean_of(opt1);
    cs.path_robots = mean_of(robots);
    cs.ratio_to_astar = cs.path_length_tu / cs.astar8_tu;
    r.cases.push_back(cs);
  }
  r.success_rate_pf = r.runs > 0 ? 100.0 * successes / r.runs : 0.0;
  // headline figures over the cases (SPEC §4.6): a case without a success is not shorter
  int shorter = 0;
  std::vector<double> ratios;
  for (const CaseSummary& cs : r.cases) {
    if (!std::isnan(cs.ratio_to_astar)) ratios.push_back(cs.ratio_to_astar);
    if (cs.path_length_tu < cs.astar8_tu) ++shorter;
  }
  r.pct_pf_shorter_than_astar = r.cases.empty() ? 0.0 : 100.0 * shorter / static_cast<double>(r.cases.size());
  r.mean_ratio_to_astar = mean_of(ratios);
  r.min_ratio_to_astar = ratios.empty() ? kNaN : *std::min_element(ratios.begin(), ratios.end());
  r.max_ratio_to_astar = ratios.empty() ? kNaN : *std::max_element(ratios.begin(), ratios.end());
  // environments: the paper's table averages each column over the robot counts
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    EnvSummary e;
    e.scenario = scenarios[s].name;
    e.env_class = std::string(sim::to_string(scenarios[s].env_class));
    e.astar8_tu = astar8_tu[s];
    e.paper = paper_row(e.scenario);
    std::vector<double> rate, ticks, path;
    for (const CaseSummary& cs : r.cases) {
      if (cs.scenario != e.scenario) continue;
      rate.push_back(cs.success_rate);
      if (!std::isnan(cs.ticks_to_form)) ticks.push_back(cs.ticks_to_form);
      if (!std::isnan(cs.path_length_tu)) path.push_back(cs.path_length_tu);
    }
    if (rate.empty()) continue;
    e.success_rate = mean_of(rate);
    e.ticks_to_form = mean_of(ticks);
    e.path_length_tu = mean_of(path);
    e.ratio_to_astar = e.path_length_tu / e.astar8_tu;
    r.envs.push_back(e);
  }
  return r;
}

nlohmann::ordered_json table_json(const std::vector<sim::Scenario>& scenarios,
                                  const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                  const TableReport& report) {
  nlohmann::ordered_json j;
  j["mode"] = report.mode;
  j["table_unit_cm"] = 10;
  nlohmann::ordered_json& rs = j["runs"] = nlohmann::ordered_json::array();
  for (const GridRun& run : runs) {
    nlohmann::ordered_json o;
    o["scenario"] = scenarios[run.c.scenario].name;
    o["robots"] = run.c.robots;
    o["seed"] = run.c.seed;
    o["mode"] = report.mode;
    o["ticks"] = run.m.ticks;
    o["state_hash"] = sim::to_hex(run.m.state_hash);
    o["astar8_tu"] = astar8_tu[run.c.scenario];
    add_path_json(o, run.m);
    rs.push_back(o);
  }
  nlohmann::ordered_json& cs = j["cases"] = nlohmann::ordered_json::array();
  for (const CaseSummary& c : report.cases) {
    cs.push_back({{"scenario", c.scenario},
                  {"robots", c.robots},
                  {"runs", c.runs},
                  {"successes", c.successes},
                  {"success_rate", c.success_rate},
                  {"ticks_to_form", number_or_null(c.ticks_to_form)},
                  {"path_length_tu", number_or_null(c.path_length_tu)},
                  {"subgoal_path_length_tu", number_or_null(c.subgoal_length_tu)},
                  {"opt1_path_length_tu", number_or_null(c.opt1_length_tu)},
                  {"path_robots", number_or_null(c.path_robots)},
                  {"astar8_tu", c.astar8_tu},
                  {"ratio_to_astar", number_or_null(c.ratio_to_astar)}});
  }
  nlohmann::ordered_json& es = j["environments"] = nlohmann::ordered_json::array();
  for (const EnvSummary& e : report.envs) {
    nlohmann::ordered_json o = {{"scenario", e.scenario},
                                {"class", e.env_class},
                                {"success_rate", e.success_rate},
                                {"ticks_to_form", number_or_null(e.ticks_to_form)},
                                {"astar8_tu", e.astar8_tu},
                                {"path_length_tu", number_or_null(e.path_length_tu)},
                                {"ratio_to_astar", number_or_null(e.ratio_to_astar)}};
    if (e.paper) {
      o["paper"] = {{"time_without", e.paper->time_without},
                    {"astar_tu", e.paper->astar_tu},
                    {"path_without_tu", e.paper->path_without_tu},
                    {"ratio_to_astar", e.paper->path_without_tu / e.paper->astar_tu}};
    }
    es.push_back(o);
  }
  j["summary"] = {{"runs", report.runs},
                  {"success_rate_pf", report.success_rate_pf},
                  {"pct_pf_shorter_than_astar", report.pct_pf_shorter_than_astar},
                  {"mean_ratio_to_astar", number_or_null(report.mean_ratio_to_astar)},
                  {"min_ratio_to_astar", number_or_null(report.min_ratio_to_astar)},
                  {"max_ratio_to_astar", number_or_null(report.max_ratio_to_astar)}};
  j["paper"] = {{"success_rate_pf", kPaperSuccessRatePf},
                {"pct_pf_shorter_than_astar", kPaperPctPfShorterThanAstar}};
  return j;
}

void write_runs_csv(std::ostream& out, const std::vector<sim::Scenario>& scenarios,
                    const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                    const std::string& mode) {
  out << "scenario,robots,seed,mode,success,ticks_to_form,path_length_tu,subgoal_path_length_tu,"
         "opt1_path_length_tu,astar8_tu,path_robots,ticks_to_chain,ticks_to_opt1,ticks,state_hash\n";
  const auto num = [](double v) { return std::isnan(v) ? std::string() : fixed(v, 4); };
  const auto tick = [](std::int64_t t) { return t < 0 ? std::string() : std::to_string(t); };
  for (const GridRun& run : runs) {
    const sim::Metrics& m = run.m;
    out << scenarios[run.c.scenario].name << ',' << run.c.robots << ',' << run.c.seed << ',' << mode << ','
        << (m.success ? 1 : 0) << ',' << tick(m.ticks_to_form) << ',' << num(m.path_length_tu) << ','
        << num(m.subgoal_path_length_tu) << ',' << num(m.opt1_path_length_tu) << ','
        << fixed(astar8_tu[run.c.scenario], 4) << ',' << m.path_robots << ',' << tick(m.ticks_to_chain) << ','
        << tick(m.ticks_to_opt1) << ',' << m.ticks << ',' << sim::to_hex(m.state_hash) << '\n';
  }
}

void write_markdown(std::ostream& out, const TableReport& r) {
  out << "| Env | class | success | time without TA (ticks) | A* length (TU) | path without TA (TU) | path / "
         "A* |\n";
  out << "|---|---|---|---|---|---|---|\n";
  for (const EnvSummary& e : r.envs) {
    const auto pair = [&](const std::string& ours, const std::optional<std::string>& paper) {
      return paper ? ours + " (paper " + *paper + ")" : ours;
    };
    std::optional<std::string> pt, pa, pp, pr;
    if (e.paper) {
      pt = fixed(e.paper->time_without, 0);
      pa = fixed(e.paper->astar_tu, 1);
      pp = fixed(e.paper->path_without_tu, 1);
      pr = fixed(e.paper->path_without_tu / e.paper->astar_tu, 2);
    }
    out << "| " << e.scenario << " | " << e.env_class << " | " << fixed(100.0 * e.success_rate, 0) << " % | "
        << pair(cell(e.ticks_to_form, 0), pt) << " | " << pair(fixed(e.astar8_tu, 1), pa) << " | "
        << pair(cell(e.path_length_tu, 1), pp) << " | " << pair(cell(e.ratio_to_astar, 2), pr) << " |\n";
  }
  out << "\n";
  out << "- success rate without TA: " << fixed(r.success_rate_pf, 1) << " % of " << r.runs
      << " runs (paper: " << fixed(kPaperSuccessRatePf, 0) << " % of 40 cases)\n";
  out << "- cases whose mean path is shorter than A*: " << fixed(r.pct_pf_shorter_than_astar, 1) << " % of "
      << r.cases.size() << " (paper: " << fixed(kPaperPctPfShorterThanAstar, 0) << " %)\n";
  out << "- path / A* over the cases: mean " << cell(r.mean_ratio_to_astar, 3) << ", range "
      << cell(r.min_ratio_to_astar, 3) << " - " << cell(r.max_ratio_to_astar, 3)
      << " (paper, per environment: 0.95 - 1.37)\n";
}

}  // namespace swarmpath::app
