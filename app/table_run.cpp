// SPDX-License-Identifier: MIT
#include "table_run.hpp"

#include <sstream>

#include "cli_options.hpp"
#include "common.hpp"
#include "evolve/params_export.hpp"
#include "sim/config_error.hpp"
#include "table_output.hpp"
#include "table_report.hpp"

namespace swarmpath::app {

TablePlan plan_table(const TableRequest& r) {
  if (r.seeds < 1 || r.seeds > 100000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 100000]");
  if (r.robots.empty()) throw sim::ConfigError("--robots", 0, "", "give at least one robot count");
  check_distinct_robots("--robots", r.robots);
  check_seed_range("--seed-base", r.seed_base, r.seeds);
  TablePlan plan;
  plan.request = r;
  plan.modes = path_modes(r.mode);
  plan.files = scenario_files(r.scenarios);
  for (const std::string& f : plan.files)
    plan.scenarios.push_back(with_fault_options(scenario_with_overrides(f, {}, r.ticks), r.faults));
  check_distinct_scenarios("--scenarios", plan.files, plan.scenarios);
  plan.threads = threads_or_all(r.threads);
  plan.astar8 = astar8_lengths(plan.scenarios);  // the A* baseline of each scenario, once
  plan.grid = make_grid(plan.scenarios.size(), r.robots, plan.modes, r.seeds, r.seed_base);
  return plan;
}

TableOutcome run_table(const TablePlan& plan, evolve::BatchEvaluator& evaluator,
                       const GridProgress& progress) {
  TableOutcome out;
  const sim::Params& p = plan.request.params;
  const std::string& file = plan.request.params_file;
  out.runs = run_grid(plan.scenarios, plan.grid, p, evaluator, progress);
  std::ostringstream md;
  md << "Controller: the " << evolve::controller_text(p) << (file.empty() ? "" : ", " + file)
     << "; the paper's figures in parentheses.\n\n";
  if (plan.modes.size() == 2) {
    const Comparison c =
        compare(summarise(plan.scenarios, plan.astar8, runs_of(out.runs, sim::Mode::kPathFormation),
                          sim::Mode::kPathFormation),
                summarise(plan.scenarios, plan.astar8, runs_of(out.runs, sim::Mode::kTaskAllocation),
                          sim::Mode::kTaskAllocation));
    write_markdown(md, c);
    out.json = comparison_json(plan.scenarios, plan.astar8, out.runs, c);
  } else {
    const TableReport report = summarise(plan.scenarios, plan.astar8, out.runs, plan.modes[0]);
    write_markdown(md, report);
    out.json = table_json(plan.scenarios, plan.astar8, out.runs, report);
  }
  out.json["params"] = file;
  out.json["controller"] = evolve::controller_json(p);
  out.markdown = md.str();
  return out;
}

std::string table_runs_csv(const TablePlan& plan, const TableOutcome& outcome) {
  std::ostringstream csv;
  write_runs_csv(csv, plan.scenarios, plan.astar8, outcome.runs);
  return csv.str();
}

}  // namespace swarmpath::app
