// SPDX-License-Identifier: MIT
// A grid of simulations (scenario x robot count x seed), run as one batch on a BatchEvaluator
// (OpenMP threads or MPI ranks): each result in its own slot, so the results do not depend on
// the number of threads or ranks.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "evolve/batch.hpp"
#include "sim/controller.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::app {

struct GridCase {
  std::size_t scenario = 0;  ///< index into the scenario list
  int robots = 0;
  sim::Mode mode = sim::Mode::kPathFormation;
  std::uint64_t seed = 0;
};

struct GridRun {
  GridCase c;
  sim::Metrics m;
};

/// Every (scenario, robots, mode, seed) in that nesting order; seeds are seed_base ..
/// seed_base+seeds-1, the same for every mode (paired runs).
std::vector<GridCase> make_grid(std::size_t scenarios, const std::vector<int>& robots,
                                const std::vector<sim::Mode>& modes, int seeds, std::uint64_t seed_base);

/// Called from the calling thread after each finished run (done, total); may print progress.
using GridProgress = evolve::BatchProgress;

/// The modes of --mode for the commands that measure paths: pf, ta, or both (pf, then ta); throws
/// ConfigError for anything else (diffusion forms no path).
std::vector<sim::Mode> path_modes(const std::string& mode);

/// Progress lines on `err`: one line rewritten in place on a terminal, else a line every tenth.
GridProgress grid_progress(std::ostream& err, bool terminal);

/// Runs the grid for each params set in one batch on `evaluator`: one list per params set, in
/// grid order. Robot counts are checked (ConfigError) before anything runs.
std::vector<std::vector<GridRun>> run_grid(const std::vector<sim::Scenario>& scenarios,
                                           const std::vector<GridCase>& grid,
                                           const std::vector<sim::Params>& params,
                                           evolve::BatchEvaluator& evaluator, const GridProgress& progress);

/// The same for one params set.
std::vector<GridRun> run_grid(const std::vector<sim::Scenario>& scenarios, const std::vector<GridCase>& grid,
                              const sim::Params& p, evolve::BatchEvaluator& evaluator,
                              const GridProgress& progress);

/// The runs of one mode, in grid order.
std::vector<GridRun> runs_of(const std::vector<GridRun>& runs, sim::Mode mode);

/// Scenario files: each path as given, or for a directory every *.toml in it, sorted by name.
std::vector<std::string> scenario_files(const std::vector<std::string>& paths);

/// A grid counts each scenario once: throws sim::ConfigError naming `option` when two entries are
/// one file (by identity), the same experiment (sim::experiment_fingerprint: an identical copy), or
/// two scenarios of one name (their rows would merge). scenarios[i] was loaded from files[i].
void check_distinct_scenarios(const std::string& option, const std::vector<std::string>& files,
                              const std::vector<sim::Scenario>& scenarios);

/// Throws sim::ConfigError naming `option` when a robot count is listed twice.
void check_distinct_robots(const std::string& option, const std::vector<int>& robots);

/// The A* baseline (SPEC §4.5) of each scenario in table units; throws sim::ConfigError naming the
/// scenario file when it finds no path (the table's path / A* would be NaN).
std::vector<double> astar8_lengths(const std::vector<sim::Scenario>& scenarios);

}  // namespace swarmpath::app
