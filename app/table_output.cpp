// SPDX-License-Identifier: MIT
#include "table_output.hpp"

#include <cmath>
#include <ostream>

#include "common.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {

namespace {

nlohmann::json number_or_null(double v) {
  return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

std::string cell(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

// "ours (paper x)", or just ours where the paper has no such environment
std::string beside(const std::string& ours, const std::optional<PaperRow>& row, double paper, int digits) {
  return row ? ours + " (paper " + fixed(paper, digits) + ")" : ours;
}

std::string mode_name(sim::Mode m) { return std::string(sim::to_string(m)); }

// the row's name, and whether it is the paper's arena: "arena-one (the paper's env1)", "env4 (not the
// paper's env4: its arena differs)"
std::string env_label(const EnvSummary& e) {
  std::string label = markdown_text(e.scenario);
  const std::optional<PaperRow> named = paper_row_named(e.scenario);
  if (e.paper && (!named || named->env != e.paper->env)) {
    label += " (the paper's env" + std::to_string(e.paper->env) + ")";
  } else if (!e.paper && named) {
    label += " (not the paper's " + e.scenario + ": its arena differs)";
  }
  return label;
}

nlohmann::ordered_json runs_json(const std::vector<sim::Scenario>& scenarios,
                                 const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs) {
  nlohmann::ordered_json rs = nlohmann::ordered_json::array();
  for (const GridRun& run : runs) {
    nlohmann::ordered_json o;
    o["scenario"] = scenarios[run.c.scenario].name;
    o["robots"] = run.c.robots;
    o["seed"] = run.c.seed;
    o["mode"] = mode_name(run.c.mode);
    o["ticks"] = run.m.ticks;
    o["state_hash"] = sim::to_hex(run.m.state_hash);
    o["astar8_tu"] = astar8_tu[run.c.scenario];
    add_path_json(o, run.m);
    rs.push_back(o);
  }
  return rs;
}

nlohmann::ordered_json case_json(const CaseSummary& c, sim::Mode mode) {
  nlohmann::ordered_json o = {{"scenario", c.scenario},
                              {"robots", c.robots},
                              {"mode", mode_name(mode)},
                              {"runs", c.runs},
                              {"successes", c.successes},
                              {"success_rate", c.success_rate},
                              {"ticks_to_form", number_or_null(c.ticks_to_form)},
                              {"path_length_tu", number_or_null(c.path_length_tu)},
                              {"subgoal_path_length_tu", number_or_null(c.subgoal_length_tu)},
                              {"opt1_path_length_tu", number_or_null(c.opt1_length_tu)},
                              {"path_robots", number_or_null(c.path_robots)},
                              {"astar8_tu", c.astar8_tu},
                              {"ratio_to_astar", number_or_null(c.ratio_to_astar)}};
  if (mode == sim::Mode::kTaskAllocation) {
    o["allocated"] = number_or_null(c.allocated);
    o["resource_reduction_pct"] = number_or_null(c.resource_reduction_pct);
    o["ticks_to_allocate"] = number_or_null(c.ticks_to_allocate);
    o["ticks_after_allocate"] = number_or_null(c.ticks_after_allocate);
  }
  return o;
}

nlohmann::ordered_json env_columns(const EnvSummary& e, sim::Mode mode) {
  nlohmann::ordered_json o = {{"success_rate", e.success_rate},
                              {"ticks_to_form", number_or_null(e.ticks_to_form)},
                              {"path_length_tu", number_or_null(e.path_length_tu)},
                              {"ratio_to_astar", number_or_null(e.ratio_to_astar)}};
  if (mode == sim::Mode::kTaskAllocation) {
    o["allocated"] = number_or_null(e.allocated);
    o["resource_reduction_pct"] = number_or_null(e.resource_reduction_pct);
    o["ticks_after_allocate"] = number_or_null(e.ticks_after_allocate);
  }
  return o;
}

nlohmann::ordered_json paper_env_json(const PaperRow& p) {
  return {{"env", p.env},
          {"time_without", p.time_without},
          {"time_with", p.time_with},
          {"astar_tu", p.astar_tu},
          {"path_without_tu", p.path_without_tu},
          {"path_with_tu", p.path_with_tu},
          {"resource_reduction_pct", p.resource_reduction_pct}};
}

nlohmann::ordered_json paper_claims_json() {
  return {{"success_rate_pf", kPaperSuccessRatePf},
          {"pct_pf_shorter_than_astar", kPaperPctPfShorterThanAstar},
          {"pct_ta_shorter_than_astar", kPaperPctTaShorterThanAstar},
          {"pct_ta_faster", kPaperPctTaFaster},
          {"pct_ta_shorter_than_pf", kPaperPctTaShorterThanPf},
          {"mean_resource_reduction_pct", kPaperMeanResourceReduction}};
}

// the summary keys of one mode: success_rate_pf / _ta, pct_pf / ta_shorter_than_astar, ...
void add_mode_summary(nlohmann::ordered_json& j, const TableReport& r) {
  const std::string tag = r.mode == sim::Mode::kTaskAllocation ? "ta" : "pf";
  j["success_rate_" + tag] = r.success_rate;
  j["pct_" + tag + "_shorter_than_astar"] = r.pct_shorter_than_astar;
  j["mean_ratio_to_astar_" + tag] = number_or_null(r.mean_ratio_to_astar);
  j["min_ratio_to_astar_" + tag] = number_or_null(r.min_ratio_to_astar);
  j["max_ratio_to_astar_" + tag] = number_or_null(r.max_ratio_to_astar);
  if (r.mode == sim::Mode::kTaskAllocation)
    j["mean_resource_reduction_pct"] = number_or_null(r.mean_resource_reduction_pct);
}

void claims_lines(std::ostream& out, const TableReport& r) {
  const bool ta = r.mode == sim::Mode::kTaskAllocation;
  out << "- success rate " << (ta ? "with" : "without") << " TA: " << fixed(r.success_rate, 1) << " % of "
      << r.runs << " runs";
  if (!ta) out << " (paper: " << fixed(kPaperSuccessRatePf, 0) << " % of 40 cases)";
  out << "\n- cases whose mean path " << (ta ? "with" : "without")
      << " TA is shorter than A*: " << fixed(r.pct_shorter_than_astar, 1) << " % of " << r.cases.size()
      << " (paper: " << fixed(ta ? kPaperPctTaShorterThanAstar : kPaperPctPfShorterThanAstar, 0) << " %)\n";
  out << "- path / A* over the cases: mean " << cell(r.mean_ratio_to_astar, 3) << ", range "
      << cell(r.min_ratio_to_astar, 3) << " - " << cell(r.max_ratio_to_astar, 3)
      << " (paper, per environment: " << (ta ? "0.89 - 1.10" : "0.95 - 1.37") << ")\n";
  if (ta) {
    out << "- mean resource reduction: " << cell(r.mean_resource_reduction_pct, 1)
        << " % (paper: " << fixed(kPaperMeanResourceReduction, 2) << " %)\n";
  }
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string markdown_text(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

nlohmann::ordered_json table_json(const std::vector<sim::Scenario>& scenarios,
                                  const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                  const TableReport& report) {
  nlohmann::ordered_json j;
  j["mode"] = mode_name(report.mode);
  j["table_unit_cm"] = 10;
  j["runs"] = runs_json(scenarios, astar8_tu, runs);
  nlohmann::ordered_json& cs = j["cases"] = nlohmann::ordered_json::array();
  for (const CaseSummary& c : report.cases) cs.push_back(case_json(c, report.mode));
  nlohmann::ordered_json& es = j["environments"] = nlohmann::ordered_json::array();
  for (const EnvSummary& e : report.envs) {
    nlohmann::ordered_json o = {{"scenario", e.scenario}, {"class", e.env_class}, {"astar8_tu", e.astar8_tu}};
    o.update(env_columns(e, report.mode));
    if (e.paper) o["paper"] = paper_env_json(*e.paper);
    es.push_back(o);
  }
  nlohmann::ordered_json summary = {{"runs", report.runs}};
  add_mode_summary(summary, report);
  j["summary"] = summary;
  j["paper"] = paper_claims_json();
  return j;
}

nlohmann::ordered_json comparison_json(const std::vector<sim::Scenario>& scenarios,
                                       const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                       const Comparison& c) {
  nlohmann::ordered_json j;
  j["mode"] = "both";
  j["table_unit_cm"] = 10;
  j["runs"] = runs_json(scenarios, astar8_tu, runs);
  nlohmann::ordered_json& cs = j["cases"] = nlohmann::ordered_json::array();
  for (const CaseSummary& x : c.pf.cases) cs.push_back(case_json(x, sim::Mode::kPathFormation));
  for (const CaseSummary& x : c.ta.cases) cs.push_back(case_json(x, sim::Mode::kTaskAllocation));
  nlohmann::ordered_json& es = j["environments"] = nlohmann::ordered_json::array();
  for (const EnvSummary& pf : c.pf.envs) {
    nlohmann::ordered_json o = {
        {"scenario", pf.scenario}, {"class", pf.env_class}, {"astar8_tu", pf.astar8_tu}};
    o["pf"] = env_columns(pf, sim::Mode::kPathFormation);
    for (const EnvSummary& ta : c.ta.envs) {
      if (ta.scenario == pf.scenario) o["ta"] = env_columns(ta, sim::Mode::kTaskAllocation);
    }
    if (pf.paper) o["paper"] = paper_env_json(*pf.paper);
    es.push_back(o);
  }
  nlohmann::ordered_json summary = {{"runs", c.pf.runs + c.ta.runs}};
  add_mode_summary(summary, c.pf);
  add_mode_summary(summary, c.ta);
  summary["pct_ta_faster"] = c.pct_ta_faster;
  summary["pct_ta_shorter_than_pf"] = c.pct_ta_shorter_than_pf;
  j["summary"] = summary;
  j["paper"] = paper_claims_json();
  return j;
}

void write_runs_csv(std::ostream& out, const std::vector<sim::Scenario>& scenarios,
                    const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs) {
  out << "scenario,robots,seed,mode,success,ticks_to_form,path_length_tu,subgoal_path_length_tu,"
         "opt1_path_length_tu,astar8_tu,path_robots,ticks_to_chain,ticks_to_opt1,allocated,"
         "resource_reduction_pct,ticks_to_allocate,ticks,state_hash,subgoals_laid,subgoals_laid_goalward,"
         "forming_from_goal_side,ticks_to_goal,recruited\n";
  const auto num = [](double v) { return std::isnan(v) ? std::string() : fixed(v, 4); };
  const auto tick = [](std::int64_t t) { return t < 0 ? std::string() : std::to_string(t); };
  for (const GridRun& run : runs) {
    const sim::Metrics& m = run.m;
    out << csv_field(scenarios[run.c.scenario].name) << ',' << run.c.robots << ',' << run.c.seed << ','
        << mode_name(run.c.mode) << ',' << (m.success ? 1 : 0) << ',' << tick(m.ticks_to_form) << ','
        << num(m.path_length_tu) << ',' << num(m.subgoal_path_length_tu) << ',' << num(m.opt1_path_length_tu)
        << ',' << fixed(astar8_tu[run.c.scenario], 4) << ',' << m.path_robots << ',' << tick(m.ticks_to_chain)
        << ',' << tick(m.ticks_to_opt1) << ',' << (m.allocated >= 0 ? std::to_string(m.allocated) : "") << ','
        << num(m.resource_reduction_pct) << ',' << tick(m.ticks_to_allocate) << ',' << m.ticks << ','
        << sim::to_hex(m.state_hash) << ',' << m.chain.subgoals_laid << ',' << m.chain.subgoals_laid_goalward
        << ',' << m.chain.forming_from_goal_side << ',' << tick(m.ticks_to_goal) << ',' << m.recruited
        << '\n';
  }
}

void write_markdown(std::ostream& out, const TableReport& r) {
  const bool ta = r.mode == sim::Mode::kTaskAllocation;
  const std::string w = ta ? "with" : "without";
  out << "| Env | class | success | time " << w << " TA (ticks) | A* length (TU) | path " << w
      << " TA (TU) | path / A* |" << (ta ? " robots allocated | resource reduction (%) |" : "") << "\n";
  out << "|---|---|---|---|---|---|---|" << (ta ? "---|---|" : "") << "\n";
  for (const EnvSummary& e : r.envs) {
    const PaperRow p = e.paper.value_or(PaperRow{});
    const double p_time = ta ? p.time_with : p.time_without;
    const double p_path = ta ? p.path_with_tu : p.path_without_tu;
    out << "| " << env_label(e) << " | " << e.env_class << " | " << fixed(100.0 * e.success_rate, 0)
        << " % | " << beside(cell(e.ticks_to_form, 0), e.paper, p_time, 0) << " | "
        << beside(fixed(e.astar8_tu, 1), e.paper, p.astar_tu, 1) << " | "
        << beside(cell(e.path_length_tu, 1), e.paper, p_path, 1) << " | "
        << beside(cell(e.ratio_to_astar, 2), e.paper, p_path / p.astar_tu, 2) << " |";
    if (ta) {
      out << " " << cell(e.allocated, 1) << " | "
          << beside(cell(e.resource_reduction_pct, 1), e.paper, p.resource_reduction_pct, 1) << " |";
    }
    out << "\n";
  }
  out << "\n";
  claims_lines(out, r);
}

void write_markdown(std::ostream& out, const Comparison& c) {
  out << "| Env | class | success without / with TA | time without TA (ticks) | time with TA (ticks) | A* "
         "length (TU) | path without TA (TU) | path with TA (TU) | robots allocated | resource reduction (%) "
         "|\n";
  out << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const EnvSummary& pf : c.pf.envs) {
    EnvSummary ta;
    ta.ticks_to_form = ta.path_length_tu = ta.allocated = ta.resource_reduction_pct = std::nan("");
    for (const EnvSummary& e : c.ta.envs) {
      if (e.scenario == pf.scenario) ta = e;
    }
    const PaperRow p = pf.paper.value_or(PaperRow{});
    out << "| " << env_label(pf) << " | " << pf.env_class << " | " << fixed(100.0 * pf.success_rate, 0)
        << " / " << fixed(100.0 * ta.success_rate, 0) << " % | "
        << beside(cell(pf.ticks_to_form, 0), pf.paper, p.time_without, 0) << " | "
        << beside(cell(ta.ticks_to_form, 0), pf.paper, p.time_with, 0) << " | "
        << beside(fixed(pf.astar8_tu, 1), pf.paper, p.astar_tu, 1) << " | "
        << beside(cell(pf.path_length_tu, 1), pf.paper, p.path_without_tu, 1) << " | "
        << beside(cell(ta.path_length_tu, 1), pf.paper, p.path_with_tu, 1) << " | " << cell(ta.allocated, 1)
        << " | " << beside(cell(ta.resource_reduction_pct, 1), pf.paper, p.resource_reduction_pct, 1)
        << " |\n";
  }
  out << "\n";
  claims_lines(out, c.pf);
  claims_lines(out, c.ta);
  out << "- cases formed faster with TA: " << fixed(c.pct_ta_faster, 1)
      << " % (paper: " << fixed(kPaperPctTaFaster, 1) << " %)\n";
  out << "- cases whose path with TA is shorter than without: " << fixed(c.pct_ta_shorter_than_pf, 1)
      << " % (paper: " << fixed(kPaperPctTaShorterThanPf, 0)
      << " %, though its env7 row contradicts it, SPEC §6.17)\n";
}

}  // namespace swarmpath::app
