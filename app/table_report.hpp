// SPDX-License-Identifier: MIT
// The results table of a grid of runs (SPEC §4.6): per-case means (scenario, robots), per
// environment averages over the robot counts (the paper's table), and the headline figures.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiment.hpp"
#include "paper_results.hpp"

namespace swarmpath::app {

/// Means over the runs of one (scenario, robots) case; lengths and times over successful runs.
struct CaseSummary {
  std::string scenario;
  int robots = 0;
  int runs = 0;
  int successes = 0;
  double success_rate = 0;       ///< [0, 1]
  double ticks_to_form = 0;      ///< mean T_form (NaN: no success)
  double path_length_tu = 0;     ///< mean final path length
  double subgoal_length_tu = 0;  ///< mean subgoal path length
  double opt1_length_tu = 0;     ///< mean optimisation-1 path length
  double path_robots = 0;
  double astar8_tu = 0;
  double ratio_to_astar = 0;  ///< path_length_tu / astar8_tu
};

/// One row of the paper's table: one environment, averaged over its robot counts.
struct EnvSummary {
  std::string scenario;
  std::string env_class;
  double success_rate = 0;
  double ticks_to_form = 0;
  double astar8_tu = 0;
  double path_length_tu = 0;
  double ratio_to_astar = 0;
  std::optional<PaperRow> paper;
};

struct TableReport {
  std::string mode;
  std::vector<CaseSummary> cases;
  std::vector<EnvSummary> envs;
  int runs = 0;
  double success_rate_pf = 0;            ///< % of runs whose path completed
  double pct_pf_shorter_than_astar = 0;  ///< % of cases whose mean path is shorter than A* (SPEC §4.6)
  double mean_ratio_to_astar = 0;        ///< mean of the cases' path / A*
  double min_ratio_to_astar = 0;
  double max_ratio_to_astar = 0;
};

/// Aggregates `runs` (in grid order); astar8_tu[i] belongs to scenarios[i].
TableReport summarise(const std::vector<sim::Scenario>& scenarios, const std::vector<double>& astar8_tu,
                      const std::vector<GridRun>& runs, const std::string& mode);

/// {"runs": [...], "cases": [...], "environments": [...], "summary": {...}, "paper": {...}}
nlohmann::ordered_json table_json(const std::vector<sim::Scenario>& scenarios,
                                  const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                                  const TableReport& report);

/// One line per run.
void write_runs_csv(std::ostream& out, const std::vector<sim::Scenario>& scenarios,
                    const std::vector<double>& astar8_tu, const std::vector<GridRun>& runs,
                    const std::string& mode);

/// The paper's table with our figures beside the paper's (markdown).
void write_markdown(std::ostream& out, const TableReport& report);

}  // namespace swarmpath::app
