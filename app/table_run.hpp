// SPDX-License-Identifier: MIT
// The paper's experiment table as a function: scenario files x robot counts x modes x seeds run in
// one batch on a BatchEvaluator, summarised as the markdown table and the JSON that `swarmpath table`
// prints and writes. The command and the Python module's table() both call it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/batch.hpp"
#include "experiment.hpp"
#include "fault_options.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::app {

struct TableRequest {
  std::vector<std::string> scenarios{"configs/scenarios/paper"};  ///< files, or folders of *.toml
  std::vector<int> robots{60, 70, 80, 90, 100};
  int seeds = 10;                     ///< per (scenario, robots, mode)
  std::uint64_t seed_base = 1;        ///< seeds seed_base ... seed_base + seeds - 1
  std::string mode = "pf";            ///< pf | ta | both
  sim::Params params;                 ///< the controller's parameters
  std::string params_file;            ///< the file they came from, named in the table ("": in memory)
  std::optional<std::int64_t> ticks;  ///< overrides every scenario's max_ticks
  std::optional<int> threads;         ///< unset: all cores
  FaultOptions faults;                ///< override every scenario's [faults] keys
};

/// A checked request: its scenarios loaded, their A* lengths, the grid to run.
struct TablePlan {
  TableRequest request;
  std::vector<sim::Mode> modes;
  std::vector<std::string> files;  ///< the scenario files, folders expanded
  std::vector<sim::Scenario> scenarios;
  std::vector<double> astar8;  ///< per scenario [TU]; NaN without a path
  std::vector<GridCase> grid;
  int threads = 1;  ///< the request's, unset resolved to all cores
};

struct TableOutcome {
  std::vector<GridRun> runs;
  std::string markdown;         ///< the table as `swarmpath table` prints it
  nlohmann::ordered_json json;  ///< as `swarmpath table --json` writes it
};

/// Checks the request (ConfigError naming the option), loads the scenarios with the fault options
/// applied, computes A*.
TablePlan plan_table(const TableRequest& r);

/// Runs the plan's grid on `evaluator` and summarises it.
TableOutcome run_table(const TablePlan& plan, evolve::BatchEvaluator& evaluator,
                       const GridProgress& progress = {});

/// One CSV line per run, as `swarmpath table --csv` writes it.
std::string table_runs_csv(const TablePlan& plan, const TableOutcome& outcome);

}  // namespace swarmpath::app
