// SPDX-License-Identifier: MIT
// The results table of a grid of runs (SPEC §4.6): per-case means (scenario, robots), per
// environment averages over the robot counts (the paper's table), and the headline figures; for
// `--mode both`, the comparison of the runs with and without task allocation on the same seeds.
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
  // task allocation: means over the runs that allocated (NaN: none did, or not TA)
  double allocated = 0;
  double resource_reduction_pct = 0;
  double ticks_to_allocate = 0;
  double ticks_after_allocate = 0;  ///< T_form - T_alloc over successful runs (SPEC §6.16)
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
  double allocated = 0;
  double resource_reduction_pct = 0;
  double ticks_after_allocate = 0;
  std::optional<PaperRow> paper;
};

/// The table of one mode.
struct TableReport {
  sim::Mode mode = sim::Mode::kPathFormation;
  std::vector<CaseSummary> cases;
  std::vector<EnvSummary> envs;
  int runs = 0;
  double success_rate = 0;            ///< % of runs whose path completed
  double pct_shorter_than_astar = 0;  ///< % of cases whose mean path is shorter than A* (SPEC §4.6)
  double mean_ratio_to_astar = 0;     ///< mean of the cases' path / A*
  double min_ratio_to_astar = 0;
  double max_ratio_to_astar = 0;
  double mean_resource_reduction_pct = 0;  ///< TA: mean over the runs that allocated (SPEC §4.3)
};

/// Aggregates the runs of one mode (in grid order); astar8_tu[i] belongs to scenarios[i].
TableReport summarise(const std::vector<sim::Scenario>& scenarios, const std::vector<double>& astar8_tu,
                      const std::vector<GridRun>& runs, sim::Mode mode);

/// Path formation without and with task allocation on the same cases (SPEC §5.2's claims).
struct Comparison {
  TableReport pf;
  TableReport ta;
  double pct_ta_faster = 0;           ///< % of cases whose mean T_form with TA is below the one without
  double pct_ta_shorter_than_pf = 0;  ///< % of cases whose mean path with TA is shorter than without
};

/// A case counts as faster (shorter) with TA when its TA mean is below the no-TA mean, or when
/// only the TA runs succeeded; a case whose TA runs all failed never counts.
Comparison compare(const TableReport& pf, const TableReport& ta);

}  // namespace swarmpath::app
